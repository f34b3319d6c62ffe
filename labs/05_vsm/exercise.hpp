/// @file exercise.hpp
/// Lab 05 C++ exercise. The signature is fixed.
#pragma once

namespace lab05 {

/// EXERCISE 05.4: the light that VSM lets through onto a receiver at depth c, hidden behind two
/// occluders at depths a < b that each cover half of the filter, as a function of
/// t = (b − a) / (c − b).
double threePlaneBleeding(double t);

}  // namespace lab05
