#include "common/platform/font.hpp"

#include "common/base/error.hpp"
#include "common/platform/shader.hpp"

// Static: Dear ImGui has its own stb_truetype, and Debian's libimgui exports it; two copies with
// external names would take each other's functions.
#define STBTT_STATIC
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace fs = std::filesystem;

namespace wb {
namespace {

constexpr float kBakePixels = 48.0f;  // the em the distances are baked at
constexpr int kPadding = 6;           // texels of distance around each glyph
constexpr int kAtlas = 1024;          // atlas width; rows are added as glyphs fill it

// Printable ASCII, Latin-1 (±, ×, µ, ², °), and the symbols the captions and labels use.
std::u32string charset() {
  std::u32string s;
  for (char32_t c = 0x20; c < 0x7F; ++c) s += c;
  for (char32_t c = 0xA0; c <= 0xFF; ++c) s += c;
  s += U"\u03BB\u03C3\u03C0\u2013\u2014\u2018\u2019\u201C\u201D\u2022\u2026\u2192\u2190\u2248\u2260\u2264\u2265"
       U"\u221A\u2211\u2212\uFFFD";
  return s;
}

}  // namespace

fs::path findFontFile() {
  if (const char* chosen = std::getenv("WB_FONT"); chosen && *chosen) return chosen;
  for (const char* p : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
                        "/opt/homebrew/share/fonts/DejaVuSans.ttf", "/usr/local/share/fonts/DejaVuSans.ttf",
                        "/Library/Fonts/DejaVuSans.ttf", "C:/Windows/Fonts/DejaVuSans.ttf"}) {
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) return p;
  }
  return {};
}

std::u32string decodeUtf8(const std::string& text) {
  std::u32string out;
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + size_t(extra) >= text.size() + size_t(extra == 0)) {  // (a sequence cut short)
      out += U'\uFFFD', ++i;
      continue;
    }
    char32_t cp = extra == 0 ? c : c & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const unsigned char next = static_cast<unsigned char>(text[i + size_t(k)]);
      ok = ok && (next >> 6) == 2;
      cp = (cp << 6) | (next & 0x3F);
    }
    out += ok ? cp : U'\uFFFD';
    i += ok ? size_t(extra) + 1 : 1;
  }
  return out;
}

TextBitmap rasterText(const fs::path& ttf, const std::string& text, float pixels) {
  std::string data;
  try {
    data = readFile(ttf);
  } catch (const Error&) {
    return {};
  }
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  stbtt_fontinfo font;  // (stb_truetype trusts its input: a file too short to be a font is refused first)
  if (ttf.empty() || data.size() < 12 || stbtt_GetFontOffsetForIndex(bytes, 0) < 0 ||
      !stbtt_InitFont(&font, bytes, stbtt_GetFontOffsetForIndex(bytes, 0)))
    return {};
  const float scale = stbtt_ScaleForPixelHeight(&font, pixels);
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&font, &ascent, &descent, &gap);
  const std::u32string cps = decodeUtf8(text);
  float width = 0;
  for (char32_t c : cps) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font, int(c), &advance, &bearing);
    width += float(advance) * scale;
  }
  TextBitmap out;
  out.width = int(std::ceil(width)) + 1;
  out.height = int(std::ceil(float(ascent - descent) * scale)) + 1;
  out.a.assign(size_t(out.width) * size_t(out.height), 0);
  float pen = 0;
  const int baseline = int(std::round(float(ascent) * scale));
  for (char32_t c : cps) {
    int advance = 0, bearing = 0, w = 0, h = 0, xoff = 0, yoff = 0;
    stbtt_GetCodepointHMetrics(&font, int(c), &advance, &bearing);
    unsigned char* glyph = stbtt_GetCodepointBitmap(&font, scale, scale, int(c), &w, &h, &xoff, &yoff);
    for (int j = 0; j < h; ++j)  // (clipped to the line, and kept where glyphs overlap)
      for (int i = 0; i < w; ++i) {
        const int x = int(std::round(pen)) + xoff + i, y = baseline + yoff + j;
        if (x < 0 || y < 0 || x >= out.width || y >= out.height) continue;
        uint8_t& a = out.a[size_t(y) * size_t(out.width) + size_t(x)];
        a = std::max(a, glyph[j * w + i]);
      }
    stbtt_FreeBitmap(glyph, nullptr);
    pen += float(advance) * scale;
  }
  return out;
}

FontAtlas::FontAtlas(const fs::path& ttf) {
  const std::string data = readFile(ttf);
  stbtt_fontinfo font;
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  if (data.size() < 12 || stbtt_GetFontOffsetForIndex(bytes, 0) < 0 ||
      !stbtt_InitFont(&font, bytes, stbtt_GetFontOffsetForIndex(bytes, 0)))
    throw Error(ttf.string() + " is not a TrueType font");
  const float scale = stbtt_ScaleForPixelHeight(&font, kBakePixels);
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&font, &ascent, &descent, &gap);
  ascent_ = float(ascent) * scale / kBakePixels;
  // Shelf packing: glyphs left to right, a new row when one is full.
  std::vector<unsigned char> atlas(size_t(kAtlas) * 64, 0);
  int x = 0, y = 0, row = 0;
  struct Placed {
    char32_t c;
    int x, y, w, h;
  };
  std::vector<Placed> placed;
  for (char32_t c : charset()) {
    int w = 0, h = 0, xoff = 0, yoff = 0;
    unsigned char* sdf =
        stbtt_GetCodepointSDF(&font, scale, int(c), kPadding, 128, 128.0f / kPadding, &w, &h, &xoff, &yoff);
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font, int(c), &advance, &bearing);
    Glyph g{0, 0, 0, 0, 0, 0, 0, 0, float(advance) * scale / kBakePixels};
    if (sdf) {
      if (x + w > kAtlas) x = 0, y += row + 1, row = 0;
      if (size_t(y + h) * kAtlas > atlas.size()) atlas.resize(size_t(y + h) * kAtlas * 2, 0);
      for (int r = 0; r < h; ++r)
        for (int k = 0; k < w; ++k) atlas[size_t(y + r) * kAtlas + size_t(x + k)] = sdf[r * w + k];
      stbtt_FreeSDF(sdf, nullptr);
      placed.push_back({c, x, y, w, h});
      g.x0 = float(xoff) / kBakePixels, g.y0 = float(yoff) / kBakePixels;
      g.x1 = float(xoff + w) / kBakePixels, g.y1 = float(yoff + h) / kBakePixels;
      x += w + 1, row = std::max(row, h);
    }
    glyphs_[c] = g;
  }
  const int height = y + row + 1;
  for (const Placed& p : placed) {
    Glyph& g = glyphs_[p.c];
    g.u0 = float(p.x) / kAtlas, g.u1 = float(p.x + p.w) / kAtlas;
    g.v0 = float(p.y) / float(height), g.v1 = float(p.y + p.h) / float(height);
  }
  texture_ = makeTexture2D(GL_R8, kAtlas, height, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  uploadTexture2D(texture_.id(), 0, 0, kAtlas, height, GL_RED, GL_UNSIGNED_BYTE, atlas.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

const FontAtlas::Glyph& FontAtlas::glyph(char32_t c) const {
  const auto g = glyphs_.find(c);
  return g != glyphs_.end() ? g->second : glyphs_.at(U'?');
}

float FontAtlas::width(const std::u32string& text) const {
  float w = 0;
  for (char32_t c : text) w += glyph(c).advance;
  return w;
}

}  // namespace wb
