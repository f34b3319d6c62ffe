/// @file ray_scene.hpp
/// The one ray caster of the workbook: the scene's triangles in world space, the same ones the labs
/// rasterise, in an Embree scene (libembree-dev: Embree 3 on Debian 12 and Ubuntu 22.04, Embree 4
/// on Ubuntu 24.04). Alpha-tested leaves let rays through where their texture is clear, through an
/// Embree filter function. Every query is safe to call from several threads at once.
#pragma once
#include "common/scene/scene.hpp"

#include <glm/glm.hpp>

#include <memory>

namespace wb {

/// The scene's triangles, ready for shadow rays and first hits.
class RayScene {
 public:
  /// Builds Embree's hierarchy; textured objects are alpha-tested with `alphaCutoff` (their texture
  /// is read with stb_image, as the renderer reads it). Throws wb::Error if Embree cannot start.
  RayScene(const Scene& scene, float alphaCutoff);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;
  /// True if a triangle blocks the ray origin + t·dir for tMin < t < tMax (`dir` of unit length).
  bool occluded(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const;
  /// True if scene object `object`'s lowest point lies within 1e-3 of height `y` (it rests there).
  bool restsOn(int object, float y) const;
  /// The smallest t in (tMin, tMax) where the ray meets a triangle, or tMax if it meets none;
  /// `object` (if given) receives the index of the scene object hit, or −1; `normal` (if given) the
  /// unit normal of the triangle hit, on either side, or 0.
  float firstHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax, int* object = nullptr,
                 glm::vec3* normal = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wb
