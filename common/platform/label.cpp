#include "common/platform/label.hpp"

#include <stb_easy_font.h>

#include <glm/vec4.hpp>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace wb {
namespace {

constexpr float kEm = 10.0f;  // the font's size at scale 1, in pixels (a line is 12)

// Two triangles per quad of stb_easy_font's (x, y, z, colour: 16 bytes per corner), drawn solid.
float addBitmapText(const std::string& text, std::vector<glm::vec4>& out) {
  std::string copy = text;
  std::vector<char> raw(text.size() * 270 * 4 + 64);  // stb_easy_font's worst case per character
  const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, raw.data(), int(raw.size()));
  auto corner = [&](int q, int k) {
    const float* f = reinterpret_cast<const float*>(raw.data() + (q * 4 + k) * 16);
    return glm::vec4(f[0], f[1], -1, -1);
  };
  for (int q = 0; q < quads; ++q)
    for (int k : {0, 1, 2, 0, 2, 3}) out.push_back(corner(q, k));
  return float(stb_easy_font_width(copy.data()));
}

// The glyphs of `text` from the atlas, the baseline at the ascent below the top; returns the width.
float addFontText(const FontAtlas& font, const std::string& text, std::vector<glm::vec4>& out) {
  float pen = 0;
  const float baseline = font.ascent() * kEm + 1;
  for (char32_t c : decodeUtf8(text)) {
    const FontAtlas::Glyph& g = font.glyph(c);
    if (g.x1 > g.x0) {
      const glm::vec4 a(pen + g.x0 * kEm, baseline + g.y0 * kEm, g.u0, g.v0);
      const glm::vec4 b(pen + g.x1 * kEm, baseline + g.y1 * kEm, g.u1, g.v1);
      for (const glm::vec4& v : {a, glm::vec4(b.x, a.y, b.z, a.w), b, a, b, glm::vec4(a.x, b.y, a.z, b.w)})
        out.push_back(v);
    }
    pen += g.advance * kEm;
  }
  return pen;
}

// One atlas for every label of the process (baking it takes about 70 ms on llvmpipe), alive while a
// label holds it; null, after one warning, where there is no font.
std::shared_ptr<FontAtlas> sharedAtlas() {
  static std::weak_ptr<FontAtlas> cache;
  if (auto atlas = cache.lock()) return atlas;
  std::shared_ptr<FontAtlas> atlas;
  const auto file = findFontFile();
  try {
    if (!file.empty()) atlas = std::make_shared<FontAtlas>(file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "warning: %s\n", e.what());
  }
  static bool told = false;
  if (!atlas && !told)
    told = true, std::fprintf(stderr,
                              "warning: no DejaVu Sans font (sudo apt-get install fonts-dejavu-core, or set "
                              "WB_FONT to a .ttf): labels use an ASCII bitmap font\n");
  cache = atlas;
  return atlas;
}

}  // namespace

bool Label::hasFont() {
  if (!fontTried_) fontTried_ = true, font_ = sharedAtlas();
  return font_ != nullptr;
}

float Label::width(const std::string& text) {
  if (hasFont()) return font_->width(decodeUtf8(text)) * kEm;
  std::string copy = text;
  return float(stb_easy_font_width(copy.data()));
}

float Label::scaleToFit(const std::string& text, int pixels, float most) {
  const float w = width(text);
  return w > 0 ? std::min(most, float(pixels) / w) : most;
}

const Label::Mesh& Label::mesh(const std::string& text) {
  if (const auto found = meshes_.find(text); found != meshes_.end()) return found->second;
  if (meshes_.size() >= 32) meshes_.clear();  // (labels change rarely; keep a few)
  std::vector<glm::vec4> vertices(6);
  const float w = hasFont() ? addFontText(*font_, text, vertices) : addBitmapText(text, vertices);
  const float h = 13;  // the dark box's two triangles, around one line and its descenders
  const glm::vec4 box[6] = {{-3, -2, -1, -1}, {w + 2, -2, -1, -1}, {w + 2, h, -1, -1},
                            {-3, -2, -1, -1}, {w + 2, h, -1, -1},  {-3, h, -1, -1}};
  std::copy(box, box + 6, vertices.begin());
  Mesh m{makeBuffer(vertices.size() * sizeof(glm::vec4), vertices.data()), GLsizei(vertices.size()) - 6};
  return meshes_.emplace(text, std::move(m)).first->second;
}

void Label::draw(const std::string& text, glm::ivec2 pixel, glm::ivec2 size, float scale) {
  if (!program_.ok()) program_ = Program({{GL_VERTEX_SHADER, "wb/label.vert"}, {GL_FRAGMENT_SHADER, "wb/label.frag"}});
  if (!vao_.id()) vao_ = makeEmptyVertexArray();
  const Mesh& m = mesh(text);
  // Colour only: the visibility and position outputs stay as drawn (the draw buffers come back after).
  GLint fbo = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
  GLenum before[4] = {GL_NONE, GL_NONE, GL_NONE, GL_NONE};
  for (int k = 0; k < 4; ++k) glGetIntegerv(GL_DRAW_BUFFER0 + k, reinterpret_cast<GLint*>(&before[k]));
  const GLenum colourOnly = fbo ? GL_COLOR_ATTACHMENT0 : GL_BACK_LEFT;
  glDrawBuffers(1, &colourOnly);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program_.id());
  program_.set("u_origin", glm::vec2(pixel));
  program_.set("u_size", glm::vec2(size));
  program_.set("u_scale", scale);
  program_.set("u_atlas", 0);
  bindTexture(0, font_ ? font_->texture() : 0);
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, m.vertices.id());
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
  glEnableVertexAttribArray(0);
  program_.set("u_color", glm::vec4(0.1f, 0.1f, 0.1f, 1));
  glDrawArrays(GL_TRIANGLES, 0, 6);
  program_.set("u_color", glm::vec4(1));
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  if (m.glyphVertices > 0) glDrawArrays(GL_TRIANGLES, 6, m.glyphVertices);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDrawBuffers(fbo ? 4 : 1, before);
}

}  // namespace wb
