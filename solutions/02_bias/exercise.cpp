// Lab 02 C++ exercises: reference solution.
#include "exercise.hpp"

#include "common/platform/gl.hpp"

#include <algorithm>
#include <cmath>

namespace lab02 {

// EXERCISE 02.3
void applyRasterizerBias(float factor, float units) {
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(factor, units);
}

double d3dDepthBias(int depthBias, double slopeScaledDepthBias, double depthBiasClamp, double maxDepthSlope,
                    float maxZ) {
  int e = 0;
  std::frexp(maxZ, &e);  // maxZ = m · 2^e, m in [0.5, 1): the IEEE exponent is e − 1
  const double bias = depthBias * std::ldexp(1.0, (e - 1) - 23) + slopeScaledDepthBias * maxDepthSlope;
  if (depthBiasClamp > 0) return std::min(bias, depthBiasClamp);
  if (depthBiasClamp < 0) return std::max(bias, depthBiasClamp);
  return bias;
}

// EXERCISE 02.4
void cullForDepthPass(bool enabled) {
  if (!enabled) {
    glDisable(GL_CULL_FACE);
    return;
  }
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);  // the faces turned to the light; the map keeps the back faces
}

// EXERCISE 02.H1: bug hunt, "the awning casts no shadow" (README.md, Bug hunt 02.H1).
// The depth pass's face culling for every method but front_faces (02.4 sets its own).
void depthPassCulling() {
  glDisable(GL_CULL_FACE);  // none: a single-sided (open) mesh casts from its back as well as its front
}

}  // namespace lab02
