// Lab 05 C++ exercise: reference solution.
#include "exercise.hpp"

#include <cmath>

namespace lab05 {

// EXERCISE 05.4
// With k = 1/t the bound is m(1-m) / (m(1-m) + (k + m)^2); it is largest where
// (k + m)^2 / (m(1-m)) is smallest: 2/(k+m) = (1-2m)/(m(1-m)) gives m = k / (1 + 2k) = 1 / (t + 2),
// and there the light is 1 / (1 + 4(t+1)/t^2) = t^2 / (t + 2)^2.
glm::dvec2 worstThreePlaneBleeding(double t) {
  const double light = t / (t + 2);
  return {1 / (t + 2), light * light};
}

}  // namespace lab05
