/// @file exercise.hpp
/// Lab 08 C++ exercises. The signatures are fixed: the app, the tests and the grader call them.
#pragma once
#include "common/scene/scene.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace lab08 {

/// EXERCISE 08.1: the view-projection of cube face `face` of a point light at `light`. Faces are in
/// GL's order 0..5 = +X, −X, +Y, −Y, +Z, −Z. Each face is a square 90° perspective with the given
/// near and far planes, looking from the light along its axis, with GL's up vector for that face:
/// −Y for ±X and ±Z, +Z for +Y, −Z for −Y (so that texture(samplerCube, direction) finds what the
/// face drew).
glm::mat4 cubeFaceViewProj(int face, const glm::vec3& light, float nearPlane, float farPlane);

/// EXERCISE 08.H1 (a bug hunt: working code with a real bug in it; README.md): the faces' near and
/// far planes, (near, far), for a light at `light` among `objects`.
glm::vec2 cubeNearFar(const std::vector<wb::SceneObject>& objects, const glm::vec3& light);

}  // namespace lab08
