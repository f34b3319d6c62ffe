// What lab 07's exercises share (not an exercise): the per-pixel disk rotation, the map's depths as
// distances along the light's axis, and the settings PCSS reads.
#ifndef PCSS_COMMON_GLSL
#define PCSS_COMMON_GLSL
#include "wb/hash.glsl"
#include "wb/poisson.glsl"

// The rotation of the Poisson disk at a pixel: a turn by 2 pi * wbHash01(pixel), as in lab 03.
mat2 pcssRotation(uvec2 pixel) {
  float angle = 6.28318531 * wbHash01(pixel);
  float c = cos(angle), s = sin(angle);
  return mat2(c, s, -s, c);
}

// A depth the spot light's perspective map stores ([0, 1]) as the distance along the light's axis,
// in world units: z = near * far / (far - d * (far - near)).
float pcssLinearDepth(float stored, vec2 nearFar) {
  return nearFar.x * nearFar.y / (nearFar.y - stored * (nearFar.y - nearFar.x));
}

// The map's depth at uv, as a distance along the light's axis.
float pcssDepthAt(sampler2D map, vec2 uv, vec2 nearFar) { return pcssLinearDepth(texture(map, uv).r, nearFar); }

struct PcssSettings {
  float lightSizeUV;  // the light's diameter over the map's width at the near plane
  vec2 nearFar;       // the light's near and far planes (world units)
  int searchSamples;  // Poisson taps of the blocker search (16, 25, 32 or 64)
  int filterSamples;  // Poisson taps of the filter
  float minFilterUV;  // the narrowest filter (uv): contact shadows stay anti-aliased
  float bias;         // a receiver closer than a texel's depth + bias is lit (world units)
};
#endif
