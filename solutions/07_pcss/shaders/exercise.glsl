// Lab 07 GLSL exercises: reference solution.
#include "wb/exercise.glsl"
#include "pcss_common.glsl"

// EXERCISE 07.1: the search region.
float pcssSearchWidth(float lightSizeUV, float zReceiver, float zNear) {
  return lightSizeUV * (zReceiver - zNear) / zReceiver;
}

// EXERCISE 07.2: the blocker search.
vec2 pcssFindBlockers(sampler2D map, vec2 uv, float zReceiver, float searchWidthUV, int samples, mat2 rotation,
                      vec2 nearFar, float bias) {
  float sum = 0.0, count = 0.0;
  for (int k = 0; k < samples; ++k) {
    float z = pcssDepthAt(map, uv + rotation * WB_POISSON_DISK[k] * (0.5 * searchWidthUV), nearFar);
    if (z < zReceiver - bias) {
      sum += z;
      count += 1.0;
    }
  }
  return count > 0.0 ? vec2(sum / count, count) : vec2(0.0);
}

// EXERCISE 07.3: the penumbra width.
float pcssPenumbraWidth(float zReceiver, float zBlocker, float lightSize) {
  return (zReceiver - zBlocker) / zBlocker * lightSize;
}

// EXERCISE 07.4: PCSS.
float pcss(sampler2D map, vec2 uv, float zReceiver, PcssSettings s, uvec2 pixel) {
  mat2 rotation = pcssRotation(pixel);
  float search = pcssSearchWidth(s.lightSizeUV, zReceiver, s.nearFar.x);
  vec2 blockers = pcssFindBlockers(map, uv, zReceiver, search, s.searchSamples, rotation, s.nearFar, s.bias);
  if (blockers.y == 0.0) return 1.0;
  float penumbra = pcssPenumbraWidth(zReceiver, blockers.x, s.lightSizeUV);
  float width = max(penumbra * s.nearFar.x / zReceiver, s.minFilterUV);
  float lit = 0.0;
  for (int k = 0; k < s.filterSamples; ++k)
    lit += step(zReceiver - s.bias, pcssDepthAt(map, uv + rotation * WB_POISSON_DISK[k] * (0.5 * width), s.nearFar));
  return lit / float(s.filterSamples);
}

// EXERCISE 07.H1: bug hunt, "the PCF comparison blurs more on a sharper map" (README.md, Bug hunt
// 07.H1).
// pcss.method=pcf, the comparison: one fixed filter width everywhere, `widthTexels` texels of `map`,
// with the same taps as PCSS's filter (samples of the rotated Poisson disk, a receiver at zReceiver
// lit by a tap whose depth is beyond it by `bias`).
float fixedPcf(sampler2D map, vec2 uv, float zReceiver, float widthTexels, float bias, vec2 nearFar, int samples,
               uvec2 pixel) {
  float widthUV = widthTexels / float(textureSize(map, 0).x);
  mat2 rotation = pcssRotation(pixel);
  float sum = 0.0;
  for (int k = 0; k < samples; ++k)
    sum += step(zReceiver - bias, pcssDepthAt(map, uv + rotation * WB_POISSON_DISK[k] * (0.5 * widthUV), nearFar));
  return sum / float(samples);
}
