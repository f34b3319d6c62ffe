#version 410 core
// The camera pass vertex stage shared by the labs: world position, normal and uv for the fragment stage.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_viewProj;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_normal = mat3(transpose(inverse(u_model))) * a_normal;
  v_uv = a_uv;
  gl_Position = u_viewProj * world;
}
