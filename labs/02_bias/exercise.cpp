// Lab 02 C++ exercises: replace each throw with your code. Check your work with: ./workbook check 02
#include "exercise.hpp"

#include "common/base/error.hpp"
#include "common/platform/gl.hpp"

#include <cmath>

namespace lab02 {

// EXERCISE 02.3
void applyRasterizerBias([[maybe_unused]] float factor, [[maybe_unused]] float units) {
  throw wb::NotImplemented("02.3 applyRasterizerBias");
  // Hints: glEnable(GL_POLYGON_OFFSET_FILL) and glPolygonOffset(factor, units). The offset is
  // factor · (the polygon's depth slope) + units · (the smallest resolvable depth step).
}

double d3dDepthBias([[maybe_unused]] int depthBias, [[maybe_unused]] double slopeScaledDepthBias,
                    [[maybe_unused]] double depthBiasClamp, [[maybe_unused]] double maxDepthSlope,
                    [[maybe_unused]] float maxZ) {
  throw wb::NotImplemented("02.3 d3dDepthBias");
  // Hints: std::frexp(maxZ, &e) gives maxZ = m · 2^e with m in [0.5, 1), so the IEEE exponent of
  // maxZ is e − 1. std::ldexp(1.0, k) is 2^k.
}

// EXERCISE 02.4
void cullForDepthPass([[maybe_unused]] bool enabled) {
  throw wb::NotImplemented("02.4 cullForDepthPass");
  // Hints: glEnable(GL_CULL_FACE), glCullFace(...). Which faces look at the light?
}

}  // namespace lab02
