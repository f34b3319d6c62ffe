// Lab 06 C++ exercise: replace the throw with your code. Check your work with: ./workbook check 06
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <cmath>

namespace lab06 {

// EXERCISE 06.2
double evsmMaxExponent([[maybe_unused]] double formatMax) {
  throw wb::NotImplemented("06.2 evsmMaxExponent");
  // Hint: lab 04's bound was for exp(c); the map now also stores exp(c)^2 = exp(2c).
}

}  // namespace lab06
