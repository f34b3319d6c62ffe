#version 410 core
// Lab 08, exercise 08.3: the whole cube in one pass. Check: ./workbook check 08
// Keep the "// EXERCISE 08.3" line: the grader finds the exercise by it.
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;
uniform mat4 u_faceViewProj[6];  // 08.1's six matrices, in GL's face order
in vec3 v_worldIn[];
in vec2 v_uvIn[];
out vec3 v_world;
out vec2 v_uv;

// EXERCISE 08.3: emit the incoming triangle once per cube face. For face = 0 .. 5: set gl_Layer to
// the face (the layer of the cube it lands in), then for each of the three vertices set v_world,
// v_uv and gl_Position = u_faceViewProj[face] * vec4(v_worldIn[i], 1.0) and call EmitVertex();
// end each face's triangle with EndPrimitive().
void main() {
  // WB_TODO: the loop over the six faces goes here (until then the lab fills the cube in six passes)
}
