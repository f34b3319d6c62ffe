#include "common/truth/soft_shadows.hpp"

#include "common/base/parallel.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace wb {
namespace {

// A fixed integer hash (lowbias32), so the jitter is the same on every machine.
float hash01(uint32_t x) {
  x ^= x >> 16, x *= 0x7feb352dU, x ^= x >> 15, x *= 0x846ca68bU, x ^= x >> 16;
  return float(x >> 8) / float(1u << 24);
}

// Shirley and Chiu's concentric map: the square [0,1]^2 onto the disk of radius 1, keeping strata.
glm::vec2 concentric(float u, float v) {
  const float a = 2 * u - 1, b = 2 * v - 1, quarter = 0.785398163f;
  if (a == 0 && b == 0) return glm::vec2(0);
  const bool wide = std::abs(a) > std::abs(b);
  const float r = wide ? a : b, phi = wide ? quarter * (b / a) : 2 * quarter - quarter * (a / b);
  return r * glm::vec2(std::cos(phi), std::sin(phi));
}

// The 10-90% crossings of a profile (mean visibility per z bin, NaN for an empty bin), around its
// first 0.5 crossing from the lit end; -1 if it has none. `step` is a bin's width.
double tenNinetyWidth(std::vector<double> v, double step) {
  std::vector<double> z;
  for (size_t i = 0; i < v.size(); ++i) z.push_back(double(i) * step);
  size_t keep = 0;  // drop empty bins
  for (size_t i = 0; i < v.size(); ++i)
    if (!std::isnan(v[i])) v[keep] = v[i], z[keep] = z[i], ++keep;
  v.resize(keep), z.resize(keep);
  if (v.size() < 3) return -1;
  if (v.front() < v.back()) std::reverse(v.begin(), v.end()), std::reverse(z.begin(), z.end());  // lit first
  // The first crossing of `level` walking from index `from` in direction `dir`, interpolated.
  auto cross = [&](double level, size_t from, int dir) -> double {
    for (size_t i = from; i + 1 < v.size() + (dir < 0) && (dir > 0 || i > 0); i += size_t(dir)) {
      const size_t j = i + size_t(dir);
      if ((v[i] - level) * (v[j] - level) <= 0 && v[i] != v[j])
        return z[i] + (z[j] - z[i]) * (v[i] - level) / (v[i] - v[j]);
    }
    return std::numeric_limits<double>::quiet_NaN();
  };
  size_t half = 0;
  while (half + 1 < v.size() && v[half + 1] >= 0.5) ++half;
  if (half + 1 >= v.size()) return -1;
  const double z90 = cross(0.9, half, -1), z10 = cross(0.1, half, 1);
  if (std::isnan(z90) || std::isnan(z10)) return -1;
  return std::abs(z10 - z90);
}

}  // namespace

std::vector<glm::vec2> lightDiskPattern(int count) {
  const int n = std::max(1, int(std::lround(std::sqrt(double(std::max(count, 1))))));
  std::vector<glm::vec2> out;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t k = uint32_t(j * n + i);
      out.push_back(0.5f *
                    concentric((float(i) + hash01(2 * k)) / float(n), (float(j) + hash01(2 * k + 1)) / float(n)));
    }
  return out;
}

namespace {
// The normal of the triangle under `p`, on the side that faces `toward` (the light's centre, which
// the pixel faces): a short ray from just above the surface back down to it; `toward`'s direction if
// nothing is there.
glm::vec3 surfaceNormal(const RayScene& rays, const glm::vec3& p, const glm::vec3& toward) {
  constexpr float kStep = 2e-3f;
  const glm::vec3 up = glm::normalize(toward - p);
  glm::vec3 n(0);
  if (rays.firstHit(p + kStep * up, -up, 0, 2 * kStep, nullptr, &n) >= 2 * kStep) return up;
  return glm::dot(n, up) < 0 ? -n : n;
}
}  // namespace

FloatImage areaLightVisibility(const RayScene& rays, const Light& light, const FloatImage& exact,
                               const std::vector<glm::vec4>& positions, int samples) {
  FloatImage out = exact;  // its NaN and facing-away pixels stay
  if (light.size <= 0 || light.type != LightType::Spot) return out;
  const int width = exact.width;
  const glm::vec3 d = glm::normalize(light.direction);
  const glm::vec3 t = glm::normalize(glm::cross(d, std::abs(d.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 b = glm::cross(d, t);
  std::vector<glm::vec3> points;
  for (const glm::vec2 p : lightDiskPattern(samples))
    points.push_back(light.position + light.size * (p.x * t + p.y * b));
  forEachRow(exact.height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      if (std::isnan(out.pixels[i]) || positions[i].w <= 0) continue;
      const glm::vec3 p(positions[i]), n = surfaceNormal(rays, p, light.position);
      int seen = 0;
      for (const glm::vec3& s : points) {
        const float dist = glm::length(s - p);
        seen += !rays.occluded(p, (s - p) / dist, 1e-3f, dist);
      }
      out.pixels[i] = float(seen) / float(points.size());
      for (const glm::vec3& s : points)  // part of the disk under the surface's own horizon: not compared
        if (glm::dot(n, s - p) <= 0) out.pixels[i] = std::numeric_limits<float>::quiet_NaN();
    }
  });
  return out;
}

double diskTenNinetyFraction() {
  // The share of a unit disk's area beyond the chord at distance t from its centre, (acos t - t
  // sqrt(1 - t^2)) / pi, is 0.1 at t = t10; the 10% and 90% chords lie at -t10 and +t10, and the full
  // width is the diameter, 2: the fraction is t10.
  double lo = 0, hi = 1;
  for (int k = 0; k < 60; ++k) {
    const double t = 0.5 * (lo + hi), share = (std::acos(t) - t * std::sqrt(1 - t * t)) / glm::pi<double>();
    (share > 0.1 ? lo : hi) = t;
  }
  return 0.5 * (lo + hi);
}

std::vector<PenumbraSlab> measurePenumbra(const PenumbraProbe& probe, const FloatImage& rendered,
                                          const FloatImage& reference, const std::vector<glm::vec4>& positions,
                                          const RayScene& rays, const Light& light, float groundY) {
  std::vector<PenumbraSlab> out;
  if (!probe.on) return out;
  const int zBins = 160;
  const double zStep = double(probe.z.y - probe.z.x) / zBins, xStep = double(probe.x.y - probe.x.x) / probe.bins;
  for (int s = 0; s < probe.bins; ++s) {
    PenumbraSlab slab;
    slab.x = probe.x.x + (s + 0.5) * xStep;
    std::vector<double> sum[2] = {std::vector<double>(zBins), std::vector<double>(zBins)};
    std::vector<int> count(zBins);
    for (size_t i = 0; i < positions.size(); ++i) {
      const glm::vec4 p = positions[i];
      if (p.w <= 0 || std::abs(p.y - groundY) > 1e-3f || std::isnan(reference.pixels[i])) continue;
      const int bz = int(std::floor((p.z - probe.z.x) / zStep)), bx = int(std::floor((p.x - probe.x.x) / xStep));
      if (bx != s || bz < 0 || bz >= zBins) continue;
      sum[0][size_t(bz)] += std::clamp(double(rendered.pixels[i]), 0.0, 1.0);
      sum[1][size_t(bz)] += reference.pixels[i], ++count[size_t(bz)];
    }
    for (int k = 0; k < 2; ++k) {
      std::vector<double> profile(zBins);
      for (int z = 0; z < zBins; ++z)
        profile[size_t(z)] = count[size_t(z)] ? sum[k][size_t(z)] / count[size_t(z)] : std::nan("");
      (k ? slab.referenceWidth : slab.width) = tenNinetyWidth(profile, zStep);
    }
    // The distance at the reference's 0.5 crossing: the ray from there to the light's centre.
    std::vector<double> ref(zBins);
    for (int z = 0; z < zBins; ++z) ref[size_t(z)] = count[size_t(z)] ? sum[1][size_t(z)] / count[size_t(z)] : -1;
    int edge = -1;
    for (int z = 0; z + 1 < zBins && edge < 0; ++z)
      if (ref[size_t(z)] >= 0 && ref[size_t(z) + 1] >= 0 && (ref[size_t(z)] - 0.5) * (ref[size_t(z) + 1] - 0.5) <= 0)
        edge = z;
    // At the 0.5 crossing the ray to the light's centre grazes the blocker's edge: step into the
    // shadow until it hits.
    const glm::vec3 axis = glm::normalize(light.direction);
    for (int step = 0; edge >= 0 && step < 40 && slab.theory == 0; ++step) {
      const float dz = float(zStep) * float(step) * (ref[size_t(edge)] > ref[size_t(edge) + 1] ? 1.0f : -1.0f);
      const glm::vec3 p(float(slab.x), groundY, probe.z.x + float((edge + 1) * zStep) + dz);
      const float len = glm::length(light.position - p);
      const glm::vec3 dir = (light.position - p) / len;
      const float hit = rays.firstHit(p, dir, 1e-3f, len);
      const double zR = glm::dot(p - light.position, axis), zB = glm::dot(p + hit * dir - light.position, axis);
      if (hit < len && zB > 0)
        slab.distance = zR - zB, slab.theory = diskTenNinetyFraction() * light.size * (zR - zB) / zB;
    }
    out.push_back(slab);
  }
  return out;
}

}  // namespace wb
