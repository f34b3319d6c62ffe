#version 410 core
// PASS 2 of lab 11, vertex stage: wb/scene.vert's outputs, plus the point in every cascade's light
// clip space (homogeneous: a warped map's matrix is a perspective, and the fragment stage divides)
// and its view distance. The constant bias moves the point towards the light in world units, before
// any matrix, so it means the same everywhere in a warped map.
#include "wb/lighting.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat4 u_view;
uniform mat4 u_cascades[4];
uniform float u_biasWorld;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_light[4];  // light clip xyzw in cascade 0..3 (the map lookups)
out float v_depth;    // view distance along the view direction
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_normal = mat3(transpose(inverse(u_model))) * a_normal;
  v_uv = a_uv;
  vec4 biased = vec4(world.xyz + u_biasWorld * wbToLight(world.xyz), 1.0);
  for (int k = 0; k < 4; ++k) v_light[k] = u_cascades[k] * biased;
  v_depth = -(u_view * world).z;
  gl_Position = u_viewProj * world;
}
