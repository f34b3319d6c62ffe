// Lab 09 C++ exercises: reference solution.
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glad/gl.h>

#include <map>
#include <utility>

namespace lab09 {

// EXERCISE 09.1
std::vector<uint32_t> buildAdjacency(const std::vector<uint32_t>& triangles) {
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> third;  // directed edge -> the third corner
  for (size_t k = 0; k + 2 < triangles.size(); k += 3)
    for (size_t e = 0; e < 3; ++e) third[{triangles[k + e], triangles[k + (e + 1) % 3]}] = triangles[k + (e + 2) % 3];
  std::vector<uint32_t> out;
  out.reserve(triangles.size() * 2);
  for (size_t k = 0; k + 2 < triangles.size(); k += 3)
    for (size_t e = 0; e < 3; ++e) {
      const uint32_t a = triangles[k + e], b = triangles[k + (e + 1) % 3];
      const auto across = third.find({b, a});
      out.push_back(a);
      out.push_back(across != third.end() ? across->second : triangles[k + (e + 2) % 3]);
    }
  return out;
}

// EXERCISE 09.4
StencilSetup zPassSetup() {
  StencilSetup s;
  s.front = {GL_KEEP, GL_KEEP, GL_INCR_WRAP};
  s.back = {GL_KEEP, GL_KEEP, GL_DECR_WRAP};
  s.caps = false;
  return s;
}

// EXERCISE 09.5
StencilSetup zFailSetup() {
  StencilSetup s;
  s.front = {GL_KEEP, GL_DECR_WRAP, GL_KEEP};
  s.back = {GL_KEEP, GL_INCR_WRAP, GL_KEEP};
  s.caps = true;
  return s;
}

// EXERCISE 09.6
bool nearPlaneMayBeShadowed(const std::array<glm::vec3, 4>& nearQuad, const glm::vec4& light, const glm::vec3& boxMin,
                            const glm::vec3& boxMax) {
  const glm::vec3 l(light);
  const bool point = light.w != 0;
  glm::vec3 centre = (nearQuad[0] + nearQuad[1] + nearQuad[2] + nearQuad[3]) * 0.25f;
  const glm::vec3 inside = point ? (centre * 4.0f + l) / 5.0f : centre + glm::normalize(l);
  std::vector<std::pair<glm::vec3, glm::vec3>> planes;  // (point, normal pointing out of the region)
  planes.emplace_back(centre, glm::cross(nearQuad[1] - nearQuad[0], nearQuad[2] - nearQuad[0]));
  for (int e = 0; e < 4; ++e) {
    const glm::vec3 a = nearQuad[size_t(e)], b = nearQuad[size_t((e + 1) % 4)];
    planes.emplace_back(a, glm::cross(b - a, point ? l - a : l));
  }
  for (auto& [p, n] : planes) {
    if (glm::dot(n, n) < 1e-12f) continue;  // the light in the plane: no plane to cull by
    if (glm::dot(n, inside - p) > 0) n = -n;
    bool allOutside = true;
    for (int c = 0; c < 8 && allOutside; ++c) {
      const glm::vec3 corner(c & 1 ? boxMax.x : boxMin.x, c & 2 ? boxMax.y : boxMin.y, c & 4 ? boxMax.z : boxMin.z);
      allOutside = glm::dot(n, corner - p) > 0;
    }
    if (allOutside) return false;
  }
  return true;
}

}  // namespace lab09
