// Lab 04 C++ exercise: replace the throw with your code. Check your work with: ./workbook check 04
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <cmath>

namespace lab04 {

// EXERCISE 04.4
double esmMaxExponent([[maybe_unused]] double formatMax) {
  throw wb::NotImplemented("04.4 esmMaxExponent");
  // Hint: the largest stored value is exp(c · 1). Solve exp(c) = formatMax for c.
}

}  // namespace lab04
