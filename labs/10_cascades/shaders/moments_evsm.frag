#version 410 core
// PASS 1 of lab 10 with csm.filter=evsm: one cascade's warped moments, by your lab 06 evsmMoments (06.1).
#include "../../06_evsm/shaders/exercise.glsl"
in vec2 v_uv;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform float u_c, u_cNeg;
layout(location = 0) out vec4 o_moments;
void main() {
  if (u_hasTexture != 0 && texture(u_albedo, v_uv).a < u_alphaCutoff) discard;
  o_moments = evsmMoments(gl_FragCoord.z, u_c, u_cNeg);
}
