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
