#version 450 core  // gl41-optional: compute, used only where the context has it (prefilter.cpp)
// One pass of the separable prefilter as a compute shader (prefilter.compute): the same taps,
// weights and clamping as blur.frag, one invocation per texel, stored with imageStore. The image
// format (WB_IMAGE_FORMAT: r32f, rg32f, rgba32f or their 16-bit forms) is injected by the framework.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D u_source;
layout(WB_IMAGE_FORMAT, binding = 0) writeonly uniform image2D u_target;
uniform ivec2 u_axis;
uniform int u_radius;
uniform float u_weights[8];  // u_weights[|i|] for i in [-r, r]
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy), size = textureSize(u_source, 0);
  if (any(greaterThanEqual(p, size))) return;
  vec4 sum = vec4(0.0);
  for (int i = -u_radius; i <= u_radius; ++i)
    sum += u_weights[abs(i)] * texelFetch(u_source, clamp(p + i * u_axis, ivec2(0), size - 1), 0);
  imageStore(u_target, p, sum);
}
