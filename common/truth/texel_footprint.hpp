/// @file texel_footprint.hpp
/// How far a shadow map may move a shadow's edge on screen, from the geometry alone: the size in
/// pixels of one map texel on the surface at each pixel of the exact shadow's outline.
#pragma once
#include "common/scene/light_view.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace wb {

/// A texel's footprint larger than this many pixels is counted as this many: a surface almost
/// edge-on to the light, where one texel spans the frame.
constexpr double kMaxTexelPixels = 64;

/// The size in pixels of one texel of `light`'s map on the surface at pixel (x, y) (`positions`: world
/// xyz, w > 0 for a surface facing the light, rows bottom to top, `width` a row): the longest a step
/// of one texel, in any direction, becomes on screen (1 / the smallest singular value of the
/// pixel → texel Jacobian, from the world positions of the pixel's nearer neighbours). The map is the
/// one the pixel can be drawn from: for cascades (one slice in `light.outlines` per matrix), the
/// slice's cascade or the next one (a blend band reaches into it), the coarser of the two; else any
/// map whose clip box holds the point, the coarsest. 0 where no map holds it or no map was drawn.
double texelPixels(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height, int x,
                   int y);

/// Texels per pixel at pixel (x, y), lab 11's measure: min(tx, ty), where tx and ty are how many texels
/// of the map a step of one pixel right and up moves (from the neighbours' world positions, through
/// the map's matrix, after its divide), in the map the pixel is drawn from: its slice's cascade, or
/// the first map whose clip box holds it. 0 where no map holds it.
double texelsPerPixel(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height, int x,
                      int y);

/// The median of texelsPerPixel over the light-facing pixels that a map holds; -1 where none does.
double medianTexelsPerPixel(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height);

/// The sum of texelPixels over the pixels where `outline` is 1: how many pixels the drawn shadow's
/// area may gain or lose when the map moves every edge by one texel.
double outlineTexelPixels(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height,
                          const std::vector<uint8_t>& outline);

}  // namespace wb
