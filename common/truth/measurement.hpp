/// @file measurement.hpp
/// Measures a rendered frame against exact visibility (ray casting): acne, light leak, light in
/// shadows, the contact gap, and for filtered maps the difference from PCF over the same footprint.
/// In split screen each half is measured on its own. Measurements that are defined for one 2D
/// orthographic map only say so for other shapes instead of computing nonsense.
#pragma once
#include "common/platform/frame_target.hpp"
#include "common/scene/light_view.hpp"
#include "common/shadows/prefilter.hpp"
#include "common/truth/ground_truth.hpp"
#include "common/truth/soft_shadows.hpp"

#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <string>
#include <vector>

namespace wb {

/// What one measurement found.
struct MeasureResult {
  VisibilityMetrics metrics;           ///< acne, leak, light in shadows (whole frame)
  double gapTexels = -1;               ///< contact gap in texels, −1 when not defined for this light
  ReferenceDifference reference;       ///< against PCF (pixels = 0 when not defined)
  ReferenceDifference area;            ///< against the area-light reference (pixels = 0 for a point light)
  std::vector<PenumbraSlab> penumbra;  ///< the scene's penumbra probe, if it has one and the light a size
  SeamError seams;                     ///< a cube map's seams against the rest (pixels = 0 for other maps)
  std::string notes;                   ///< why a measurement was skipped, if one was
  std::string ownMeasure;              ///< a lab's own measure's numbers, for a frame that holds no visibility
  long todoPixels = 0;                 ///< pixels showing a stub's WB_TODO: the numbers mean nothing yet
  /// The sum, over the exact shadow's outline, of one map texel's size in pixels there
  /// (outlineTexelPixels): how far the map alone may move the drawn area (0 without a map).
  double outlineTexelPixels = 0;
  /// The median texels per pixel over the light-facing pixels a map holds (medianTexelsPerPixel; -1
  /// without a map).
  double texelsPerPixel = -1;
  /// One half of a split-screen frame, measured on its own.
  struct Half {
    std::string setting;            ///< "key=value" that half shows
    VisibilityMetrics metrics;      ///< acne, leak, light in shadows
    ReferenceDifference reference;  ///< against PCF (pixels = 0 when not defined)
  };
  std::vector<Half> halves;      ///< in split screen, left then right (empty otherwise)
  std::string text;              ///< the whole result for people
  std::vector<uint8_t> heatmap;  ///< RGBA8: acne red, leaks blue (rows bottom to top)
  double milliseconds = 0;       ///< time the measurement took
  /// The numbers as JSON (a frame with ownMeasure: own_measure alone): acne_percent, leak_percent,
  /// shadow_light_percent, shadow_area_ratio, wrong_outside_rim_percent (acne and leaks beyond kRimPixels of the exact
  /// edges), contact_gap_texels (null when not defined), pcf_diff_percent and pcf_lighter_percent (null when not
  /// defined), area_mean_abs_percent and area_off_percent (null for a point light; over the pixels where the frame or
  /// the area-light reference is below 1), penumbra (rows), seam_error_percent, rest_error_percent and seam_pixels
  /// (null unless the light has a cube map), texels_per_pixel_median (null without a map).
  nlohmann::json toJson() const;
};

/// The state one frame is measured in.
struct MeasureInput {
  const FrameTarget& target;  ///< the frame, with visibility and positions
  const Scene& scene;         ///< the scene the rays are cast against
  float alphaCutoff;          ///< the alpha test the renderer used
  const LightView& light;     ///< the light and map of the (right half of the) frame
  const Light& sceneLight;    ///< the light to use when the lab showed none
  /// In split screen, what the left and right halves show ("key=value", from the shell above);
  /// empty for one whole frame.
  std::vector<std::string> halves;
  const LightView* sides;  ///< in split screen: the left and right halves' lights (two)
  int lightSamples;        ///< rays per pixel of the area-light reference
  /// True in split screen (two halves named).
  bool split() const { return halves.size() == 2; }
};

/// How close to a cube face's boundary a pixel's direction must be to count as on a seam.
constexpr double kSeamDegrees = 2.0;

/// Measures frames; keeps the ray-cast scene and the PCF reference between calls.
class Measurement {
 public:
  /// Measures the frame in `in`.
  MeasureResult measure(const MeasureInput& in);

 private:
  const std::vector<float>* pcfReference(const MeasureInput& in, int side);
  std::string halves(const MeasureInput& in, const FloatImage& rendered, const FloatImage& exact, MeasureResult& out,
                     const std::vector<glm::vec4>& positions);
  std::string areaText(const MeasureInput& in, const Light& light, const FloatImage& rendered, const FloatImage& exact,
                       const std::vector<glm::vec4>& positions, MeasureResult& r);
  std::string pcfText(const MeasureInput& in, const FloatImage& rendered, const std::string& why, MeasureResult& r);
  std::string seamsText(const MeasureInput& in, const Light& light, const FloatImage& rendered,
                        const std::vector<glm::vec4>& positions, MeasureResult& r);
  std::unique_ptr<RayScene> rays_;
  const Scene* raysScene_ = nullptr;
  float raysCutoff_ = -1;
  PcfReference pcf_;
  std::vector<float> reference_[2];
};

}  // namespace wb
