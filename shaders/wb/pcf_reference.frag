#version 410 core
// The reference a filtered shadow map can at best reach: percentage-closer filtering over the same
// footprint (the prefilter's 2r + 1 weights in each direction, each tap a bilinear blend of four
// depth compares), from the plain depth map, for the world positions of the frame. Exact visibility
// says whether the light is blocked; this says what PCF with the same kernel would draw.
uniform sampler2D u_positions;  // world xyz; w = +1 facing the light (see outputs.glsl)
uniform sampler2D u_depth;      // the light's depth map, read without comparison
uniform mat4 u_lightViewProj;
uniform float u_bias;           // in depth units
uniform int u_radius;
uniform float u_weights[8];     // as in blur.frag
layout(location = 0) out float o_visibility;

float lit(ivec2 texel, float depth) {
  ivec2 last = textureSize(u_depth, 0) - 1;
  return depth - u_bias <= texelFetch(u_depth, clamp(texel, ivec2(0), last), 0).r ? 1.0 : 0.0;
}

void main() {
  vec4 p = texelFetch(u_positions, ivec2(gl_FragCoord.xy), 0);
  if (p.w <= 0.0) {  // sky, or facing away from the light: not compared
    o_visibility = -1.0;
    return;
  }
  vec4 clip = u_lightViewProj * vec4(p.xyz, 1.0);
  vec3 coord = clip.xyz / clip.w * 0.5 + 0.5;
  vec2 texel = coord.xy * vec2(textureSize(u_depth, 0)) - 0.5;
  ivec2 base = ivec2(floor(texel));
  vec2 f = fract(texel);
  float sum = 0.0;
  for (int j = -u_radius; j <= u_radius; ++j)
    for (int i = -u_radius; i <= u_radius; ++i) {
      ivec2 t = base + ivec2(i, j);
      float bottom = mix(lit(t, coord.z), lit(t + ivec2(1, 0), coord.z), f.x);
      float top = mix(lit(t + ivec2(0, 1), coord.z), lit(t + ivec2(1, 1), coord.z), f.x);
      sum += u_weights[abs(i)] * u_weights[abs(j)] * mix(bottom, top, f.y);
    }
  o_visibility = sum;
}
