// Lab 04 GLSL exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 04.1: the warped depth.
float esmWarp(float depth, float c) {
  return exp(c * depth);
}

// EXERCISE 04.2: log-space filtering.
float logAdd(float logA, float logB) {
  float m = max(logA, logB);
  return m + log(1.0 + exp(-abs(logA - logB)));
}

// EXERCISE 04.3: evaluate and clamp.
float esmVisibility(float logFiltered, float receiverDepth, float c) {
  return clamp(exp(logFiltered - c * receiverDepth), 0.0, 1.0);
}

// EXERCISE 04.5: non-planarity.
float esmNeedsFallback(float logFiltered, float receiverDepth, float c, float epsilon) {
  return logFiltered - c * receiverDepth > log(1.0 + epsilon) ? 1.0 : 0.0;
}
