/// @file font.hpp
/// The workbook's one typeface for text drawn into frames (labels, presenter captions): DejaVu Sans
/// from Debian's fonts-dejavu-core, as a signed-distance atlas (stb_truetype), so that one atlas
/// stays sharp at every size, from a split-screen label to a 1080p caption, with ±, ×, µ, ≤ and ².
#pragma once
#include "common/platform/gl.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace wb {

/// The TTF file used: $WB_FONT if set, else the first DejaVu Sans found in the usual places (Debian's
/// fonts-dejavu-core, Homebrew, Windows); empty when there is none.
std::filesystem::path findFontFile();

/// Decodes UTF-8 into code points; a malformed byte becomes U+FFFD.
std::u32string decodeUtf8(const std::string& text);

/// A line of text as coverage (0..255, one byte a pixel), from rasterText().
struct TextBitmap {
  int width = 0;           ///< in pixels
  int height = 0;          ///< in pixels (the font's line height)
  std::vector<uint8_t> a;  ///< width * height coverage values, row by row from the top
};
/// `text` in the font `ttf`, `pixels` tall, rasterised on the CPU with no GL context: for pictures
/// written by tests and tools. Empty (width 0) when the font cannot be read.
TextBitmap rasterText(const std::filesystem::path& ttf, const std::string& text, float pixels);

/// A signed-distance atlas of DejaVu Sans: printable ASCII, Latin-1 and the few symbols captions
/// use. Glyph metrics are in em units (1 = the font's size in pixels).
class FontAtlas {
 public:
  /// One glyph: where it is in the atlas and where it goes on the line.
  struct Glyph {
    float u0;       ///< the glyph's rectangle in the atlas (0..1): left
    float v0;       ///< top
    float u1;       ///< right
    float v1;       ///< bottom
    float x0;       ///< where it goes, in em, from the pen on the baseline (y down): left
    float y0;       ///< top
    float x1;       ///< right
    float y1;       ///< bottom
    float advance;  ///< how far the pen moves, in em
  };
  /// Loads the font and bakes the atlas (needs a GL context); throws wb::Error when it cannot.
  explicit FontAtlas(const std::filesystem::path& ttf);
  /// The glyph of `c`, or of '?' for one the atlas lacks.
  const Glyph& glyph(char32_t c) const;
  /// The width of `text` in em.
  float width(const std::u32string& text) const;
  float ascent() const { return ascent_; }          ///< from the baseline up, in em
  GLuint texture() const { return texture_.id(); }  ///< the atlas (GL_R8, 0.5 on the outline)

 private:
  std::map<char32_t, Glyph> glyphs_;
  float ascent_ = 0.8f;
  Texture texture_;
};

}  // namespace wb
