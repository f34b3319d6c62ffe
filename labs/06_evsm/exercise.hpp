/// @file exercise.hpp
/// Lab 06 C++ exercise. The signature is fixed.
#pragma once

namespace lab06 {

/// EXERCISE 06.2: the largest exponent c for which the second moment exp(c z)², z in [0, 1], still
/// fits in a format whose largest finite value is `formatMax`.
double evsmMaxExponent(double formatMax);

}  // namespace lab06
