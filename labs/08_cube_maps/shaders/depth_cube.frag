#version 410 core
// PASS 1 of lab 08: the linear distance from the light (08.2) as the depth; leaves alpha-tested.
#include "exercise.glsl"
in vec2 v_uv;
in vec3 v_world;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform vec3 u_lightPos;
uniform float u_far;
void main() {
  if (u_hasTexture != 0 && texture(u_albedo, v_uv).a < u_alphaCutoff) discard;
  float d = cubeDepth(v_world, u_lightPos, u_far);
  gl_FragDepth = wbIsTodo(d) ? 1.0 : clamp(d, 0.0, 1.0);  // a stub stores "nothing here"
}
