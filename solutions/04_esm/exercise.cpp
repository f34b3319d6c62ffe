// Lab 04 C++ exercise: reference solution.
#include "exercise.hpp"

#include <cmath>

namespace lab04 {

// EXERCISE 04.4
double esmMaxExponent(double formatMax) { return std::log(formatMax); }

}  // namespace lab04
