/// @file camera.hpp
/// An orbit camera with named bookmarks (from the scene file, keys 1–9).
#pragma once
#include <glm/glm.hpp>

#include <string>

namespace wb {

/// A saved viewpoint: the orbit camera's parameters under a name.
struct CameraBookmark {
  std::string name = "default";  ///< shown in the UI
  glm::vec3 target{0, 0.5f, 0};  ///< the point the camera orbits
  float distance = 10;           ///< distance from the target
  float yaw = 30;                ///< degrees around +y, 0 looks down −z
  float pitch = 25;              ///< degrees above the horizon
  float fov = 45;                ///< vertical field of view in degrees
};

/// Orbits a target point; mouse drags change yaw/pitch, the wheel changes distance.
struct OrbitCamera {
  CameraBookmark pose;      ///< the current parameters
  float nearPlane = 0.1f;   ///< near clip distance
  float farPlane = 200.0f;  ///< far clip distance

  /// The eye position in world space.
  glm::vec3 eye() const;
  /// World → view matrix.
  glm::mat4 view() const;
  /// View → clip matrix for the given aspect ratio (width / height).
  glm::mat4 projection(float aspect) const;
  /// Rotates by a mouse movement in pixels.
  void orbit(float dxPixels, float dyPixels);
  /// Moves closer (positive steps) or further (negative steps).
  void zoom(float steps);
};

}  // namespace wb
