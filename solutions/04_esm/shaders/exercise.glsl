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

// EXERCISE 04.H1: bug hunt, "log space loses the shadows at large c" (README.md, Bug hunt 04.H1).
// Not a stub: this is the lab's working code, and it has a bug of a kind that shipped in a real
// engine. Find it from the symptom; the handout says how to see it and how it is measured.
// One pass of the separable prefilter in log space: the map holds c z, and the result is the log of
// the weighted sum of exp(c z) over the 2 radius + 1 texels along `axis` around texel p (weights[|i|]
// for tap i, normalised), which the next pass and the lookup read as c z again.
float logBlurTaps(sampler2D source, ivec2 p, ivec2 axis, int radius, float weights[8]) {
  ivec2 last = textureSize(source, 0) - 1;
  float logSum = -1e30;
  for (int i = -radius; i <= radius; ++i) {
    float cz = texelFetch(source, clamp(p + i * axis, ivec2(0), last), 0).r;
    logSum = logAdd(logSum, log(weights[abs(i)]) + cz);
  }
  return logSum;
}
