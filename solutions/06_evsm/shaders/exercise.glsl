// Lab 06 GLSL exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 06.1: the four moments.
vec4 evsmMoments(float depth, float cPos, float cNeg) {
  float pos = exp(cPos * depth), neg = -exp(-cNeg * depth);
  return vec4(pos, pos * pos, neg, neg * neg);
}

// EXERCISE 06.3: the smaller of two Chebyshev bounds, with bleeding reduction.
float evsmChebyshev(vec2 moments, float warped, float minVariance) {
  if (warped <= moments.x) return 1.0;
  float variance = max(moments.y - moments.x * moments.x, minVariance);
  float d = warped - moments.x;
  return variance / (variance + d * d);
}

float evsmVisibility(vec4 moments, float depth, float cPos, float cNeg, float minVariance, float bleeding, int channels) {
  float pos = exp(cPos * depth), neg = -exp(-cNeg * depth);
  float p = evsmChebyshev(moments.xy, pos, minVariance * (cPos * pos) * (cPos * pos));
  if (channels == 4) p = min(p, evsmChebyshev(moments.zw, neg, minVariance * (cNeg * neg) * (cNeg * neg)));
  return clamp((p - bleeding) / (1.0 - bleeding), 0.0, 1.0);
}
