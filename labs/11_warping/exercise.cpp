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

namespace lab11 {

// EXERCISE 11.H1: bug hunt, "with SDSM on, the cascades give fewer texels than without" (README.md, Bug
// hunt 11.H1). Not a stub: this is the lab's working code, and it has a bug that shipped in a real
// engine. Find it from the symptom; the handout says how to see it and how it is measured.
// The split positions travel as fractions of the shadow range (0 at its start, 1 at its end), the form
// an engine's settings and its shader share; here they become view distances again.
std::vector<float> switchDistances(const std::vector<float>& splits, float nearPlane, float farPlane) {
  std::vector<float> out;
  if (splits.size() < 2) return out;
  const float start = splits.front(), length = splits.back() - splits.front();
  for (size_t i = 1; i + 1 < splits.size(); ++i) {
    const float fraction = (splits[i] - start) / length;
    out.push_back(nearPlane + fraction * (farPlane - nearPlane));
  }
  return out;
}

}  // namespace lab11
