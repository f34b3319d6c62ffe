#version 410 core
// The separable prefilter in log space: the map holds c z, and every weighted sum of exp(c z) is
// formed in log space (04.H1, with 04.2's logAdd), so no value ever leaves the format's range, whatever
// c is.
#include "exercise.glsl"
uniform sampler2D u_source;
uniform ivec2 u_axis;
uniform int u_radius;
uniform float u_weights[8];  // normalised, as in wb/blur.frag
layout(location = 0) out vec4 o_value;
void main() { o_value = vec4(logBlurTaps(u_source, ivec2(gl_FragCoord.xy), u_axis, u_radius, u_weights)); }
