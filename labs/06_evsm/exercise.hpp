/// @file exercise.hpp
/// Lab 06 C++ exercise. The signature is fixed.
#pragma once
#include <glm/glm.hpp>

namespace lab06 {

/// EXERCISE 06.2: the largest exponent c for which the second moment exp(c z)², z in [0, 1], still
/// fits in a format whose largest finite value is `formatMax`.
double evsmMaxExponent(double formatMax);

/// EXERCISE 06.H1 (a bug hunt: working code with a real bug in it; README.md): the exponents the map
/// is written with, (c+, c-): as set, or each brought under `bound` (06.2's, for the map's format;
/// `fp16` when that format is RGBA16F) where one is above it.
glm::vec2 usableExponents(float cPos, float cNeg, double bound, bool fp16);

}  // namespace lab06
