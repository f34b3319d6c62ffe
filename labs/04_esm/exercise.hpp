/// @file exercise.hpp
/// Lab 04 C++ exercise. The signature is fixed.
#pragma once

namespace lab04 {

/// EXERCISE 04.4: the largest exponent c for which exp(c · z), z in [0, 1], still fits in a format
/// whose largest finite value is `formatMax` (FLT_MAX for 32-bit floats, 65504 for 16-bit ones).
double esmMaxExponent(double formatMax);

}  // namespace lab04
