/// @file exercise.hpp
/// Lab 10 C++ exercises. The signatures are fixed: the app, the tests and the grader call them.
#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace lab10 {

/// How the view frustum is cut into slices.
enum class SplitScheme {
  Uniform = 0,      ///< C_i = n + (f − n) · i / N
  Logarithmic = 1,  ///< C_i = n · (f / n)^(i / N)
  Practical = 2     ///< C_i = λ · logarithmic + (1 − λ) · uniform
};

/// EXERCISE 10.1: the split distances C_0 .. C_N along the view direction (N + 1 values for N =
/// `cascades`; C_0 = nearPlane, C_N = farPlane), by `scheme`; `lambda` is used by Practical only.
std::vector<float> splitDistances(float nearPlane, float farPlane, int cascades, SplitScheme scheme, float lambda);

/// EXERCISE 10.2: the eight world-space corners of the slice of the camera's frustum between view
/// distances `d0` and `d1` (along the view direction, positive). `invView` takes camera space to
/// world space (the camera looks down −z); `fovY` is the full vertical field of view in radians.
/// Order: the d0 corners, then the d1 corners, each as (−x, −y), (+x, −y), (+x, +y), (−x, +y) in
/// camera space.
std::array<glm::vec3, 8> sliceCorners(const glm::mat4& invView, float fovY, float aspect, float d0, float d1);

/// EXERCISE 10.3: the cascade's light matrix, fit to its slice (the crop matrix): an orthographic
/// projection times `lightView` whose x and y map the corners' light-space bounds exactly onto
/// [−1, 1], and whose depth range holds the corners, extended towards the light by `casterReach`
/// (world units) so that casters outside the slice still reach the map.
glm::mat4 fitCascade(const glm::mat4& lightView, const std::array<glm::vec3, 8>& corners, float casterReach);

/// EXERCISE 10.4: the same, stabilised: fit the slice's bounding sphere (centre the corners' mean,
/// radius the largest distance to a corner, rounded up to a multiple of 1/16 world unit), so the
/// box's size never changes as the camera turns; then move the box so its origin lies on a whole
/// texel of a `mapSize` map, so the texel grid never moves as the camera slides. The box is the
/// sphere's: 2r wide and high around the (snapped) centre, and in depth from r + casterReach in
/// front of the centre (towards the light) to r behind it.
glm::mat4 stableCascade(const glm::mat4& lightView, const std::array<glm::vec3, 8>& corners, int mapSize,
                        float casterReach);

/// An object's bounds in world space: (the smallest x, y, z; the largest).
using Box = std::pair<glm::vec3, glm::vec3>;

/// EXERCISE 10.H2 (a bug hunt: working code with a real bug in it; README.md): per-cascade caster
/// culling (csm.cull=on). The indices of the `boxes` (every object's world bounds) to draw into one
/// cascade's map: `cascade` is its light matrix (10.3 or 10.4), `view` the camera's view matrix, and
/// [sliceNear, sliceFar] the view distances of the slice it covers (10.1).
std::vector<uint32_t> castersFor(const glm::mat4& cascade, const glm::mat4& view, float sliceNear, float sliceFar,
                                 const std::vector<Box>& boxes);

}  // namespace lab10
