#version 410 core
// SDSM's depth pre-pass, vertex stage: the camera's view, and each point's view distance.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat4 u_view;
out vec2 v_uv;
out float v_depth;
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_uv = a_uv;
  v_depth = -(u_view * world).z;
  gl_Position = u_viewProj * world;
}
