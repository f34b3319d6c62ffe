#include "common/truth/texel_footprint.hpp"

#include <algorithm>
#include <cmath>

namespace wb {
namespace {

// Where `p` falls in the map of `viewProj` in texels, or false when it lies outside its clip box.
bool toTexels(const glm::mat4& viewProj, int size, const glm::vec3& p, glm::dvec2& texel) {
  const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
  if (clip.w <= 0) return false;
  const glm::dvec3 ndc = glm::dvec3(clip) / double(clip.w);
  texel = (glm::dvec2(ndc) * 0.5 + 0.5) * double(size);
  return std::abs(ndc.x) <= 1 && std::abs(ndc.y) <= 1 && std::abs(ndc.z) <= 1;
}

// The world-space step to the pixel's neighbour along one axis (dx, dy): the nearer of the two
// sides on a measured surface, so that an outline beside another surface's edge keeps its own
// plane; false where neither side is measured.
bool step(const std::vector<glm::vec4>& positions, int width, int height, int x, int y, int dx, int dy,
          glm::vec3& out) {
  const glm::vec3 p(positions[size_t(y) * size_t(width) + size_t(x)]);
  bool found = false;
  for (int sign : {1, -1}) {
    const int u = x + sign * dx, v = y + sign * dy;
    if (u < 0 || v < 0 || u >= width || v >= height) continue;
    const glm::vec4& q = positions[size_t(v) * size_t(width) + size_t(u)];
    if (q.w == 0) continue;
    const glm::vec3 d = float(sign) * (glm::vec3(q) - p);
    if (!found || glm::length(d) < glm::length(out)) out = d, found = true;
  }
  return found;
}

// The pixel → texel Jacobian's columns of map `k` at world point `p`, whose screen neighbours lie
// `ex`, `ey` away: the texels one pixel step right (a) and up (b) moves; false outside the map.
bool jacobian(const LightView& light, size_t k, const glm::vec3& p, const glm::vec3& ex, const glm::vec3& ey,
              glm::dvec2& a, glm::dvec2& b) {
  glm::dvec2 t, tx, ty;
  if (!toTexels(light.viewProj[k], light.size, p, t)) return false;
  toTexels(light.viewProj[k], light.size, p + ex, tx), toTexels(light.viewProj[k], light.size, p + ey, ty);
  a = tx - t, b = ty - t;
  return true;
}

// One texel of map `k` on screen at world point `p`, whose screen neighbours lie `ex`, `ey` away.
double footprint(const LightView& light, size_t k, const glm::vec3& p, const glm::vec3& ex, const glm::vec3& ey) {
  glm::dvec2 a, b;
  if (!jacobian(light, k, p, ex, ey, a, b)) return 0;
  const double sum = glm::dot(a, a) + glm::dot(b, b), det = a.x * b.y - a.y * b.x;
  const double smallest = std::sqrt(std::max(0.0, 0.5 * (sum - std::sqrt(std::max(0.0, sum * sum - 4 * det * det)))));
  return smallest > 0 ? std::min(kMaxTexelPixels, 1 / smallest) : kMaxTexelPixels;
}

// The cascade whose slice of the view holds `p` (between the planes of its near and far faces), or -1.
int sliceOf(const LightView& light, const glm::vec3& p) {
  for (size_t k = 0; k < light.outlines.size(); ++k) {
    const auto& c = light.outlines[k];
    const glm::vec3 n = glm::normalize(glm::cross(c[1] - c[0], c[3] - c[0]));
    const float along = glm::dot(n, p - c[0]), depth = glm::dot(n, c[4] - c[0]);
    if (depth > 0 ? along >= 0 && along <= depth : along <= 0 && along >= depth) return int(k);
  }
  return -1;
}

// The light-facing surface at pixel (x, y) as the maps see it: its world point, the world steps to its
// neighbours along x and y, and the first map it can be drawn from (for cascades, its slice's).
struct PixelSurface {
  glm::vec3 p, ex, ey;
  size_t first = 0;
  bool cascades = false;
};

// False where no map was drawn, the pixel holds no light-facing surface with a neighbour, or no
// cascade's slice holds it.
bool pixelSurface(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height, int x, int y,
                  PixelSurface& s) {
  const glm::vec4& q = positions[size_t(y) * size_t(width) + size_t(x)];
  if (!light.hasMap() || light.size <= 0 || q.w == 0 || !step(positions, width, height, x, y, 1, 0, s.ex) ||
      !step(positions, width, height, x, y, 0, 1, s.ey))
    return false;
  s.p = glm::vec3(q);
  s.cascades = !light.outlines.empty() && light.outlines.size() == light.viewProj.size();
  if (!s.cascades) return true;
  const int k = sliceOf(light, s.p);
  s.first = size_t(std::max(k, 0));
  return k >= 0;
}

}  // namespace

double texelPixels(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height, int x,
                   int y) {
  PixelSurface s;
  if (!pixelSurface(light, positions, width, height, x, y, s)) return 0;
  // (a cascade's pixel may be drawn from its slice's map or, in a blend band, the next one)
  const size_t last = s.cascades ? std::min(light.viewProj.size(), s.first + 2) : light.viewProj.size();
  double most = 0;
  for (size_t k = s.first; k < last; ++k) most = std::max(most, footprint(light, k, s.p, s.ex, s.ey));
  return most;
}

double texelsPerPixel(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height, int x,
                      int y) {
  PixelSurface s;
  if (!pixelSurface(light, positions, width, height, x, y, s)) return 0;
  for (size_t k = s.first; k < light.viewProj.size(); ++k) {
    glm::dvec2 a, b;
    if (jacobian(light, k, s.p, s.ex, s.ey, a, b)) return std::min(glm::length(a), glm::length(b));
  }
  return 0;
}

double medianTexelsPerPixel(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height) {
  std::vector<double> all;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (const double t = texelsPerPixel(light, positions, width, height, x, y); t > 0) all.push_back(t);
  if (all.empty()) return -1;
  std::nth_element(all.begin(), all.begin() + std::ptrdiff_t(all.size() / 2), all.end());
  return all[all.size() / 2];
}

double outlineTexelPixels(const LightView& light, const std::vector<glm::vec4>& positions, int width, int height,
                          const std::vector<uint8_t>& outline) {
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (outline[size_t(y) * size_t(width) + size_t(x)]) sum += texelPixels(light, positions, width, height, x, y);
  return sum;
}

}  // namespace wb
