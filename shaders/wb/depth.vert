#version 410 core
// Depth from the light (labs after 01): only depth matters, plus the uv for alpha-tested casters.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_lightViewProj;
out vec2 v_uv;
void main() {
  v_uv = a_uv;
  gl_Position = u_lightViewProj * u_model * vec4(a_position, 1.0);
}
