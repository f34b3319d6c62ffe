#version 410 core
// PASS 1 of lab 06: the light's view, storing the warped moments (06.1) or the powers of depth (06.x).
#include "exercise.glsl"
in vec2 v_uv;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform float u_cPos, u_cNeg;
uniform int u_msm;
layout(location = 0) out vec4 o_moments;
void main() {
  if (u_hasTexture != 0 && texture(u_albedo, v_uv).a < u_alphaCutoff) discard;
  o_moments = u_msm != 0 ? msmMoments(gl_FragCoord.z) : evsmMoments(gl_FragCoord.z, u_cPos, u_cNeg);
}
