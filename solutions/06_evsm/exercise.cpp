// Lab 06 C++ exercise: reference solution.
#include "exercise.hpp"

#include <algorithm>

#include <cmath>

namespace lab06 {

// EXERCISE 06.2
double evsmMaxExponent(double formatMax) { return 0.5 * std::log(formatMax); }

// EXERCISE 06.H1: bug hunt, "a larger c+ brings the light bleeding back".
glm::vec2 usableExponents(float cPos, float cNeg, double bound, [[maybe_unused]] bool fp16) {
  // Every format: exp(c)^2 is stored, and 06.2's bound says where it overflows this one.
  if (std::max(cPos, cNeg) <= bound) return {cPos, cNeg};
  const float limit = float(bound) * 0.999f;
  return {std::min(cPos, limit), std::min(cNeg, limit)};
}

}  // namespace lab06
