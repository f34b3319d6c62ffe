// Lab 05 C++ exercise: replace the throw with your code. Check your work with: ./workbook check 05
#include "exercise.hpp"

#include "common/error.hpp"

namespace lab05 {

// EXERCISE 05.4
double threePlaneBleeding([[maybe_unused]] double t) {
  throw wb::NotImplemented("05.4 threePlaneBleeding");
  // Hints: with half the filter at a and half at b, mu = (a + b) / 2 and sigma^2 = (b - a)^2 / 4.
  // Put them into Chebyshev's bound for the receiver c and write the result with t alone.
}

}  // namespace lab05
