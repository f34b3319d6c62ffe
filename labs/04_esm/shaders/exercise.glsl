// Lab 04 GLSL exercises. Each function is one exercise; keep the signatures, replace the bodies.
// A body that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 04
#include "wb/exercise.glsl"

// EXERCISE 04.1: the value the map stores for a depth z in [0, 1]: exp(c z).
float esmWarp(float depth, float c) {
  return WB_TODO;
}

// EXERCISE 04.2: log-space filtering. Given log(A) and log(B), return log(A + B) without ever
// forming A or B (they may be far beyond the format's range).
float logAdd(float logA, float logB) {
  return WB_TODO;
  // Hint: log(A + B) = m + log(1 + exp(-|logA - logB|)) with m = max(logA, logB). logA may be
  // -1e30 (an empty sum): the formula must still return logB.
}

// EXERCISE 04.3: evaluate. logFiltered = log of the filtered exp(c z) around the lookup. Returns the
// visibility exp(logFiltered - c * receiverDepth), clamped to [0, 1].
float esmVisibility(float logFiltered, float receiverDepth, float c) {
  return WB_TODO;
}

// EXERCISE 04.5: non-planarity. Returns 1.0 when the unclamped ESM value exceeds 1 + epsilon (the
// filter averaged in surfaces behind the receiver, and ESM's assumption fails), else 0.0.
float esmNeedsFallback(float logFiltered, float receiverDepth, float c, float epsilon) {
  return WB_TODO;
  // Hint: compare in log space to avoid overflow: exp(x) > 1 + e  <=>  x > log(1 + e).
}

// EXERCISE 04.H1: bug hunt, "log space loses the shadows at large c" (README.md, Bug hunt 04.H1).
// Not a stub: this is the lab's working code, and it has a bug of a kind that shipped in a real
// engine. Find it from the symptom; the handout says how to see it and how it is measured.
// One pass of the separable prefilter in log space: the map holds c z, and the result is the log of
// the weighted sum of exp(c z) over the 2 radius + 1 texels along `axis` around texel p (weights[|i|]
// for tap i, normalised), which the next pass and the lookup read as c z again.
float logBlurTaps(sampler2D source, ivec2 p, ivec2 axis, int radius, float weights[8]) {
  ivec2 last = textureSize(source, 0) - 1;
  float sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    float cz = texelFetch(source, clamp(p + i * axis, ivec2(0), last), 0).r;
    sum += weights[abs(i)] * exp(cz);
  }
  return log(sum);
}
