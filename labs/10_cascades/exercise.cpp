// Lab 10 C++ exercises: replace each throw with your code. The hints below each throw are yours to
// delete. Check your work with: ./workbook check 10
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

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

}  // namespace lab10
