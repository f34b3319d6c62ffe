/// @file label.hpp
/// A line of text burnt into the frame's colour (never its visibility), so that a headless
/// screenshot says what it shows too: the split screen's halves, the presenter's captions.
#pragma once
#include "common/platform/font.hpp"
#include "common/platform/gl.hpp"
#include "common/platform/shader.hpp"

#include <glm/vec2.hpp>

#include <map>
#include <memory>
#include <string>

namespace wb {

/// Draws short labels (UTF-8) in DejaVu Sans (common/platform/font.hpp); where no such font is found, in
/// stb_easy_font's ASCII bitmap font, after one warning.
class Label {
 public:
  /// Draws `text` with its top left at `pixel` (from the top left) into colour attachment 0 of the
  /// bound framebuffer of `size`, white on a dark box. At `scale` 1 the font's size is 10 pixels and
  /// the box 15 tall (2 above the text's top, 13 down to below its descenders).
  void draw(const std::string& text, glm::ivec2 pixel, glm::ivec2 size, float scale = 2.0f);
  /// The largest scale, up to `most`, at which `text` is at most `pixels` wide.
  float scaleToFit(const std::string& text, int pixels, float most = 2.0f);
  /// The width of `text` at scale 1, in pixels.
  float width(const std::string& text);
  /// True when the labels use the TTF font (false: the ASCII bitmap fallback).
  bool hasFont();

 private:
  struct Mesh {
    Buffer vertices;        // (x, y, u, v): the box's 6, then the glyphs'
    GLsizei glyphVertices;  // how many of the glyphs'
  };
  const Mesh& mesh(const std::string& text);  // built once per text, not per frame
  Program program_;
  VertexArray vao_;
  std::map<std::string, Mesh> meshes_;
  std::shared_ptr<FontAtlas> font_;  // the process's one atlas (label.cpp)
  bool fontTried_ = false;
};

}  // namespace wb
