/// @file image.hpp
/// Image files: PNG screenshots (stb_image_write) and single-channel float PFM visibility buffers.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace wb {

/// A single-channel float image, rows bottom to top (the order of glReadPixels and of PFM).
struct FloatImage {
  int width = 0;              ///< size in pixels
  int height = 0;             ///< size in pixels
  std::vector<float> pixels;  ///< width × height values
  /// The value at (x, y), y counted from the bottom row.
  float at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

/// Writes RGBA8 pixels (rows bottom to top) as a PNG, or a JPEG when the name ends in .jpg or .jpeg;
/// throws wb::UsageError for another extension and wb::Error if the file cannot be written.
void writePng(const std::filesystem::path& file, int w, int h, const std::vector<uint8_t>& rgba);
/// Writes a float image as a greyscale PFM ("Pf", little-endian).
void writePfm(const std::filesystem::path& file, const FloatImage& image);
/// Reads a greyscale PFM written by writePfm(); throws wb::Error naming the file on bad input.
FloatImage readPfm(const std::filesystem::path& file);
/// Maps a float image to RGBA8 with `lo` → black and `hi` → white, for looking at it as a PNG.
std::vector<uint8_t> toGrey(const FloatImage& image, float lo = 0, float hi = 1);

}  // namespace wb
