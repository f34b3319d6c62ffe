// Lab 06 GLSL exercises. Each function is one exercise; keep the signatures, replace the bodies.
// A body that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 06
#include "wb/exercise.glsl"

// EXERCISE 06.1: the four moments the map stores for a depth z in [0, 1]:
// (w+, w+^2, w-, w-^2) with the positive warp w+ = exp(cPos z) and the negative warp w- = -exp(-cNeg z).
vec4 evsmMoments(float depth, float cPos, float cNeg) {
  return vec4(WB_TODO);
}

// EXERCISE 06.3: the visibility of a receiver at `depth` from filtered moments. Warp the depth like
// the map, take Chebyshev's bound on each pair (lit when the warped depth is not beyond the mean;
// variance at least minVariance scaled by the warp's slope squared: (c w)^2), keep the smaller bound
// (with channels == 2, only the positive one), then reduce bleeding: clamp((p - amount)/(1 - amount)).
float evsmVisibility(vec4 moments, float depth, float cPos, float cNeg, float minVariance, float bleeding, int channels) {
  return WB_TODO;
  // Hint: for the negative warp the mean is negative and "beyond" still means a larger warped value.
}

// EXERCISE 06.x (extension): moment shadow maps, Hamburger with four moments. msmMoments stores the
// powers (z, z^2, z^3, z^4). msmVisibility first pulls the filtered moments b a little towards
// (0.5, 0.5, 0.5, 0.5) (b' = (1 - momentBias) b + momentBias 0.5) so the system below is solvable,
// then finds the two other support depths of the three-point distribution that matches b' and puts
// one point at the receiver: solve the 3x3 Hankel system [1 b1 b2; b1 b2 b3; b2 b3 b4] c = (1, z, z^2)
// (Cholesky), take the roots z2 <= z3 of c3 x^2 + c2 x + c1 = 0, and return 1 - G, where
//   G = 0                                                     if z <= z2
//   G = (z z3 - b1 (z + z3) + b2) / ((z3 - z2) (z - z2))      if z2 < z <= z3
//   G = 1 - (z2 z3 - b1 (z2 + z3) + b2) / ((z - z2) (z - z3)) otherwise.
vec4 msmMoments(float depth) {
  return vec4(WB_TODO);
}

float msmVisibility(vec4 moments, float depth, float momentBias) {
  return WB_TODO;
}
