// Lab 05 GLSL exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 05.1: the moments, with the derivative bias.
vec2 vsmMoments(float depth, float dzdx, float dzdy) {
  return vec2(depth, depth * depth + 0.25 * (dzdx * dzdx + dzdy * dzdy));
}

// EXERCISE 05.2: Chebyshev's one-tailed bound.
float chebyshevUpperBound(vec2 moments, float receiverDepth, float minVariance) {
  if (receiverDepth <= moments.x) return 1.0;
  float variance = max(moments.y - moments.x * moments.x, minVariance);
  float d = receiverDepth - moments.x;
  return variance / (variance + d * d);
}

// EXERCISE 05.3: light-bleeding reduction.
float reduceLightBleeding(float pMax, float amount) {
  return clamp((pMax - amount) / (1.0 - amount), 0.0, 1.0);
}
