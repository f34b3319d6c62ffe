#version 410 core
// PASS 1 of lab 05: the light's view, storing the depth's first two moments (05.1).
#include "exercise.glsl"
in vec2 v_uv;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
layout(location = 0) out vec4 o_moments;
void main() {
  if (u_hasTexture != 0 && texture(u_albedo, v_uv).a < u_alphaCutoff) discard;
  float z = gl_FragCoord.z;
  o_moments = vec4(vsmMoments(z, dFdx(z), dFdy(z)), 0.0, 0.0);
}
