#include "common/truth/ground_truth.hpp"

#include "common/base/error.hpp"
#include "common/base/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace wb {
namespace {

// The shadow ray from `p` to `light`: towards a point or spot light, up to its distance; against a
// directional light's direction, without end.
struct LightRay {
  glm::vec3 dir;
  float tMax;
};
LightRay rayToLight(const Light& light, const glm::vec3& p) {
  if (light.type == LightType::Directional) return {-light.direction, std::numeric_limits<float>::infinity()};
  const float d = glm::length(light.position - p);
  return {(light.position - p) / d, d};
}

// Adds one pixel, `rendered` against `reference`, to `d`.
void accumulate(ReferenceDifference& d, float rendered, float reference) {
  const double diff = double(std::clamp(rendered, 0.0f, 1.0f)) - double(reference);
  ++d.pixels, d.absSum += std::abs(diff), d.lighter += diff > 0.1, d.darker += diff < -0.1;
}

// 1 for every pixel within `radius` pixels (either way, diagonals included) of an edge of the exact
// shadow: a measured pixel (facing the light or away) whose 4-neighbour is measured and falls on
// the other side of 0.5.
std::vector<uint8_t> shadowRim(const FloatImage& exact, const std::vector<glm::vec4>& positions, int radius) {
  const int w = exact.width, h = exact.height;
  auto shadowed = [&](int x, int y) -> int {  // -1 where nothing is measured
    const size_t i = size_t(y) * size_t(w) + size_t(x);
    return std::isnan(exact.pixels[i]) || positions[i].w == 0 ? -1 : exact.pixels[i] < 0.5f;
  };
  std::vector<uint8_t> edge(exact.pixels.size()), rim(exact.pixels.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int s = shadowed(x, y), right = x + 1 < w ? shadowed(x + 1, y) : -1,
                up = y + 1 < h ? shadowed(x, y + 1) : -1;
      if (s < 0) continue;
      if (right >= 0 && right != s) edge[size_t(y) * w + x] = edge[size_t(y) * w + x + 1] = 1;
      if (up >= 0 && up != s) edge[size_t(y) * w + x] = edge[size_t(y + 1) * w + x] = 1;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (edge[size_t(y) * w + x])
        for (int v = std::max(0, y - radius); v <= std::min(h - 1, y + radius); ++v)
          for (int u = std::max(0, x - radius); u <= std::min(w - 1, x + radius); ++u) rim[size_t(v) * w + u] = 1;
  return rim;
}

}  // namespace

std::vector<uint8_t> outlineMask(const FloatImage& exact, const std::vector<glm::vec4>& positions) {
  const int w = exact.width, h = exact.height;
  auto state = [&](int x, int y) -> int {  // -1 outside the frame or where nothing is measured
    if (x < 0 || y < 0 || x >= w || y >= h) return -1;
    const size_t i = size_t(y) * size_t(w) + size_t(x);
    return std::isnan(exact.pixels[i]) || positions[i].w <= 0 ? -1 : exact.pixels[i] < 0.5f;
  };
  std::vector<uint8_t> outline(exact.pixels.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      outline[size_t(y) * size_t(w) + size_t(x)] = state(x, y) == 1 && (state(x - 1, y) == 0 || state(x + 1, y) == 0 ||
                                                                        state(x, y - 1) == 0 || state(x, y + 1) == 0);
  return outline;
}

FloatImage exactVisibility(const RayScene& rays, const Light& light, int width, int height,
                           const std::vector<glm::vec4>& positions) {
  FloatImage out{width, height, std::vector<float>(size_t(width) * size_t(height))};
  const float cosCone = std::cos(glm::radians(light.angle));
  // One pixel: NaN where nothing is measured, 0 for a surface facing away, else one ray.
  auto visibility = [&](const glm::vec4& p) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    if (p.w == 0) return nan;  // background
    const LightRay ray = rayToLight(light, glm::vec3(p));
    if (light.type == LightType::Spot && glm::dot(-ray.dir, light.direction) < cosCone) return nan;
    if (p.w < 0) return 0.0f;  // facing away: an attached shadow
    // Start a little way along the ray so the surface does not shadow itself through rounding.
    return rays.occluded(glm::vec3(p), ray.dir, 1e-3f, ray.tMax) ? 0.0f : 1.0f;
  };
  forEachRow(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      out.pixels[i] = visibility(positions[i]);
    }
  });
  return out;
}

VisibilityMetrics compareVisibility(const FloatImage& rendered, const FloatImage& exact,
                                    const std::vector<glm::vec4>& positions) {
  VisibilityMetrics m;
  const std::vector<uint8_t> rim = shadowRim(exact, positions, kRimPixels);
  for (size_t i = 0; i < exact.pixels.size(); ++i) {
    const float e = exact.pixels[i], r = rendered.pixels[i];
    if (std::isnan(e) || positions[i].w <= 0) continue;
    const bool wrong = e >= 0.5f ? r < 0.5f : r >= 0.5f;  // (a NaN drawn is neither)
    if (e >= 0.5f)
      ++m.litPixels, m.acnePixels += wrong;
    else
      ++m.shadowedPixels, m.leakPixels += wrong, m.shadowLight += std::clamp(double(r), 0.0, 1.0);
    m.rimPixels += rim[i], m.wrongOutsideRim += wrong && !rim[i];
  }
  for (uint8_t o : outlineMask(exact, positions)) m.outlinePixels += o;
  return m;
}

ReferenceDifference compareWithReference(const FloatImage& rendered, const std::vector<float>& reference, int x0,
                                         int x1) {
  ReferenceDifference d;
  for (size_t i = 0; i < reference.size() && i < rendered.pixels.size(); ++i) {
    const int x = int(i % size_t(rendered.width));
    if (reference[i] < 0 || x < x0 || x >= x1) continue;
    accumulate(d, rendered.pixels[i], reference[i]);
  }
  return d;
}

FloatImage filteredPointVisibility(const RayScene& rays, const glm::vec3& light, int width, int height,
                                   const std::vector<glm::vec4>& positions, const std::vector<glm::vec3>& offsets,
                                   float bias) {
  const std::vector<glm::vec3> taps = offsets.empty() ? std::vector<glm::vec3>{glm::vec3(0)} : offsets;
  FloatImage out{width, height, std::vector<float>(size_t(width) * size_t(height))};
  forEachRow(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      const glm::vec4 p = positions[i];
      const glm::vec3 d = glm::vec3(p) - light;
      int lit = 0;
      for (const glm::vec3& o : taps)  // from the light outwards, as the map saw it
        lit += p.w > 0 && !rays.occluded(light, glm::normalize(d + o), 1e-3f, glm::length(d) - bias);
      out.pixels[i] = p.w == 0 ? std::numeric_limits<float>::quiet_NaN() : float(lit) / float(taps.size());
    }
  });
  return out;
}

FloatImage rayTracedVisibility(const RayScene& rays, const Light& light, const glm::mat4& invViewProj, int width,
                               int height, int threads) {
  FloatImage out{width, height, std::vector<float>(size_t(width) * size_t(height))};
  auto unproject = [&](float x, float y, float z) {
    const glm::vec4 p = invViewProj * glm::vec4(x, y, z, 1);
    return glm::vec3(p) / p.w;
  };
  forEachRow(
      height,
      [&](int y) {
        for (int x = 0; x < width; ++x) {
          const float nx = (float(x) + 0.5f) / float(width) * 2 - 1, ny = (float(y) + 0.5f) / float(height) * 2 - 1;
          const glm::vec3 from = unproject(nx, ny, -1), dir = glm::normalize(unproject(nx, ny, 1) - from);
          const float far = 1e30f, t = rays.firstHit(from, dir, 0, far);
          float v = std::numeric_limits<float>::quiet_NaN();
          if (t < far) {
            const glm::vec3 p = from + t * dir;
            const LightRay ray = rayToLight(light, p);
            v = rays.occluded(p, ray.dir, 1e-3f, ray.tMax) ? 0.0f : 1.0f;
          }
          out.pixels[size_t(y) * size_t(width) + size_t(x)] = v;
        }
      },
      threads);
  return out;
}

double degreesFromCubeSeam(const glm::vec3& d) {
  glm::dvec3 a = glm::abs(glm::dvec3(d));
  if (a.x < a.y) std::swap(a.x, a.y);
  if (a.y < a.z) std::swap(a.y, a.z);
  if (a.x < a.y) std::swap(a.x, a.y);  // now a.x >= a.y >= a.z
  const double len = glm::length(a);
  // The plane |d_major| = |d_second| has the normal (1, -1, 0) / sqrt(2) in these sorted components.
  return len > 0 ? glm::degrees(std::asin(std::clamp((a.x - a.y) / (std::sqrt(2.0) * len), 0.0, 1.0))) : 0;
}

SeamError cubeSeamError(const FloatImage& rendered, const FloatImage& exact, const std::vector<glm::vec4>& positions,
                        const glm::vec3& light, double degrees) {
  SeamError e;
  for (size_t i = 0; i < exact.pixels.size() && i < rendered.pixels.size(); ++i) {
    if (std::isnan(exact.pixels[i]) || positions[i].w <= 0) continue;
    accumulate(degreesFromCubeSeam(glm::vec3(positions[i]) - light) < degrees ? e.seam : e.rest, rendered.pixels[i],
               exact.pixels[i]);
  }
  return e;
}

double contactGapTexels(const FloatImage& rendered, const FloatImage& exact, const std::vector<glm::vec4>& positions,
                        const RayScene& rays, const Light& light, float groundY, float texelWorld) {
  constexpr size_t kBins = 64;                                             // half-texel bins up to 32 texels
  std::map<int, std::pair<std::vector<long>, std::vector<long>>> casters;  // object -> (shadowed, leaking) per bin
  for (size_t i = 0; i < exact.pixels.size(); ++i) {
    const glm::vec4 p = positions[i];
    if (std::isnan(exact.pixels[i]) || exact.pixels[i] >= 0.5f || p.w <= 0 || std::abs(p.y - groundY) > 1e-3f) continue;
    const LightRay ray = rayToLight(light, glm::vec3(p));
    int object = -1;
    const float t = rays.firstHit(glm::vec3(p), ray.dir, 1e-3f, ray.tMax, &object);
    const glm::vec3 blocker = glm::vec3(p) + t * ray.dir;
    const size_t bin = size_t(2 * glm::length(glm::vec2(blocker.x - p.x, blocker.z - p.z)) / texelWorld);
    if (!rays.restsOn(object, groundY) || bin >= kBins) continue;
    auto& [shadowed, leaking] = casters[object];
    shadowed.resize(kBins), leaking.resize(kBins);
    ++shadowed[bin];
    leaking[bin] += rendered.pixels[i] >= 0.5f;
  }
  double worst = 0;
  for (const auto& [object, bins] : casters) {
    const auto& [shadowed, leaking] = bins;
    // Bins with fewer than 4 pixels say nothing; a caster with no informative bin is skipped. The
    // gap counts from the first informative bin, where the camera first sees that caster's shadow.
    double gap = -1, first = -1;
    for (size_t b = 0; b < kBins && gap < 0; ++b) {
      if (shadowed[b] < 4) continue;
      if (first < 0) first = 0.5 * double(b);
      if (2 * leaking[b] < shadowed[b]) gap = 0.5 * double(b) - first;
    }
    if (gap < 0 && first >= 0) gap = 0.5 * kBins - first;  // every informative bin leaks
    worst = std::max(worst, gap);
  }
  return worst;
}

std::vector<uint8_t> artifactHeatmap(const FloatImage& rendered, const FloatImage& exact,
                                     const std::vector<glm::vec4>& positions) {
  std::vector<uint8_t> rgba(exact.pixels.size() * 4, 255);
  for (size_t i = 0; i < exact.pixels.size(); ++i) {
    uint8_t* px = &rgba[4 * i];
    const float e = exact.pixels[i], r = rendered.pixels[i];
    px[0] = px[1] = px[2] = 30;
    if (std::isnan(e) || positions[i].w <= 0) continue;
    px[0] = px[1] = px[2] = e >= 0.5f ? 150 : 80;
    if (e >= 0.5f && r < 0.5f) px[0] = 255, px[1] = 40, px[2] = 40;   // acne
    if (e < 0.5f && r >= 0.5f) px[0] = 40, px[1] = 110, px[2] = 255;  // leak
  }
  return widenMarks(rgba, exact.width);
}

std::vector<uint8_t> widenMarks(const std::vector<uint8_t>& rgba, int width) {
  // A mark is a pixel of acne (red) or leak (blue); each becomes a 2x2 block, so that a single pixel
  // can be seen on a projector. Only the grey around marks is painted over, never another mark.
  auto mark = [&](size_t i) { return rgba[4 * i] == 255 || rgba[4 * i + 2] == 255; };
  std::vector<uint8_t> out = rgba;
  const size_t n = rgba.size() / 4, w = size_t(std::max(1, width));
  for (size_t i = 0; i < n; ++i) {
    if (!mark(i)) continue;
    const size_t x = i % w;
    for (size_t j : {i + 1, i + w, i + w + 1}) {
      if (j >= n || (j % w) < x || mark(j)) continue;  // (the row's end; another mark)
      std::copy(&rgba[4 * i], &rgba[4 * i] + 4, &out[4 * j]);
    }
  }
  return out;
}

}  // namespace wb
