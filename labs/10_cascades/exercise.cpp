// Lab 10 C++ exercises: replace each throw with your code. The hints below each throw are yours to
// delete. Check your work with: ./workbook check 10
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace lab10 {

// EXERCISE 10.1
std::vector<float> splitDistances([[maybe_unused]] float nearPlane, [[maybe_unused]] float farPlane,
                                  [[maybe_unused]] int cascades, [[maybe_unused]] SplitScheme scheme,
                                  [[maybe_unused]] float lambda) {
  throw wb::NotImplemented("10.1 splitDistances");
  // Hints: t = i / N for i = 0 .. N; the uniform and logarithmic formulas are in exercise.hpp, and
  // the practical scheme mixes them with lambda. Make the first and last values exactly near and far.
}

// EXERCISE 10.2
std::array<glm::vec3, 8> sliceCorners([[maybe_unused]] const glm::mat4& invView, [[maybe_unused]] float fovY,
                                      [[maybe_unused]] float aspect, [[maybe_unused]] float d0,
                                      [[maybe_unused]] float d1) {
  throw wb::NotImplemented("10.2 sliceCorners");
  // Hints: at distance d the frustum's half-height is d * tan(fovY / 2) and its half-width that times
  // the aspect; build each corner in camera space (z = -d) and take it to the world with invView.
}

// EXERCISE 10.3
glm::mat4 fitCascade([[maybe_unused]] const glm::mat4& lightView,
                     [[maybe_unused]] const std::array<glm::vec3, 8>& corners, [[maybe_unused]] float casterReach) {
  throw wb::NotImplemented("10.3 fitCascade");
  // Hints: take the corners to light space and find their bounds; glm::ortho(left, right, bottom,
  // top, zNear, zFar) measures zNear and zFar as distances in front of the light (-z).
}

// EXERCISE 10.4
glm::mat4 stableCascade([[maybe_unused]] const glm::mat4& lightView,
                        [[maybe_unused]] const std::array<glm::vec3, 8>& corners, [[maybe_unused]] int mapSize,
                        [[maybe_unused]] float casterReach) {
  throw wb::NotImplemented("10.4 stableCascade");
  // Hints: the centre and the radius first (round the radius up to the next multiple of 1/16); in
  // light space one texel is 2 * radius / mapSize wide: move the centre's x and y down to a whole
  // number of texels. The depth range is the sphere's, extended towards the light by casterReach.
}

// EXERCISE 10.H2: bug hunt, "with csm.cull=on, shadows go missing near the camera" (README.md, Bug
// hunt 10.H2). Not a stub: this is the lab's working code, and it has a bug that shipped in a real
// engine. Find it from the symptom; the handout says how to see it and how it is measured.
// csm.cull=on draws into each cascade's map only the objects that concern it, so that a cascade
// draws a few of the field's objects rather than all of them. An object is kept when its box lies
// on the cascade's map (its corners' x and y in the cascade's clip space overlap [-1, 1], and not
// all of it is beyond the far plane) and along the view within the cascade's slice.
std::vector<uint32_t> castersFor(const glm::mat4& cascade, const glm::mat4& view, float sliceNear, float sliceFar,
                                 const std::vector<Box>& boxes) {
  std::vector<uint32_t> kept;
  for (size_t k = 0; k < boxes.size(); ++k) {
    glm::vec3 lo(1e30f), hi(-1e30f);           // the box in the cascade's clip space
    float nearest = 1e30f, farthest = -1e30f;  // and along the view
    for (int c = 0; c < 8; ++c) {
      const glm::vec4 corner(c & 1 ? boxes[k].second.x : boxes[k].first.x, c & 2 ? boxes[k].second.y : boxes[k].first.y,
                             c & 4 ? boxes[k].second.z : boxes[k].first.z, 1);
      const glm::vec3 p(cascade * corner);  // (orthographic: w stays 1)
      lo = glm::min(lo, p), hi = glm::max(hi, p);
      const float depth = -(view * corner).z;
      nearest = std::min(nearest, depth), farthest = std::max(farthest, depth);
    }
    const bool onMap = lo.x <= 1 && hi.x >= -1 && lo.y <= 1 && hi.y >= -1 && lo.z <= 1;
    const bool inSlice = farthest >= sliceNear && nearest <= sliceFar;
    if (onMap && inSlice) kept.push_back(uint32_t(k));
  }
  return kept;
}

}  // namespace lab10
