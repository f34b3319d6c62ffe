#version 410 core
// PASS 1 of lab 10 with csm.filter=esm: one cascade's warped depth exp(c z), by your lab 04 esmWarp (04.1).
#include "../../04_esm/shaders/exercise.glsl"
in vec2 v_uv;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform float u_c;
layout(location = 0) out vec4 o_value;
void main() {
  if (u_hasTexture != 0 && texture(u_albedo, v_uv).a < u_alphaCutoff) discard;
  o_value = vec4(esmWarp(gl_FragCoord.z, u_c));
}
