#version 410 core
// PASS 1 of lab 08, per cube face: the face's view-projection, and the world position for the
// distance the fragment shader writes.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_lightViewProj;
out vec2 v_uv;
out vec3 v_world;
void main() {
  v_uv = a_uv;
  v_world = vec3(u_model * vec4(a_position, 1.0));
  gl_Position = u_lightViewProj * vec4(v_world, 1.0);
}
