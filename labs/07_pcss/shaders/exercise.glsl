// Lab 07 exercises: percentage-closer soft shadows. Each function returns WB_TODO until you write it.
// A body that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 07
// Keep the "// EXERCISE 07.x" lines: the grader finds each exercise by its line.
//
// Conventions (the tests rely on them):
//  - depths are distances along the light's axis, in world units: zReceiver for the pixel,
//    pcssDepthAt(map, uv, nearFar) for the map (pcss_common.glsl);
//  - widths are FULL widths in shadow-map uv units ([0, 1] spans the map), so a disk of width w has
//    radius w / 2. WB_POISSON_DISK[k] lies in the unit disk (radius 1): tap k of a region of width w
//    around uv is uv + rotation * WB_POISSON_DISK[k] * (w / 2), for k = 0 .. samples - 1;
//  - a tap is a blocker when its depth < zReceiver - bias; it is lit when its depth >= zReceiver - bias.
#include "wb/exercise.glsl"
#include "pcss_common.glsl"

// EXERCISE 07.1: the width of the region to search for blockers, on the map: the light's disk seen
// from the receiver, cut by the near plane: lightSizeUV * (zReceiver - zNear) / zReceiver.
float pcssSearchWidth(float lightSizeUV, float zReceiver, float zNear) {
  return WB_TODO;
}

// EXERCISE 07.2: the blocker search. Visit `samples` taps over the region of width searchWidthUV;
// return vec2(the mean depth of the taps that are blockers, how many there were), or vec2(0.0) when
// there are none (the caller then knows the pixel is fully lit and skips the rest).
vec2 pcssFindBlockers(sampler2D map, vec2 uv, float zReceiver, float searchWidthUV, int samples, mat2 rotation,
                      vec2 nearFar, float bias) {
  return vec2(WB_TODO);
}

// EXERCISE 07.3: the penumbra's width under the parallel-planes assumption, in the units of
// lightSize: (zReceiver - zBlocker) / zBlocker * lightSize.
float pcssPenumbraWidth(float zReceiver, float zBlocker, float lightSize) {
  return WB_TODO;
}

// EXERCISE 07.4: PCSS. Rotate the disk by pcssRotation(pixel); search (07.1, 07.2); with no
// blockers return 1.0 at once; else take the penumbra (07.3, in uv with s.lightSizeUV), project it
// onto the map (* s.nearFar.x / zReceiver), keep it at least s.minFilterUV wide, and return the lit
// share of s.filterSamples taps over a disk of that width.
float pcss(sampler2D map, vec2 uv, float zReceiver, PcssSettings s, uvec2 pixel) {
  return WB_TODO;
}

// EXERCISE 07.H1: bug hunt, "the PCF comparison blurs more on a sharper map" (README.md, Bug hunt
// 07.H1). Not a stub: this is the lab's working code, and it has a bug of a kind that shipped in a
// real engine. Find it from the symptom; the handout says how to see it and how it is measured.
// pcss.method=pcf, the comparison: one fixed filter width everywhere, `widthTexels` texels of `map`,
// with the same taps as PCSS's filter (samples of the rotated Poisson disk, a receiver at zReceiver
// lit by a tap whose depth is beyond it by `bias`).
float fixedPcf(sampler2D map, vec2 uv, float zReceiver, float widthTexels, float bias, vec2 nearFar, int samples,
               uvec2 pixel) {
  float widthUV = widthTexels / 512.0;
  mat2 rotation = pcssRotation(pixel);
  float sum = 0.0;
  for (int k = 0; k < samples; ++k)
    sum += step(zReceiver - bias, pcssDepthAt(map, uv + rotation * WB_POISSON_DISK[k] * (0.5 * widthUV), nearFar));
  return sum / float(samples);
}
