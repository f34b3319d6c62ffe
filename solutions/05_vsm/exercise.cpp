// Lab 05 C++ exercise: reference solution.
#include "exercise.hpp"

namespace lab05 {

// EXERCISE 05.4
// sigma^2 / (sigma^2 + (c - mu)^2) with sigma^2 = dx^2 / 4 and c - mu = dx / 2 + dy, divided by dy^2.
double threePlaneBleeding(double t) { return t * t / (2 * t * t + 4 * t + 4); }

}  // namespace lab05
