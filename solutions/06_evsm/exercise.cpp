// Lab 06 C++ exercise: reference solution.
#include "exercise.hpp"

#include <cmath>

namespace lab06 {

// EXERCISE 06.2
double evsmMaxExponent(double formatMax) { return 0.5 * std::log(formatMax); }

}  // namespace lab06
