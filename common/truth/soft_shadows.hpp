/// @file soft_shadows.hpp
/// The truth for soft shadows (lab 07): the visible fraction of a spot light's disk, by casting
/// rays to a fixed stratified pattern of points on it, and the penumbra's width measured across a
/// straight shadow edge, against the width the parallel-planes theory predicts.
#pragma once
#include "common/truth/ground_truth.hpp"

#include <vector>

namespace wb {

/// The sample points of a light disk of diameter 1 centred at 0, in its own plane: `count` (a
/// square number, at least 1) stratified cells mapped onto the disk (Shirley's concentric map), each
/// jittered by a fixed hash of its index, so the pattern is the same in every run.
std::vector<glm::vec2> lightDiskPattern(int count);

/// The visible fraction of `light`'s disk (diameter `light.size`, facing `light.direction`) from each
/// pixel, starting from `exact` (exactVisibility() of the same frame): its NaN (background, outside
/// the cone) and 0 on surfaces facing away are kept, every other pixel gets the share of the
/// `samples` rays that reach the disk. A pixel whose surface sees part of the disk under its own
/// plane (within the light's angular radius of grazing) becomes NaN, not compared: there the truth
/// mixes the shadow with the shading's horizon, which no shadow map models, and N·L makes the
/// surface dark whatever the visibility. With `light.size` 0 it is `exact`. Uses every core.
FloatImage areaLightVisibility(const RayScene& rays, const Light& light, const FloatImage& exact,
                               const std::vector<glm::vec4>& positions, int samples);

/// One slab of a penumbra probe (Scene::penumbraProbe).
struct PenumbraSlab {
  double x = 0;                ///< the slab's centre, world x
  double distance = 0;         ///< receiver - blocker distance along the light's axis (at the edge)
  double theory = 0;           ///< 10-90% width the parallel-planes formula predicts for a disk light
  double width = -1;           ///< 10-90% width of the rendered visibility across the edge (-1: none found)
  double referenceWidth = -1;  ///< the same, of the area-light reference
};

/// The 10-90% width of a disk light's penumbra, as a fraction of its full width w_light·(zR-zB)/zB:
/// the distance between the chords that leave 10% and 90% of the disk's area on one side (0.687).
double diskTenNinetyFraction();

/// Measures the probe's slabs: each slab's ground pixels are binned by z, the bins' mean visibility
/// forms a profile across the edge, and its 0.9 and 0.1 crossings (around the first 0.5 crossing
/// from the lit side) give the width. The distance comes from a ray cast from the edge to the light.
std::vector<PenumbraSlab> measurePenumbra(const PenumbraProbe& probe, const FloatImage& rendered,
                                          const FloatImage& reference, const std::vector<glm::vec4>& positions,
                                          const RayScene& rays, const Light& light, float groundY);

}  // namespace wb
