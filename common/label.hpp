/// @file label.hpp
/// A line of text burnt into the frame's colour (never its visibility), so that a headless
/// screenshot says what it shows too: the split screen's halves are labelled with it.
#pragma once
#include "common/gl.hpp"
#include "common/shader.hpp"

#include <glm/vec2.hpp>

#include <map>
#include <string>

namespace wb {

/// Draws short labels with stb_easy_font's bitmap font.
class Label {
 public:
  /// Draws `text` with its top left at `pixel` (from the top left) into colour attachment 0 of the
  /// bound framebuffer of `size`, white on a dark box, `scale` times the font's size.
  void draw(const std::string& text, glm::ivec2 pixel, glm::ivec2 size, float scale = 2.0f);
  /// The largest scale, up to `most`, at which `text` is at most `pixels` wide.
  static float scaleToFit(const std::string& text, int pixels, float most = 2.0f);

 private:
  struct Mesh {
    Buffer vertices;        // the box's 6, then the glyphs'
    GLsizei glyphVertices;  // how many of the glyphs'
  };
  const Mesh& mesh(const std::string& text);  // built once per text, not per frame
  Program program_;
  VertexArray vao_;
  std::map<std::string, Mesh> meshes_;
};

}  // namespace wb
