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
