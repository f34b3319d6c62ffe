/// @file exercise.hpp
/// Lab 05 C++ exercise. The signature is fixed.
#pragma once
#include <glm/vec2.hpp>

namespace lab05 {

/// EXERCISE 05.4: the worst light bleeding of three planes. Occluders at depths a < b share the
/// filter over a receiver at depth c > b that neither lets through: a fraction `mix` of the
/// filter's taps sees a, the rest b. With t = (b − a) / (c − b) > 0, return (mix, light): the mix
/// that lets the most light through Chebyshev's bound (no minimum variance, no reduction), and that
/// light. At mix ½ the light is t² / (2t² + 4t + 4); the worst is higher, and not at ½.
glm::dvec2 worstThreePlaneBleeding(double t);

}  // namespace lab05
