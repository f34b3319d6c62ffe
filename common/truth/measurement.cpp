#include "common/truth/measurement.hpp"

#include "common/base/error.hpp"
#include "common/base/strf.hpp"
#include "common/shadows/shadow_map.hpp"
#include "common/truth/texel_footprint.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace wb {
namespace {

std::string footprint(const LightView& s) {
  return std::to_string(s.kernel) + "x" + std::to_string(s.kernel) + (s.kernel > 1 && s.gaussian ? " Gaussian" : "");
}

// The contact gap and the PCF reference need texels of one size: one orthographic 2D map.
std::string whyNotOrthographic2D(const LightView& v) {
  if (!v.hasMap()) return "no shadow map";
  if (!v.isSingle2D()) return "defined for one 2D map; this light has a " + v.shapeName();
  if (v.light.type != LightType::Directional) return "directional lights only";
  return "";
}

}  // namespace

nlohmann::json MeasureResult::toJson() const {
  if (!ownMeasure.empty())  // a frame that holds a lab's own measure: no shadow numbers at all
    return {{"own_measure", ownMeasure}, {"todo_pixels", todoPixels}, {"notes", notes}};
  nlohmann::json j = {{"acne_percent", 100 * metrics.acneRate()},
                      {"leak_percent", 100 * metrics.leakRate()},
                      {"shadow_light_percent", 100 * metrics.meanShadowLight()},
                      {"lit_pixels", metrics.litPixels},
                      {"shadowed_pixels", metrics.shadowedPixels},
                      {"shadow_area_ratio", metrics.areaRatio()},
                      {"rim_pixels", metrics.rimPixels},
                      {"outline_pixels", metrics.outlinePixels},
                      {"outline_texel_pixels", outlineTexelPixels},
                      {"texels_per_pixel_median", nullptr},
                      {"wrong_outside_rim_percent", 100 * metrics.wrongOutsideRimRate()},
                      {"contact_gap_texels", nullptr},
                      {"pcf_diff_percent", nullptr},
                      {"pcf_lighter_percent", nullptr},
                      {"todo_pixels", todoPixels},
                      {"notes", notes}};
  if (gapTexels >= 0) j["contact_gap_texels"] = gapTexels;
  if (texelsPerPixel >= 0) j["texels_per_pixel_median"] = texelsPerPixel;
  if (reference.pixels > 0) {
    j["pcf_diff_percent"] = 100 * reference.meanAbs();
    j["pcf_lighter_percent"] = 100 * reference.lighterRate();
  }
  j["area_mean_abs_percent"] = nullptr, j["area_off_percent"] = nullptr;
  if (area.pixels > 0) {
    j["area_mean_abs_percent"] = 100 * area.meanAbs();
    j["area_off_percent"] = 100 * (area.lighterRate() + area.darkerRate());
  }
  j["seam_error_percent"] = nullptr, j["rest_error_percent"] = nullptr, j["seam_pixels"] = nullptr;
  if (seams.seam.pixels + seams.rest.pixels > 0) {
    j["seam_error_percent"] = 100 * seams.seam.meanAbs(), j["rest_error_percent"] = 100 * seams.rest.meanAbs();
    j["seam_pixels"] = seams.seam.pixels;
  }
  j["penumbra"] = nlohmann::json::array();
  for (const auto& p : penumbra)
    j["penumbra"].push_back({{"x", p.x},
                             {"distance", p.distance},
                             {"theory", p.theory},
                             {"width", p.width},
                             {"reference_width", p.referenceWidth}});
  return j;
}

const std::vector<float>* Measurement::pcfReference(const MeasureInput& in, int side) {
  // In split screen the left side's reference needs the map it was drawn with, so its size must match.
  const LightView& s = in.split() ? in.sides[side] : in.light;
  if (!whyNotOrthographic2D(in.light).empty() || s.size != in.light.size) return nullptr;
  if (reference_[side].empty()) {
    const glm::ivec2 size = in.target.size();
    reference_[side] = pcf_.render(in.target.attachment(2), size.x, size.y, in.light.texture, in.light.size,
                                   in.light.viewProj[0], s.kernel, s.gaussian);
  }
  return &reference_[side];
}

std::string Measurement::halves(const MeasureInput& in, const FloatImage& rendered, const FloatImage& exact,
                                MeasureResult& out, const std::vector<glm::vec4>& positions) {
  const int w = rendered.width, h = rendered.height;
  std::string text;
  for (int side = 0; side < 2; ++side) {
    const int x0 = side * (w - w / 2), x1 = x0 + w / 2;
    FloatImage r{w / 2, h, {}}, e{w / 2, h, {}};
    std::vector<glm::vec4> pos;
    for (int y = 0; y < h; ++y)
      for (int x = x0; x < x1; ++x) {
        const size_t k = size_t(y) * size_t(w) + size_t(x);
        r.pixels.push_back(rendered.pixels[k]), e.pixels.push_back(exact.pixels[k]), pos.push_back(positions[k]);
      }
    MeasureResult::Half& half = out.halves.emplace_back();
    half.setting = in.halves[size_t(side)];
    const VisibilityMetrics& m = half.metrics = compareVisibility(r, e, pos);
    text += strf("\n%s %s: acne %.2f%%, leak %.2f%%, light in shadows %.2f%%", side ? "right" : "left ",
                 half.setting.c_str(), 100 * m.acneRate(), 100 * m.leakRate(), 100 * m.meanShadowLight());
    if (const auto* ref = pcfReference(in, side)) {
      const ReferenceDifference& d = half.reference = compareWithReference(rendered, *ref, x0, x1);
      text += strf("\n       against PCF %s: |difference| %.2f%%, lighter %.2f%%", footprint(in.sides[side]).c_str(),
                   100 * d.meanAbs(), 100 * d.lighterRate());
    } else {
      text += "\n       against PCF: n/a";
    }
  }
  return text;
}

// Soft shadows: the frame against the visible fraction of the light's disk, and the penumbra probe.
std::string Measurement::areaText(const MeasureInput& in, const Light& light, const FloatImage& rendered,
                                  const FloatImage& exact, const std::vector<glm::vec4>& positions, MeasureResult& r) {
  if (light.size <= 0 || light.type != LightType::Spot) return "";
  const auto t0 = std::chrono::steady_clock::now();
  const FloatImage area = areaLightVisibility(*rays_, light, exact, positions, in.lightSamples);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  double rays = 0;  // to the disk, one per sample per light-facing pixel in the cone
  for (size_t i = 0; i < area.pixels.size(); ++i) rays += !std::isnan(area.pixels[i]) && positions[i].w > 0;
  rays *= in.lightSamples;
  // Every light-facing pixel in the light's reach is compared, but the sums are divided by the pixels
  // the area light leaves in some shadow (below 1): a fixed count for the scene, whatever the
  // technique. (Dividing by the pixels where *either* is below 1 rewarded a technique for darkening
  // lit ground a little: its faint haze added pixels with small errors to the count.)
  std::vector<float> ref(area.pixels);
  for (size_t i = 0; i < ref.size(); ++i)
    if (std::isnan(ref[i]) || positions[i].w <= 0) ref[i] = -1;
  std::string text;
  for (int side = 0; side < (in.split() ? 2 : 1); ++side) {
    const int w = rendered.width, x0 = in.split() ? side * (w - w / 2) : 0, x1 = in.split() ? x0 + w / 2 : w;
    ReferenceDifference d = compareWithReference(rendered, ref, x0, x1);
    d.pixels = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
      const int x = int(i % size_t(w));
      d.pixels += x >= x0 && x < x1 && ref[i] >= 0 && ref[i] < 0.999f;
    }
    if (!in.split() || side == 1) r.area = d;
    text += strf(
        "\nagainst the area light (%d rays a pixel, %.0f ms, %.1f M rays/s)%s, per pixel it leaves in some "
        "shadow: |difference| %.2f%%, off by > 0.1 on %.2f%%",
        in.lightSamples, ms, rays / std::max(ms, 1e-3) / 1e3,
        !in.split() ? "" : strf(", %s %s", side ? "right" : "left", in.halves[size_t(side)].c_str()).c_str(),
        100 * d.meanAbs(), 100 * (d.lighterRate() + d.darkerRate()));
  }
  r.penumbra = measurePenumbra(in.scene.penumbraProbe, rendered, area, positions, *rays_, light, in.scene.boundsMin.y);
  if (!r.penumbra.empty()) text += "\npenumbra, 10-90% width (world units) against receiver-blocker distance:";
  if (!r.penumbra.empty()) text += "\n      x  distance    theory  rendered  reference";
  for (const auto& p : r.penumbra)
    text += strf("\n  %5.2f  %8.3f  %8.3f  %8.3f  %9.3f", p.x, p.distance, p.theory, p.width, p.referenceWidth);
  return text;
}

namespace {

// The first lines of a measurement: acne, leak, gap, light in shadows, area and time, after a warning
// when the frame shows a stub's pattern.
std::string headline(const MeasureResult& r, int pixels) {
  const VisibilityMetrics& m = r.metrics;
  const std::string todo =
      r.todoPixels <= 0
          ? ""
          : strf(
                "NOT MEASURED: %ld of %d pixels show the not-implemented pattern (an exercise this frame needs "
                "is unfinished); the numbers below count them as shadowed and say nothing yet\n",
                r.todoPixels, pixels);
  return todo + strf(
                    "acne rate %.2f%% (%ld of %ld lit pixels drawn shadowed)\nlight leak %.2f%% (%ld of %ld shadowed "
                    "pixels drawn lit)\ncontact gap %s\nlight in shadows %.2f%% (mean visibility where the light "
                    "is blocked)\nshadow area %.1f%% of the exact one; acne + leak %.2f%% beyond %d px of its edges\n"
                    "(measured in %.0f ms, the ray casting included)",
                    100 * m.acneRate(), m.acnePixels, m.litPixels, 100 * m.leakRate(), m.leakPixels, m.shadowedPixels,
                    r.gapTexels < 0 ? "n/a" : strf("%.1f texels", r.gapTexels).c_str(), 100 * m.meanShadowLight(),
                    100 * m.areaRatio(), 100 * m.wrongOutsideRimRate(), kRimPixels, r.milliseconds);
}

}  // namespace

std::string Measurement::pcfText(const MeasureInput& in, const FloatImage& rendered, const std::string& why,
                                 MeasureResult& r) {
  const auto* ref = pcfReference(in, in.split() ? 1 : 0);
  if (!ref) return "against PCF: n/a (" + (why.empty() ? std::string("map sizes differ") : why) + ")";
  r.reference = compareWithReference(rendered, *ref, 0, rendered.width);
  return strf(
      "against PCF over the same footprint (%s)%s: |difference| %.2f%%,\n  lighter by > 0.1 on "
      "%.2f%%, darker on %.2f%% of light-facing pixels",
      footprint(in.split() ? in.sides[1] : in.light).c_str(), in.split() ? ", whole frame" : "",
      100 * r.reference.meanAbs(), 100 * r.reference.lighterRate(), 100 * r.reference.darkerRate());
}

std::string Measurement::seamsText(const MeasureInput& in, const Light& light, const FloatImage& rendered,
                                   const std::vector<glm::vec4>& positions, MeasureResult& r) {
  if (in.light.target != GL_TEXTURE_CUBE_MAP) return "";
  // The same lookups with rays: what differs is the map's doing, not the filter's.
  const FloatImage same = filteredPointVisibility(*rays_, light.position, rendered.width, rendered.height, positions,
                                                  in.light.cubeOffsets, in.light.cubeBias);
  r.seams = cubeSeamError(rendered, same, positions, light.position, kSeamDegrees);
  return strf(
      "\nagainst the same %zu lookup%s with rays: |difference| %.2f%% within %.0f degrees of a cube "
      "face's edge (%ld pixels), %.2f%% elsewhere",
      std::max<size_t>(1, in.light.cubeOffsets.size()), in.light.cubeOffsets.size() > 1 ? "s" : "",
      100 * r.seams.seam.meanAbs(), kSeamDegrees, r.seams.seam.pixels, 100 * r.seams.rest.meanAbs());
}

MeasureResult Measurement::measure(const MeasureInput& in) {
  const auto t0 = std::chrono::steady_clock::now();
  const int w = in.target.size().x, h = in.target.size().y;
  const FloatImage rendered = in.target.readVisibility();
  if (rendered.width != w || rendered.height != h)
    throw UsageError("the visibility to measure is " + std::to_string(rendered.width) + "x" +
                     std::to_string(rendered.height) + " but the frame is " + std::to_string(w) + "x" +
                     std::to_string(h) + "; use the same --size");
  const std::vector<glm::vec4> positions = in.target.readPositions();
  if (!rays_ || raysScene_ != &in.scene || raysCutoff_ != in.alphaCutoff)
    rays_ = std::make_unique<RayScene>(in.scene, in.alphaCutoff), raysScene_ = &in.scene, raysCutoff_ = in.alphaCutoff;
  reference_[0].clear(), reference_[1].clear();
  const Light& light = in.light.hasMap() ? in.light.light : in.sceneLight;
  const FloatImage exact = exactVisibility(*rays_, light, w, h, positions);
  MeasureResult r;
  r.metrics = compareVisibility(rendered, exact, positions);
  r.outlineTexelPixels = outlineTexelPixels(in.light, positions, w, h, outlineMask(exact, positions));
  r.texelsPerPixel = medianTexelsPerPixel(in.light, positions, w, h);
  for (float v : rendered.pixels) r.todoPixels += isTodo(v);  // a stub's pattern
  const std::string why = whyNotOrthographic2D(in.light);
  if (why.empty())
    r.gapTexels = contactGapTexels(rendered, exact, positions, *rays_, light, in.scene.boundsMin.y,
                                   texelWorldSize(in.light.viewProj[0], in.light.size));
  else
    r.notes = "contact gap and PCF reference: n/a (" + why + ")";
  const std::string pcf = pcfText(in, rendered, why, r);
  const std::string split = in.split() ? halves(in, rendered, exact, r, positions) : "";
  const std::string seams = seamsText(in, light, rendered, positions, r);
  std::string area = areaText(in, light, rendered, exact, positions, r);
  if (!area.empty())
    area =
        "\n(acne and leak above: against a point light at the disk's centre; for a light with a size, the\n"
        "area light below is the truth)" +
        area;
  r.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  r.text = headline(r, w * h) + "\n" + pcf + seams + split + area;
  r.heatmap = artifactHeatmap(rendered, exact, positions);
  return r;
}

}  // namespace wb
