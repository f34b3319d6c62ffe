// Lab 09 C++ exercises: replace each throw with your code. The hints below each throw are yours to
// delete. Check your work with: ./workbook check 09
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glad/gl.h>

namespace lab09 {

// EXERCISE 09.1
std::vector<uint32_t> buildAdjacency([[maybe_unused]] const std::vector<uint32_t>& triangles) {
  throw wb::NotImplemented("09.1 buildAdjacency");
  // Hints:
  // - First pass: a map from each directed edge (a, b) of every triangle to that triangle's third corner.
  // - Second pass: for edge (a, b), look up (b, a): the triangle across has the edge the other way round.
  // - Not found: an open edge. Use the triangle's own third corner.
}

// EXERCISE 09.4
StencilSetup zPassSetup() {
  throw wb::NotImplemented("09.4 zPassSetup");
  // Hints: only the depthPass operations change the count; GL_INCR_WRAP and GL_DECR_WRAP, never
  // GL_INCR and GL_DECR (they clamp at 0 and 255, so the order of the faces would matter).
}

// EXERCISE 09.5
StencilSetup zFailSetup() {
  throw wb::NotImplemented("09.5 zFailSetup");
  // Hints: now only the depthFail operations count, the other way round from 09.4; what closes the
  // volumes at both ends, now that the count starts behind the scene?
}

// EXERCISE 09.6
bool nearPlaneMayBeShadowed([[maybe_unused]] const std::array<glm::vec3, 4>& nearQuad,
                            [[maybe_unused]] const glm::vec4& light, [[maybe_unused]] const glm::vec3& boxMin,
                            [[maybe_unused]] const glm::vec3& boxMax) {
  throw wb::NotImplemented("09.6 nearPlaneMayBeShadowed");
  // Hints:
  // - The region is bounded by five planes: the near quad's own, and one through each quad edge and
  //   the light (for a directional light: through the edge, along the direction to the light).
  // - Orient every plane so a point inside the region (the average of the light and the corners, or
  //   for a directional light the quad's centre moved towards the light) is on its inner side.
  // - The box misses the region if all eight corners lie outside one of the planes. Otherwise say true.
}

}  // namespace lab09
