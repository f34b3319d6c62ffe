// Grading-time variations: the same seed turns a scene the same way every time, by a little (lights
// 1 to 3 degrees, cameras up to 3 degrees), and another seed turns it another way.
#include "common/base/variant.hpp"
#include "common/scene/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace {
wb::Scene canonical() {
  return wb::Scene::load(std::filesystem::path(wb::variant::kSourceDir) / "scenes/depth_map.json");
}
float degreesBetween(glm::vec3 a, glm::vec3 b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}
}  // namespace

TEST(VaryScene, ASeedTurnsLightsAndCamerasALittleAndTheSameWayEachTime) {
  const wb::Scene base = canonical();
  wb::Scene a = canonical(), b = canonical(), c = canonical();
  wb::varyScene(a, 7);
  wb::varyScene(b, 7);
  wb::varyScene(c, 8);
  ASSERT_EQ(a.lights.size(), base.lights.size());
  for (size_t i = 0; i < base.lights.size(); ++i) {
    const float turned = degreesBetween(base.lights[i].direction, a.lights[i].direction);
    EXPECT_GE(turned, 0.99f) << "light " << i;
    EXPECT_LE(turned, 3.01f) << "light " << i;
    EXPECT_EQ(a.lights[i].direction, b.lights[i].direction) << "the same seed, the same turn";
    EXPECT_NE(a.lights[i].direction, c.lights[i].direction) << "another seed, another turn";
  }
  for (size_t i = 0; i < base.cameras.size(); ++i) {
    EXPECT_LE(std::abs(a.cameras[i].yaw - base.cameras[i].yaw), 3.0f);
    EXPECT_LE(std::abs(a.cameras[i].pitch - base.cameras[i].pitch), 3.0f);
    EXPECT_EQ(a.cameras[i].yaw, b.cameras[i].yaw);
  }
}
