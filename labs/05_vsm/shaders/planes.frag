#version 410 core
// The lab's experiments: a synthetic map, the near depth u_a left of texel column u_split and the
// far depth u_b from it on, stored as moments (05.1) and as depth, then prefiltered like any map.
#include "exercise.glsl"
uniform float u_a, u_b;
uniform int u_split;
layout(location = 0) out vec4 o_moments;
void main() {
  float z = int(gl_FragCoord.x) < u_split ? u_a : u_b;
  gl_FragDepth = z;
  o_moments = vec4(vsmMoments(z, 0.0, 0.0), 0.0, 0.0);
}
