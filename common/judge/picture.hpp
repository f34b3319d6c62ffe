/// @file picture.hpp
/// The pictures a failing test leaves for the student, small enough for a report page (each PNG under
/// 100 KB): a scene's three panels (reference, yours, difference) and a sweep's plot (yours against
/// the reference over one input, the failing cases marked). Drawn on the CPU, with the workbook's
/// font where it is found (no text otherwise).
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace wb::test {

/// An RGB colour.
struct Rgb {
  uint8_t r;  ///< red
  uint8_t g;  ///< green
  uint8_t b;  ///< blue
};

/// An RGB picture to draw on, written as PNG.
class Canvas {
 public:
  Canvas(int width, int height, Rgb fill);  ///< a width x height picture filled with `fill`
  /// Copies an RGBA8 image of w x h with its top left corner at (x, y).
  void blit(int x, int y, int w, int h, const std::vector<uint8_t>& rgba);
  /// A line `thick` pixels wide.
  void line(double x0, double y0, double x1, double y1, Rgb c, int thick = 1);
  /// A filled disc, or a ring two pixels wide.
  void disc(double x, double y, double radius, Rgb c, bool ring = false);
  /// `text` with its top left at (x, y), or its top right there when `right`; its width in pixels.
  int text(int x, int y, const std::string& text, float pixels, Rgb c, bool right = false);
  /// Writes the picture; false when the file could not be written.
  bool save(const std::filesystem::path& file) const;

 private:
  void put(int x, int y, Rgb c, float alpha = 1.0f);
  int width_, height_;
  std::vector<uint8_t> rgb_;
};

/// A failing scene as one picture: the reference, yours and their difference side by side (RGBA8
/// images of w x h each), titled, with `caption` (what the colours of the difference mean) below.
void writeScenePanels(const std::filesystem::path& file, int w, int h, const std::vector<uint8_t>& reference,
                      const std::vector<uint8_t>& yours, const std::vector<uint8_t>& difference,
                      const std::string& caption);

/// One case of a sweep: the input swept, your value, the reference's, and whether the case fails.
struct SweepPoint {
  double x;      ///< the input swept
  double got;    ///< your value
  double want;   ///< the reference's
  bool failing;  ///< whether the case fails
};

/// A function test that sweeps one input, as a plot: the reference's values (grey), yours (blue),
/// the failing cases ringed in red. Written to the test output folder as `name`.png when a case
/// fails; returns the line for the failure message ("\n  picture: PATH"), or "" when none fails.
std::string plotSweep(const std::string& name, const std::string& title, const std::string& xLabel,
                      const std::string& yLabel, const std::vector<SweepPoint>& points);

/// A function test's cases, read by index, of which some series sweep one input.
struct SweepCases {
  size_t count;                                    ///< how many cases
  std::function<double(size_t)> x;                 ///< case i's swept input
  std::function<double(size_t)> got;               ///< case i's value, yours
  std::function<double(size_t)> want;              ///< case i's value, the reference's
  std::function<bool(size_t)> failing;             ///< whether case i fails
  std::function<bool(size_t, size_t)> sameSeries;  ///< whether cases i and k differ in the swept input alone
};
/// plotSweep() of the series of the first failing case ("" when none fails).
std::string plotFirstFailingSeries(const std::string& name, const std::string& title, const std::string& xLabel,
                                   const std::string& yLabel, const SweepCases& cases);

}  // namespace wb::test
