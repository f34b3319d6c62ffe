// The truth suite's derived bound for shadow maps: one texel's size on screen, from the geometry.
#include "common/truth/texel_footprint.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace {

// A ground plane (y = 0) seen straight from above, `pixel` world units a pixel, 64 x 48 pixels.
constexpr int kW = 64, kH = 48;
std::vector<glm::vec4> ground(float pixel) {
  std::vector<glm::vec4> p(size_t(kW) * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) p[size_t(y) * kW + x] = glm::vec4(x * pixel, 0, y * pixel, 1);
  return p;
}

// A light straight above whose orthographic map covers `extent` world units across from `lo` on.
glm::mat4 mapAbove(float lo, float extent) {
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  return glm::ortho(lo, lo + extent, -lo - extent, -lo, 1.0f, 20.0f) * view;
}

// A cascade's slice of the view: a box from x = 0 to 9, y = -1 to 1, z from z0 to z1.
std::array<glm::vec3, 8> slice(float z0, float z1) {
  return {glm::vec3(0, -1, z0), glm::vec3(9, -1, z0), glm::vec3(9, 1, z0), glm::vec3(0, 1, z0),
          glm::vec3(0, -1, z1), glm::vec3(9, -1, z1), glm::vec3(9, 1, z1), glm::vec3(0, 1, z1)};
}

wb::LightView oneMap(float extent, int size) {
  wb::LightView v;
  v.viewProj = {mapAbove(-1, extent)}, v.target = GL_TEXTURE_2D, v.texture = 1, v.size = size;
  return v;
}

TEST(TexelFootprint, ATexelOnTheGroundIsItsWorldWidthOverAPixels) {
  // 100 world units over 1000 texels: 0.1 a texel; a pixel is 0.05: a texel spans 2 pixels.
  const auto pos = ground(0.05f);
  EXPECT_NEAR(wb::texelPixels(oneMap(100, 1000), pos, kW, kH, 10, 10), 2.0, 1e-3);
  // Twice the texels: one pixel each; at the frame's corner, from the one neighbour there is.
  EXPECT_NEAR(wb::texelPixels(oneMap(100, 2000), pos, kW, kH, kW - 1, kH - 1), 1.0, 1e-3);
}

TEST(TexelFootprint, NothingWhereNoMapHoldsThePointOrNoMapWasDrawn) {
  const auto pos = ground(1.0f);  // 64 world units across; the map's box reaches x = 9 only
  EXPECT_EQ(wb::texelPixels(oneMap(10, 100), pos, kW, kH, 40, 5), 0.0);
  wb::LightView none = oneMap(100, 1000);
  none.texture = 0;
  EXPECT_EQ(wb::texelPixels(none, pos, kW, kH, 5, 5), 0.0);
}

TEST(TexelFootprint, ASurfaceEdgeOnToTheLightIsCappedNotInfinite) {
  std::vector<glm::vec4> wall(size_t(kW) * kH);  // the plane x = 0, seen face on: the light grazes it
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) wall[size_t(y) * kW + x] = glm::vec4(0, y * 0.05f, x * 0.05f, 1);
  EXPECT_EQ(wb::texelPixels(oneMap(100, 1000), wall, kW, kH, 10, 10), wb::kMaxTexelPixels);
}

TEST(TexelFootprint, ACascadesPixelCountsTheCoarserOfItsSliceAndTheNext) {
  // Two cascades: a fine map (1 pixel a texel) and a coarse one (4); slice 0 is z in [0, 1], slice
  // 1 is z in [1, 3], each a box standing on the ground across the whole frame.
  wb::LightView v = oneMap(100, 2000);
  v.viewProj.push_back(mapAbove(-1, 100)), v.size = 2000, v.target = GL_TEXTURE_2D_ARRAY;
  v.viewProj[1] = glm::scale(glm::mat4(1), glm::vec3(0.25f, 0.25f, 1)) * v.viewProj[1];  // 4x wider texels
  v.outlines = {slice(0, 1), slice(1, 3)};
  const auto pos = ground(0.05f);                                   // rows 0..20 lie in slice 0, 21..47 in slice 1
  EXPECT_NEAR(wb::texelPixels(v, pos, kW, kH, 10, 10), 4.0, 1e-2);  // a blend band may reach cascade 1
  EXPECT_NEAR(wb::texelPixels(v, pos, kW, kH, 10, 40), 4.0, 1e-2);
  v.viewProj[1] = v.viewProj[0];  // both fine: one pixel
  EXPECT_NEAR(wb::texelPixels(v, pos, kW, kH, 10, 10), 1.0, 1e-3);
  v.outlines = {slice(5, 6), slice(6, 7)};  // beyond every slice: no cascade draws it
  EXPECT_EQ(wb::texelPixels(v, pos, kW, kH, 10, 10), 0.0);
}

TEST(TexelFootprint, TheOutlineSumAddsItsPixelsOnly) {
  const auto pos = ground(0.05f);
  std::vector<uint8_t> outline(size_t(kW) * kH);
  outline[size_t(5) * kW + 5] = outline[size_t(6) * kW + 5] = outline[size_t(7) * kW + 5] = 1;
  EXPECT_NEAR(wb::outlineTexelPixels(oneMap(100, 1000), pos, kW, kH, outline), 6.0, 1e-2);
}

// Texels per pixel, lab 11's measure, for the showcase's table: the shorter of a pixel step's moves
// through the map the pixel is drawn from (its own cascade, not the coarser of two).
TEST(TexelFootprint, TexelsPerPixelIsTheShorterStepInThePixelsOwnMap) {
  const auto pos = ground(0.05f);  // 0.1 world units a texel, 0.05 a pixel: half a texel a pixel
  EXPECT_NEAR(wb::texelsPerPixel(oneMap(100, 1000), pos, kW, kH, 10, 10), 0.5, 1e-3);
  wb::LightView stretched = oneMap(100, 1000);  // x's texels 4x wider: 0.125 texels a pixel that way
  stretched.viewProj[0] = glm::scale(glm::mat4(1), glm::vec3(0.25f, 1, 1)) * stretched.viewProj[0];
  EXPECT_NEAR(wb::texelsPerPixel(stretched, pos, kW, kH, 10, 10), 0.125, 1e-3);
  EXPECT_NEAR(wb::medianTexelsPerPixel(oneMap(100, 1000), pos, kW, kH), 0.5, 1e-3);
  EXPECT_EQ(wb::medianTexelsPerPixel(oneMap(10, 100), ground(1.0f), kW, kH) > 0, true);  // (part of the frame)
  wb::LightView none = oneMap(100, 1000);
  none.texture = 0;
  EXPECT_EQ(wb::medianTexelsPerPixel(none, pos, kW, kH), -1.0);
}

TEST(TexelFootprint, TexelsPerPixelReadsTheSlicesOwnCascade) {
  wb::LightView v = oneMap(100, 2000);  // cascade 0: one texel a pixel; cascade 1: a quarter
  v.viewProj.push_back(glm::scale(glm::mat4(1), glm::vec3(0.25f, 0.25f, 1)) * mapAbove(-1, 100));
  v.target = GL_TEXTURE_2D_ARRAY;
  v.outlines = {slice(0, 1), slice(1, 3)};
  const auto pos = ground(0.05f);  // rows 0..20 lie in slice 0, 21..47 in slice 1
  EXPECT_NEAR(wb::texelsPerPixel(v, pos, kW, kH, 10, 10), 1.0, 1e-3);
  EXPECT_NEAR(wb::texelsPerPixel(v, pos, kW, kH, 10, 40), 0.25, 1e-3);
}

}  // namespace
