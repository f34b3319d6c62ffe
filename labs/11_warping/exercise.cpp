// Lab 11 C++ exercises: replace each throw with your code. The hints below each throw are yours to
// delete. Check your work with: ./workbook check 11
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lab11 {

// EXERCISE 11.3
float warpNear([[maybe_unused]] float zNear, [[maybe_unused]] float depthRange, [[maybe_unused]] float sinGamma,
               [[maybe_unused]] float strength, [[maybe_unused]] float fadeSin) {
  throw wb::NotImplemented("11.3 warpNear");
  // Hints: z1 first, then n_opt; the fade is a clamp of a straight line; s = 0 gives
  // std::numeric_limits<float>::infinity().
}

// EXERCISE 11.4
glm::mat4 warpMatrix([[maybe_unused]] const glm::mat4& lightView, [[maybe_unused]] const std::vector<glm::vec3>& body,
                     [[maybe_unused]] float n, [[maybe_unused]] float casterReach) {
  throw wb::NotImplemented("11.4 warpMatrix");
  // Hints: the body's light-space bounds first. The depth row is glm::ortho's. For the warp, write the
  // perspective along y as a matrix whose last row gives w = y - (smallest y) + n; glm::mat4 is
  // column-major (m[column][row]). Take the body's points through it, divide by w, and fit x.
}

// EXERCISE 11.6
std::vector<float> fittedSplits([[maybe_unused]] glm::vec2 bounds, [[maybe_unused]] float nearPlane,
                                [[maybe_unused]] float farPlane, [[maybe_unused]] int cascades,
                                [[maybe_unused]] float lambda) {
  throw wb::NotImplemented("11.6 fittedSplits");
  // Hints: decide lo and hi first (clamp, then fall back); lab 10's practical scheme does the rest.
}

}  // namespace lab11
