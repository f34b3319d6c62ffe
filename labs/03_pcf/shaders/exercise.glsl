// Lab 03 GLSL exercises. Each function is one exercise; keep the signatures, replace the bodies.
// A body that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 03
// Every function filters the *comparisons*: a tap is lit (1) when coord.z - bias <= its stored depth.
#include "wb/exercise.glsl"
#include "wb/hash.glsl"
#include "wb/poisson.glsl"

// EXERCISE 03.1: an N x N grid of explicit comparisons, N = 2 * radius + 1.
// Taps sit at coord.xy + (i, j) * spacing texels, for i, j in [-radius, radius]; returns their mean.
float pcfGrid(sampler2D map, vec3 coord, int radius, float spacing, float bias) {
  return WB_TODO;
  // Hints: textureSize(map, 0) gives the map size in texels. Compare, then average; averaging the
  // depths first and comparing once gives a hard shadow again.
}

// EXERCISE 03.2: the hardware's 2 x 2 filter (a demo: the filtering is implementation-defined).
// `map` has GL_COMPARE_REF_TO_TEXTURE and linear filtering; sampling it returns the filtered result.
float pcfHardware(sampler2DShadow map, vec3 coord, float bias) {
  return WB_TODO;
  // Hint: the third coordinate of a sampler2DShadow lookup is the reference depth.
}

// EXERCISE 03.3: Gaussian weights.
// The weight of a tap `offsetTexels` away from the centre: exp(-|offset|^2 / (2 sigma^2)).
float gaussianWeight(vec2 offsetTexels, float sigma) {
  return WB_TODO;
}

// The grid of 03.1 with those weights (offsets in texels, i.e. (i, j) * spacing), normalised by
// the sum of the weights.
float pcfGaussian(sampler2D map, vec3 coord, int radius, float spacing, float sigma, float bias) {
  return WB_TODO;
}

// EXERCISE 03.4: a Poisson disk, rotated per pixel.
// Taps at coord.xy + R(angle) * WB_POISSON_DISK[k] * radiusTexels texels, k < count, where R rotates
// counter-clockwise by angle = 2 pi * wbHash01(pixel). Returns the mean of the comparisons.
float pcfPoisson(sampler2D map, vec3 coord, int count, float radiusTexels, uvec2 pixel, float bias) {
  return WB_TODO;
  // Hint: mat2(c, s, -s, c) rotates counter-clockwise (GLSL matrices are column-major).
}

// EXERCISE 03.5: optimized PCF. The same result as pcfGrid(map, coord, radius, 1.0, bias), from
// textureGather, which returns 4 depths per fetch: ((radius + 1)^2 fetches instead of (2 radius + 1)^2).
float pcfGather(sampler2D map, vec3 coord, int radius, float bias) {
  return WB_TODO;
  // Hints: the grid's taps land in the texels t0 + (i, j), t0 = floor(coord.xy * size).
  // textureGather at the corner (t0 + (i, j) + 1) / size returns texels i..i+1, j..j+1 as
  // (x: (i, j+1), y: (i+1, j+1), z: (i+1, j), w: (i, j)). With an odd N, the last row and column of
  // gathers reach one texel too far: leave those out.
}

// EXERCISE 03.H1: bug hunt, "dark ground under the short lamp" (README.md, Bug hunt 03.H1).
// Not a stub: this is the lab's working code, and it has a bug that shipped in real engines. Find it
// from the symptom; the handout says how to see it and how it is measured.
// True when the shadow map holds an answer for the point at shadow coordinate `coord` (the map's
// uv and the depth the light's projection gives it); the scene pass counts any other point as lit.
bool insideShadowMap(vec3 coord) {
  bvec2 low = greaterThanEqual(coord.xy, vec2(0.0)), high = lessThanEqual(coord.xy, vec2(1.0));
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
  return bias * reachTexels;
}
