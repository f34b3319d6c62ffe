#include "common/label.hpp"

#include <stb_easy_font.h>

#include <glm/vec4.hpp>

#include <algorithm>
#include <vector>

namespace wb {
namespace {

// Two triangles per quad, from stb_easy_font's quads (x, y, z, colour: 16 bytes per corner).
void addQuads(const std::vector<char>& raw, int quads, std::vector<glm::vec2>& out) {
  auto corner = [&](int q, int k) {
    const float* f = reinterpret_cast<const float*>(raw.data() + (q * 4 + k) * 16);
    return glm::vec2(f[0], f[1]);
  };
  for (int q = 0; q < quads; ++q)
    for (int k : {0, 1, 2, 0, 2, 3}) out.push_back(corner(q, k));
}

}  // namespace

float Label::scaleToFit(const std::string& text, int pixels, float most) {
  std::string copy = text;
  const float w = float(stb_easy_font_width(copy.data()));
  return w > 0 ? std::min(most, float(pixels) / w) : most;
}

const Label::Mesh& Label::mesh(const std::string& text) {
  if (const auto found = meshes_.find(text); found != meshes_.end()) return found->second;
  if (meshes_.size() >= 16) meshes_.clear();          // (labels change rarely; keep a few)
  std::vector<char> raw(text.size() * 270 * 4 + 64);  // stb_easy_font's worst case per character
  std::string copy = text;
  const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, raw.data(), int(raw.size()));
  const float w = float(stb_easy_font_width(copy.data())), h = float(stb_easy_font_height(copy.data()));
  // The dark box's two triangles, then the glyphs'.
  std::vector<glm::vec2> vertices = {{-3, -3}, {w + 2, -3}, {w + 2, h}, {-3, -3}, {w + 2, h}, {-3, h}};
  addQuads(raw, quads, vertices);
  Mesh m{makeBuffer(vertices.size() * sizeof(glm::vec2), vertices.data()), GLsizei(vertices.size()) - 6};
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
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, m.vertices.id());
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);
  glEnableVertexAttribArray(0);
  program_.set("u_color", glm::vec4(0.1f, 0.1f, 0.1f, 1));
  glDrawArrays(GL_TRIANGLES, 0, 6);
  program_.set("u_color", glm::vec4(1));
  if (m.glyphVertices > 0) glDrawArrays(GL_TRIANGLES, 6, m.glyphVertices);
  glEnable(GL_DEPTH_TEST);
  glDrawBuffers(fbo ? 4 : 1, before);
}

}  // namespace wb
