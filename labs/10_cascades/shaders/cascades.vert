#version 410 core
// PASS 2 of lab 10, vertex stage: wb/scene.vert's outputs, plus the point in every cascade's light clip
// space and its view depth, so the fragment stage multiplies by no matrix (the light's projections
// are orthographic: these interpolate exactly).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat4 u_view;
uniform mat4 u_cascades[4];
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out vec3 v_light[4];  // light clip xyz in cascade 0..3
out float v_depth;    // view distance along the view direction
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_normal = mat3(transpose(inverse(u_model))) * a_normal;
  v_uv = a_uv;
  for (int k = 0; k < 4; ++k) v_light[k] = (u_cascades[k] * world).xyz;
  v_depth = -(u_view * world).z;
  gl_Position = u_viewProj * world;
}
