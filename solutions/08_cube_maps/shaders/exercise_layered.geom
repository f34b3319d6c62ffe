#version 410 core
// Lab 08, exercise 08.3: reference solution.
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;
uniform mat4 u_faceViewProj[6];
in vec3 v_worldIn[];
in vec2 v_uvIn[];
out vec3 v_world;
out vec2 v_uv;

// EXERCISE 08.3: the single-pass geometry shader.
void main() {
  for (int face = 0; face < 6; ++face) {
    gl_Layer = face;
    for (int i = 0; i < 3; ++i) {
      v_world = v_worldIn[i];
      v_uv = v_uvIn[i];
      gl_Position = u_faceViewProj[face] * vec4(v_worldIn[i], 1.0);
      EmitVertex();
    }
    EndPrimitive();
  }
}
