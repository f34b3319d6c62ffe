#include "common/judge/picture.hpp"

#include "common/judge/harness.hpp"
#include "common/platform/font.hpp"
#include "common/platform/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace fs = std::filesystem;

namespace wb::test {
namespace {

const Rgb kInk{40, 40, 40}, kGrid{225, 225, 225}, kReference{150, 150, 150}, kYours{30, 90, 230}, kFailing{230, 30, 30};

const fs::path& font() {
  static const fs::path file = findFontFile();
  return file;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// The range [lo, hi] of the finite values, widened by `pad` of its size (or of the value, where it is one).
std::pair<double, double> range(const std::vector<double>& values, double pad) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!std::isfinite(lo)) return {0, 1};
  const double span = hi > lo ? hi - lo : std::max(1e-6, std::abs(lo));
  return {lo - pad * span, hi + pad * span};
}

// The values' range: the reference's, widened to take in yours where they are near it (within twice
// its size), so that one value far off (a division by zero) does not flatten the rest.
std::pair<double, double> valueRange(const std::vector<SweepPoint>& points) {
  std::vector<double> want, all;
  for (const auto& p : points) want.push_back(p.want);
  auto [lo, hi] = range(want, 0.0);
  const double span = std::max(hi - lo, 1e-6 + 0.5 * std::max(std::abs(lo), std::abs(hi)));
  all = want;
  for (const auto& p : points)
    if (p.got >= lo - 2 * span && p.got <= hi + 2 * span) all.push_back(p.got);
  return range(all, 0.08);
}

}  // namespace

Canvas::Canvas(int width, int height, Rgb fill)
    : width_(width), height_(height), rgb_(size_t(width) * size_t(height) * 3) {
  for (size_t i = 0; i < rgb_.size(); i += 3) rgb_[i] = fill.r, rgb_[i + 1] = fill.g, rgb_[i + 2] = fill.b;
}

void Canvas::put(int x, int y, Rgb c, float alpha) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  uint8_t* p = &rgb_[(size_t(y) * size_t(width_) + size_t(x)) * 3];
  const uint8_t in[3] = {c.r, c.g, c.b};
  for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(p[k] + (in[k] - p[k]) * alpha));
}

void Canvas::blit(int x, int y, int w, int h, const std::vector<uint8_t>& rgba) {
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const uint8_t* s = &rgba[(size_t(h - 1 - j) * size_t(w) + size_t(i)) * 4];  // (bottom row first)
      put(x + i, y + j, {s[0], s[1], s[2]});
    }
}

void Canvas::line(double x0, double y0, double x1, double y1, Rgb c, int thick) {
  const int steps = int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
  for (int s = 0; s <= steps; ++s) {
    const double t = double(s) / steps, x = x0 + (x1 - x0) * t, y = y0 + (y1 - y0) * t;
    for (int dy = 0; dy < thick; ++dy)
      for (int dx = 0; dx < thick; ++dx)
        put(int(std::lround(x)) + dx - thick / 2, int(std::lround(y)) + dy - thick / 2, c);
  }
}

void Canvas::disc(double x, double y, double radius, Rgb c, bool ring) {
  for (int j = int(y - radius) - 1; j <= int(y + radius) + 1; ++j)
    for (int i = int(x - radius) - 1; i <= int(x + radius) + 1; ++i) {
      const double d = std::hypot(i - x, j - y);
      if (d <= radius && (!ring || d >= radius - 2)) put(i, j, c);
    }
}

int Canvas::text(int x, int y, const std::string& text, float pixels, Rgb c, bool right) {
  const TextBitmap t = rasterText(font(), text, pixels);
  const int left = right ? x - t.width : x;
  for (int j = 0; j < t.height; ++j)
    for (int i = 0; i < t.width; ++i)
      if (const uint8_t a = t.a[size_t(j) * size_t(t.width) + size_t(i)]) put(left + i, y + j, c, float(a) / 255.0f);
  return t.width;
}

bool Canvas::save(const fs::path& file) const {
  std::vector<uint8_t> rgba(size_t(width_) * size_t(height_) * 4, 255);  // (writePng: bottom row first)
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      std::copy_n(&rgb_[3 * (size_t(height_ - 1 - y) * size_t(width_) + size_t(x))], 3,
                  &rgba[4 * (size_t(y) * size_t(width_) + size_t(x))]);
  try {
    writePng(file, width_, height_, rgba);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

void writeScenePanels(const fs::path& file, int w, int h, const std::vector<uint8_t>& reference,
                      const std::vector<uint8_t>& yours, const std::vector<uint8_t>& difference,
                      const std::string& caption) {
  const int gap = 8, top = 24, bottom = 24;
  Canvas c(3 * w + 4 * gap, h + top + bottom, {255, 255, 255});
  const char* titles[] = {"reference", "yours", "difference"};
  const std::vector<uint8_t>* images[] = {&reference, &yours, &difference};
  for (int k = 0; k < 3; ++k) {
    const int x = gap + k * (w + gap);
    c.text(x, 4, titles[k], 15, kInk);
    c.blit(x, top, w, h, *images[k]);
  }
  c.text(gap, top + h + 4, caption, 13, kInk);
  c.save(file);
}

std::string plotSweep(const std::string& name, const std::string& title, const std::string& xLabel,
                      const std::string& yLabel, const std::vector<SweepPoint>& points) {
  if (std::none_of(points.begin(), points.end(), [](const SweepPoint& p) { return p.failing; })) return "";
  const int width = 560, height = 370, left = 72, right = 20, top = 64, bottom = 50;
  std::vector<double> xs;
  for (const auto& p : points) xs.push_back(p.x);
  double x0, x1, y0, y1;  // (not structured bindings: the lambdas below may not name those before C++20)
  std::tie(x0, x1) = range(xs, 0.04);
  std::tie(y0, y1) = valueRange(points);
  auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (width - left - right); };
  auto py = [&](double y) {  // (a value that is not finite is drawn on the frame's edge)
    const double v = std::isnan(y) ? y1 : std::clamp(y, y0, y1);
    return height - bottom - (v - y0) / (y1 - y0) * (height - top - bottom);
  };
  Canvas c(width, height, {255, 255, 255});
  for (int k = 0; k <= 4; ++k) {  // the grid, with the values at its lines
    const double x = x0 + (x1 - x0) * k / 4, y = y0 + (y1 - y0) * k / 4;
    c.line(px(x), top, px(x), height - bottom, kGrid);
    c.line(left, py(y), width - right, py(y), kGrid);
    c.text(int(px(x)) - 12, height - bottom + 4, number(x), 12, kInk);
    c.text(left - 6, int(py(y)) - 8, number(y), 12, kInk, true);
  }
  c.line(left, height - bottom, width - right, height - bottom, kInk);
  c.line(left, top, left, height - bottom, kInk);
  std::vector<SweepPoint> sorted = points;
  std::stable_sort(sorted.begin(), sorted.end(), [](const SweepPoint& a, const SweepPoint& b) { return a.x < b.x; });
  for (size_t i = 1; i < sorted.size(); ++i) {
    c.line(px(sorted[i - 1].x), py(sorted[i - 1].want), px(sorted[i].x), py(sorted[i].want), kReference, 4);
    c.line(px(sorted[i - 1].x), py(sorted[i - 1].got), px(sorted[i].x), py(sorted[i].got), kYours, 2);
  }
  for (const auto& p : sorted) {
    c.disc(px(p.x), py(p.want), 4.5, kReference);
    c.disc(px(p.x), py(p.got), 3, kYours);
    if (p.failing) c.disc(px(p.x), py(p.got), 8, kFailing, true);
  }
  c.text(8, 6, title, 15, kInk);
  c.text(8, top - 20, yLabel, 12, kInk);
  c.text(width - right, height - 22, xLabel, 13, kInk, true);
  int x = left;  // the legend
  c.line(x, 31, x + 18, 31, kReference, 4);
  x += 24 + c.text(x + 24, 23, "reference", 12, kInk) + 14;
  c.line(x, 31, x + 18, 31, kYours, 2);
  x += 24 + c.text(x + 24, 23, "yours", 12, kInk) + 14;
  c.disc(x + 7, 31, 7, kFailing, true);
  c.text(x + 20, 23, "failing (off the plot: on its edge)", 12, kInk);
  const fs::path file = testOutputDir() / (name + ".png");
  fs::create_directories(file.parent_path());
  return c.save(file) ? "\n  picture: " + file.string() : "";
}

std::string plotFirstFailingSeries(const std::string& name, const std::string& title, const std::string& xLabel,
                                   const std::string& yLabel, const SweepCases& cases) {
  for (size_t i = 0; i < cases.count; ++i) {
    if (!cases.failing(i)) continue;
    std::vector<SweepPoint> series;
    for (size_t k = 0; k < cases.count; ++k)
      if (cases.sameSeries(i, k)) series.push_back({cases.x(k), cases.got(k), cases.want(k), cases.failing(k)});
    return plotSweep(name, title, xLabel, yLabel, series);
  }
  return "";
}

}  // namespace wb::test
