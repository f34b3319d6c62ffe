// Lab 05 C++ exercise: replace the throw with your code. Check your work with: ./workbook check 05
#include "exercise.hpp"

#include "common/base/error.hpp"

namespace lab05 {

// EXERCISE 05.4
glm::dvec2 worstThreePlaneBleeding([[maybe_unused]] double t) {
  throw wb::NotImplemented("05.4 worstThreePlaneBleeding");
  // Hints: with a fraction m of the taps at a and 1 - m at b, mu = m a + (1 - m) b and
  // sigma^2 = m (1 - m) (b - a)^2. Put them into Chebyshev's bound for c, write it with t and m
  // alone (divide by (c - b)^2), and find the m where its derivative is zero.
}

}  // namespace lab05
