#version 410 core
// PASS 1 of lab 08 in one pass: world positions only; the geometry shader (08.3) picks the faces.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
out vec2 v_uvIn;
out vec3 v_worldIn;
void main() {
  v_uvIn = a_uv;
  v_worldIn = vec3(u_model * vec4(a_position, 1.0));
  gl_Position = vec4(v_worldIn, 1.0);
}
