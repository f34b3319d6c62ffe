/// @file ground_truth.hpp
/// Exact light visibility, by casting rays against the scene's triangles (RayScene: the same
/// triangles the labs rasterise, alpha-tested leaves included), and the artifact metrics every technique is
/// measured with: acne (lit surfaces drawn shadowed) and light leaking (shadowed surfaces drawn lit).
#pragma once
#include "common/platform/image.hpp"
#include "common/scene/scene.hpp"
#include "common/truth/ray_scene.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace wb {

/// Exact visibility per pixel: 1 lit, 0 shadowed, NaN where nothing is measured (background,
/// outside a spot light's cone). `positions` holds world xyz and w = +1 for a surface facing the
/// light, −1 for one facing away (always shadowed), 0 for background, rows bottom to top.
FloatImage exactVisibility(const RayScene& rays, const Light& light, int width, int height,
                           const std::vector<glm::vec4>& positions);

/// 1 for each truly shadowed light-facing pixel beside a lit one (a 4-neighbour): the exact shadow's
/// outline, one pixel wide, as VisibilityMetrics::outlinePixels counts it.
std::vector<uint8_t> outlineMask(const FloatImage& exact, const std::vector<glm::vec4>& positions);

/// How a rendered visibility buffer compares with the exact one.
struct VisibilityMetrics {
  long litPixels = 0;        ///< light-facing pixels the light really reaches
  long acnePixels = 0;       ///< of those, drawn shadowed (visibility < 0.5)
  long shadowedPixels = 0;   ///< light-facing pixels in a cast shadow
  long leakPixels = 0;       ///< of those, drawn lit (visibility >= 0.5)
  double shadowLight = 0;    ///< sum of the drawn visibility over those: partial light counts too
  long rimPixels = 0;        ///< light-facing pixels within kRimPixels of an edge of the exact shadow
  long wrongOutsideRim = 0;  ///< acne and leak pixels farther than that from every edge
  /// Truly shadowed light-facing pixels beside a lit one: the exact shadow's outline, one pixel wide.
  /// An exact technique may flip only pixels whose centre lies within rounding of an edge, and a map
  /// finer than a pixel moves an edge by less than one: either way the drawn area may differ from the
  /// exact one by at most this many pixels, whatever the rasterizer.
  long outlinePixels = 0;
  /// Acne rate: the share of lit light-facing pixels drawn shadowed.
  double acneRate() const { return litPixels ? double(acnePixels) / litPixels : 0; }
  /// Light leak: the share of truly shadowed pixels drawn lit.
  double leakRate() const { return shadowedPixels ? double(leakPixels) / shadowedPixels : 0; }
  /// Bleeding: the mean drawn visibility over truly shadowed pixels (0 for a perfect shadow), which
  /// also counts the faint light that stays below the leak threshold.
  double meanShadowLight() const { return shadowedPixels ? shadowLight / double(shadowedPixels) : 0; }
  /// The drawn shadow's area over the exact one (1 = the same number of light-facing pixels drawn
  /// shadowed as are truly shadowed): below 1 the shadow shrank, above 1 it grew.
  double areaRatio() const {
    return shadowedPixels ? double(acnePixels + shadowedPixels - leakPixels) / double(shadowedPixels) : 1;
  }
  /// Acne and leaks away from the exact shadow's edges: their share of the light-facing pixels that
  /// are not on the rim, where a map's texels may fall either way.
  double wrongOutsideRimRate() const {
    const long outside = litPixels + shadowedPixels - rimPixels;
    return outside > 0 ? double(wrongOutsideRim) / double(outside) : 0;
  }
};

/// The rim of an exact shadow's edges, in pixels each side: where a pixel and a neighbour disagree on
/// lit or shadowed (a cast shadow's outline, a terminator, an object's outline over a shadow).
constexpr int kRimPixels = 2;

/// Compares `rendered` with `exact` on every pixel where `exact` is not NaN.
VisibilityMetrics compareVisibility(const FloatImage& rendered, const FloatImage& exact,
                                    const std::vector<glm::vec4>& positions);

/// How a rendered visibility differs from a reference rendering of the same frame (PCF over the same
/// footprint, see PcfReference) on the pixels the reference covers (value >= 0).
struct ReferenceDifference {
  long pixels = 0;    ///< light-facing pixels compared
  long lighter = 0;   ///< of those, drawn lighter than the reference by more than 0.1 (bleeding)
  long darker = 0;    ///< of those, drawn darker than the reference by more than 0.1
  double absSum = 0;  ///< the sum of |rendered - reference|
  /// The mean absolute difference.
  double meanAbs() const { return pixels ? absSum / double(pixels) : 0; }
  /// The share of pixels drawn lighter than the reference by more than 0.1.
  double lighterRate() const { return pixels ? double(lighter) / double(pixels) : 0; }
  /// The share of pixels drawn darker than the reference by more than 0.1.
  double darkerRate() const { return pixels ? double(darker) / double(pixels) : 0; }
};

/// Compares `rendered` with `reference` (same size, `width` pixels a row) in the columns [x0, x1).
ReferenceDifference compareWithReference(const FloatImage& rendered, const std::vector<float>& reference, int x0,
                                         int x1);

/// Ray-traced shadows as a render mode: a ray through the centre of every pixel of the camera whose
/// inverse view-projection is `invViewProj` (rows bottom to top) to the first surface, then one ray
/// from there to `light`: 1 lit, 0 shadowed (a closed caster's back faces shadow themselves), NaN
/// where the first ray meets nothing. On `threads` threads (0: every core).
FloatImage rayTracedVisibility(const RayScene& rays, const Light& light, const glm::mat4& invViewProj, int width,
                               int height, int threads);

/// A point light's frame split by where its cube map is read: the pixels whose direction from the
/// light lies within `degrees` of a boundary between two faces (the seams), and the rest. Each half
/// holds |rendered − exact| over its light-facing pixels (exact not NaN), as a ReferenceDifference.
struct SeamError {
  ReferenceDifference seam;  ///< within `degrees` of a face boundary
  ReferenceDifference rest;  ///< everywhere else
};
/// The angle in degrees between direction `d` and the nearest boundary between two cube faces (the
/// plane where its two largest |components| are equal): 0 on a seam, 45 at a face's centre.
double degreesFromCubeSeam(const glm::vec3& d);
/// The share of a point light's filtered lookups that see the light, with rays instead of a map:
/// for each pixel (positions, w > 0 facing the light) and offset o, one test of whether the light
/// reaches |d| − bias along d + o, where d = p − light; NaN for the background, 0 facing away.
/// `offsets` empty: one test along d (hard shadows with a bias).
FloatImage filteredPointVisibility(const RayScene& rays, const glm::vec3& light, int width, int height,
                                   const std::vector<glm::vec4>& positions, const std::vector<glm::vec3>& offsets,
                                   float bias);
/// Splits the frame's difference from `exact` (for a cube map: filteredPointVisibility with the
/// lab's own offsets and bias) into seams and the rest for a point light at `light`.
SeamError cubeSeamError(const FloatImage& rendered, const FloatImage& exact, const std::vector<glm::vec4>& positions,
                        const glm::vec3& light, double degrees);

/// Peter-panning on the ground: the distance between a caster's contact line and where its shadow
/// starts, in shadow-map texels, for the worst caster resting on the ground. Every ground pixel (y within 1e-3 of
/// `groundY`) that is truly in a cast shadow is binned, per caster, by its horizontal distance to the
/// point that blocks its light (for a caster resting on the ground, its distance from the contact
/// line), in half-texel bins of at least 4 pixels; a caster's gap is the distance from its first
/// bin (where the camera first sees its shadow) to its first bin drawn mostly (more than half)
/// shadowed. It is 0 when nothing on the ground is in a cast shadow, and at most 32 texels.
double contactGapTexels(const FloatImage& rendered, const FloatImage& exact, const std::vector<glm::vec4>& positions,
                        const RayScene& rays, const Light& light, float groundY, float texelWorld);

/// An RGBA8 picture of the comparison: the scene's light-facing pixels in grey, acne in red, light
/// leaks in blue, the rest dark (rows bottom to top).
std::vector<uint8_t> artifactHeatmap(const FloatImage& rendered, const FloatImage& exact,
                                     const std::vector<glm::vec4>& positions);
/// The heatmap's marks (red acne, blue leaks) widened to 2x2 pixels over the grey beside them, so
/// that one pixel's mistake shows on a projector; `width` is the picture's width.
std::vector<uint8_t> widenMarks(const std::vector<uint8_t>& rgba, int width);

}  // namespace wb
