#version 450 core
// PASS 2 vertex stage: the camera's view of the scene, carrying world position for the shadow lookup.
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
