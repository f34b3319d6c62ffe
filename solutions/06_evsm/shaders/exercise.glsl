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

// EXERCISE 06.x (extension): moment shadow maps, Hamburger with four moments.
vec4 msmMoments(float depth) {
  float z2 = depth * depth;
  return vec4(depth, z2, z2 * depth, z2 * z2);
}

float msmVisibility(vec4 moments, float depth, float momentBias) {
  vec4 b = mix(moments, vec4(0.5), momentBias);
  // Cholesky of the Hankel matrix H = L D L^T, then L y = (1, z, z^2), D L^T c = y.
  float d1 = b.y - b.x * b.x;                     // the variance
  float l21 = (b.z - b.x * b.y) / d1;
  float d2 = b.w - b.y * b.y - l21 * l21 * d1;
  float y1 = depth - b.x, y2 = depth * depth - b.y - l21 * y1;
  float c3 = y2 / d2, c2 = y1 / d1 - l21 * c3, c1 = 1.0 - b.x * c2 - b.y * c3;
  float root = sqrt(max(c2 * c2 - 4.0 * c3 * c1, 0.0));
  float r0 = (-c2 - root) / (2.0 * c3), r1 = (-c2 + root) / (2.0 * c3);
  float z2 = min(r0, r1), z3 = max(r0, r1);
  float shadow;
  if (depth <= z2)
    shadow = 0.0;
  else if (depth <= z3)
    shadow = (depth * z3 - b.x * (depth + z3) + b.y) / ((z3 - z2) * (depth - z2));
  else
    shadow = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((depth - z2) * (depth - z3));
  return clamp(1.0 - shadow, 0.0, 1.0);
}
