#version 410 core
// The separable prefilter in log space: the map holds c z, and every weighted sum of exp(c z) is
// formed with logAdd (04.2), so no value ever leaves the format's range, whatever c is.
#include "exercise.glsl"
uniform sampler2D u_source;
uniform ivec2 u_axis;
uniform int u_radius;
uniform float u_weights[8];  // normalised, as in wb/blur.frag
layout(location = 0) out vec4 o_value;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy), last = textureSize(u_source, 0) - 1;
  float logSum = -1e30;
  for (int i = -u_radius; i <= u_radius; ++i)
    logSum = logAdd(logSum, log(u_weights[abs(i)]) + texelFetch(u_source, clamp(p + i * u_axis, ivec2(0), last), 0).r);
  o_value = vec4(logSum);
}
