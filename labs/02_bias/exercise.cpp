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

// EXERCISE 02.H1: bug hunt, "the awning casts no shadow" (README.md, Bug hunt 02.H1).
// Not a stub: this is the lab's working code, and it has a bug that shipped in a real sample. Find it
// from the symptom; the handout says how to see it and how it is measured.
// The depth pass's face culling for every method but front_faces (02.4 sets its own).
void depthPassCulling() {
  // The same as the camera pass: the faces turned away cannot be seen, so skip them.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
}

}  // namespace lab02
