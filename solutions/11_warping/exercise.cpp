// Lab 11 C++ exercises: reference solution.
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lab11 {

// EXERCISE 11.3
float warpNear(float zNear, float depthRange, float sinGamma, float strength, float fadeSin) {
  const float off = 0.02f;  // below about one degree the warp gains nothing: the uniform map
  const float fade = sinGamma <= off  ? 0.0f
                     : fadeSin <= off ? 1.0f
                                      : std::clamp((sinGamma - off) / (fadeSin - off), 0.0f, 1.0f);
  const float s = strength * fade;
  if (s <= 0) return std::numeric_limits<float>::infinity();
  const float z1 = zNear + depthRange * sinGamma;
  return (zNear + std::sqrt(zNear * z1)) / sinGamma / s;
}

// EXERCISE 11.4
glm::mat4 warpMatrix(const glm::mat4& lightView, const std::vector<glm::vec3>& body, float n, float casterReach) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& b : body) {
    const glm::vec3 p(lightView * glm::vec4(b, 1));
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  const float zNear = -hi.z - casterReach, zFar = -lo.z;  // light space looks down -z
  if (!std::isfinite(n)) return glm::ortho(lo.x, hi.x, lo.y, hi.y, zNear, zFar) * lightView;
  // The depth row of the orthographic fit (x and y pass through), then the perspective along +y: the
  // eye n before the body's nearest y, on its x centre. w = t = y - lo.y + n runs from n to f = n + d.
  const glm::mat4 depth = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, zNear, zFar);
  const float f = n + (hi.y - lo.y), cx = 0.5f * (lo.x + hi.x);
  const float a = (f + n) / (f - n), b = -2 * f * n / (f - n);
  glm::mat4 warp(0);                                // warp[column][row]
  warp[0][0] = n, warp[3][0] = -n * cx;             // x' = n (x - cx)
  warp[1][1] = a, warp[3][1] = a * (n - lo.y) + b;  // y' = a t + b: -1 at t = n, 1 at t = f
  warp[2][2] = n;                                   // depth' = n depth
  warp[1][3] = 1, warp[3][3] = n - lo.y;            // w = t
  const glm::mat4 m = warp * depth * lightView;
  float xl = 1e30f, xh = -1e30f;
  for (const glm::vec3& p : body) {
    const glm::vec4 c = m * glm::vec4(p, 1);
    xl = std::min(xl, c.x / c.w), xh = std::max(xh, c.x / c.w);
  }
  glm::mat4 fit(1);
  fit[0][0] = 2 / (xh - xl), fit[3][0] = -(xh + xl) / (xh - xl);
  return fit * m;
}

// EXERCISE 11.6
std::vector<float> fittedSplits(glm::vec2 bounds, float nearPlane, float farPlane, int cascades, float lambda) {
  float lo = nearPlane, hi = farPlane;
  const float a = std::clamp(bounds.x, nearPlane, farPlane), b = std::clamp(bounds.y, nearPlane, farPlane);
  if (bounds.y > 0 && b > a) lo = a, hi = b;
  std::vector<float> c(size_t(cascades) + 1);
  for (int i = 0; i <= cascades; ++i) {
    const float t = float(i) / float(cascades);
    c[size_t(i)] = lambda * lo * std::pow(hi / lo, t) + (1 - lambda) * (lo + (hi - lo) * t);
  }
  c.front() = lo, c.back() = hi;
  return c;
}

}  // namespace lab11

namespace lab11 {

// EXERCISE 11.H1: bug hunt (the fix). The fractions were taken over the fitted range (C_0 .. C_N), so
// they must be turned back over that same range; the camera's near plane and shadow distance are the
// range only while warp.sdsm is off.
std::vector<float> switchDistances(const std::vector<float>& splits, [[maybe_unused]] float nearPlane,
                                   [[maybe_unused]] float farPlane) {
  std::vector<float> out;
  if (splits.size() < 2) return out;
  const float start = splits.front(), length = splits.back() - splits.front();
  for (size_t i = 1; i + 1 < splits.size(); ++i) {
    const float fraction = (splits[i] - start) / length;
    out.push_back(start + fraction * length);
  }
  return out;
}

}  // namespace lab11
