// Lab 06 C++ exercise: replace the throw with your code. Check your work with: ./workbook check 06
#include "exercise.hpp"

#include <algorithm>

#include "common/base/error.hpp"

#include <cmath>

namespace lab06 {

// EXERCISE 06.2
double evsmMaxExponent([[maybe_unused]] double formatMax) {
  throw wb::NotImplemented("06.2 evsmMaxExponent");
  // Hint: lab 04's bound was for exp(c); the map now also stores exp(c)^2 = exp(2c).
}

// EXERCISE 06.H1: bug hunt, "a larger c+ brings the light bleeding back" (README.md, Bug hunt 06.H1).
// Not a stub: this is the lab's working code, and it has a bug of a kind that shipped in a real
// engine. Find it from the symptom; the handout says how to see it and how it is measured.
glm::vec2 usableExponents(float cPos, float cNeg, double bound, bool fp16) {
  // fp32 holds exp(88): no exponent the settings offer overflows it, so only fp16 needs the clamp.
  if (!fp16 || std::max(cPos, cNeg) <= bound) return {cPos, cNeg};
  const float limit = float(bound) * 0.999f;
  return {std::min(cPos, limit), std::min(cNeg, limit)};
}

}  // namespace lab06
