#version 410 core
// One pass of the separable prefilter: 2r + 1 texels along u_axis (horizontal or vertical), read
// with texelFetch (one fetch per tap; a linear lookup would blend four) and weighted by u_weights
// (box or Gaussian, normalised by the CPU). Run twice for the 2D filter.
uniform sampler2D u_source;
uniform ivec2 u_axis;
uniform int u_radius;
uniform float u_weights[8];  // u_weights[|i|] for i in [-r, r]
layout(location = 0) out vec4 o_value;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy), last = textureSize(u_source, 0) - 1;
  vec4 sum = vec4(0.0);
  for (int i = -u_radius; i <= u_radius; ++i)
    sum += u_weights[abs(i)] * texelFetch(u_source, clamp(p + i * u_axis, ivec2(0), last), 0);
  o_value = sum;
}
