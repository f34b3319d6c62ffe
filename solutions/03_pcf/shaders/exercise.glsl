// Lab 03 GLSL exercises: reference solution.
#include "wb/exercise.glsl"
#include "wb/hash.glsl"
#include "wb/poisson.glsl"

// EXERCISE 03.1: an N x N grid of explicit comparisons.
float pcfGrid(sampler2D map, vec3 coord, int radius, float spacing, float bias) {
  vec2 texel = 1.0 / vec2(textureSize(map, 0));
  float sum = 0.0, count = 0.0;
  for (int j = -radius; j <= radius; ++j)
    for (int i = -radius; i <= radius; ++i) {
      float depth = texture(map, coord.xy + vec2(i, j) * spacing * texel).r;
      sum += step(coord.z - bias, depth);
      count += 1.0;
    }
  return sum / count;
}

// EXERCISE 03.2: the hardware's 2 x 2 filter.
float pcfHardware(sampler2DShadow map, vec3 coord, float bias) {
  return texture(map, vec3(coord.xy, coord.z - bias));
}

// EXERCISE 03.3: Gaussian weights.
float gaussianWeight(vec2 offsetTexels, float sigma) {
  return exp(-dot(offsetTexels, offsetTexels) / (2.0 * sigma * sigma));
}

float pcfGaussian(sampler2D map, vec3 coord, int radius, float spacing, float sigma, float bias) {
  vec2 texel = 1.0 / vec2(textureSize(map, 0));
  float sum = 0.0, weights = 0.0;
  for (int j = -radius; j <= radius; ++j)
    for (int i = -radius; i <= radius; ++i) {
      vec2 offset = vec2(i, j) * spacing;
      float w = gaussianWeight(offset, sigma);
      sum += w * step(coord.z - bias, texture(map, coord.xy + offset * texel).r);
      weights += w;
    }
  return sum / weights;
}

// EXERCISE 03.4: a Poisson disk, rotated per pixel.
float pcfPoisson(sampler2D map, vec3 coord, int count, float radiusTexels, uvec2 pixel, float bias) {
  vec2 texel = 1.0 / vec2(textureSize(map, 0));
  float angle = 6.28318531 * wbHash01(pixel);
  float c = cos(angle), s = sin(angle);
  mat2 rot = mat2(c, s, -s, c);
  float sum = 0.0;
  for (int k = 0; k < count; ++k) {
    vec2 p = rot * WB_POISSON_DISK[k];
    sum += step(coord.z - bias, texture(map, coord.xy + p * radiusTexels * texel).r);
  }
  return sum / float(count);
}

// EXERCISE 03.5: optimized PCF with textureGather.
float pcfGather(sampler2D map, vec3 coord, int radius, float bias) {
  vec2 size = vec2(textureSize(map, 0));
  vec2 t0 = floor(coord.xy * size);
  float z = coord.z - bias, sum = 0.0;
  for (int j = -radius; j <= radius; j += 2)
    for (int i = -radius; i <= radius; i += 2) {
      vec4 lit = step(vec4(z), textureGather(map, (t0 + vec2(i, j) + 1.0) / size));
      bool lastX = i + 1 > radius, lastY = j + 1 > radius;
      sum += lit.w + (lastX ? 0.0 : lit.z) + (lastY ? 0.0 : lit.x) + (lastX || lastY ? 0.0 : lit.y);
    }
  float n = float(2 * radius + 1);
  return sum / (n * n);
}

// EXERCISE 03.H1: bug hunt, "dark ground under the short lamp" (README.md, Bug hunt 03.H1).
// Not a stub: this is the lab's working code, and it has a bug that shipped in real engines. Find it
// from the symptom; the handout says how to see it and how it is measured.
// True when the shadow map holds an answer for the point at shadow coordinate `coord` (the map's
// uv and the depth the light's projection gives it); the scene pass counts any other point as lit.
bool insideShadowMap(vec3 coord) {
  bvec3 low = greaterThanEqual(coord, vec3(0.0)), high = lessThanEqual(coord, vec3(1.0));
  return all(low) && all(high);
}

// EXERCISE 03.H2: bug hunt, "acne when the filter is one tap wide" (README.md, Bug hunt 03.H2).
// Not a stub: this is the lab's working code, and it has a bug that shipped in a real engine. Find it
// from the symptom; the handout says how to see it and how it is measured.
// The bias the scene pass gives a filter whose taps reach up to `reachTexels` texels from the point
// along either axis of the map (0: a single tap), where `bias` (shadow.bias) is what a single tap
// needs. A tap further away reads the receiver's surface further along its slope, so each texel of
// reach needs one more `bias`.
float filterBias(float bias, float reachTexels) {
  return bias * (1.0 + reachTexels);
}
