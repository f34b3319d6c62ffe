/// @file frame_target.hpp
/// The offscreen target every camera pass draws into (shaders/wb/outputs.glsl declares it): colour
/// (attachment 0), light visibility (1), world position (2), and depth + stencil. Screenshots,
/// --dump-visibility and the measurements read it back. With samples (present.msaa, for lectures) the
/// passes between clear() and resolve() draw into multisampled twins of the attachments, which
/// resolve() averages into the single-sampled ones that everything else reads.
#pragma once
#include "common/platform/gl.hpp"
#include "common/platform/image.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace wb {

/// The frame target: RGBA8 colour, R32F visibility, RGBA32F position, GL_DEPTH24_STENCIL8.
class FrameTarget {
 public:
  /// (Re)allocates every attachment when `size` differs from the current size.
  void resize(glm::ivec2 size);
  /// Multisampling for the frame's passes: 1 (off), 2, 4 or 8; takes effect at the next clear().
  void setSamples(int samples) { samples_ = samples; }
  /// Binds the framebuffer (the multisampled one between clear() and resolve()) and sets the
  /// viewport to the whole target.
  void bind() const;
  /// Averages the multisampled attachments into the target (each pixel's visibility and position
  /// too: an edge pixel holds the mean of its samples); after it, bind() binds the target itself.
  void resolve();
  /// Clears colour to the sky, visibility to 1 (lit), position to 0 (no surface), depth to 1 and
  /// stencil to 0.
  void clear() const;
  /// Turns writes to the visibility and position attachments off (overlays) or back on.
  void maskDataOutputs(bool masked) const;
  /// The size in pixels.
  glm::ivec2 size() const { return size_; }
  /// The framebuffer name.
  GLuint framebuffer() const { return fbo_.id(); }
  /// Attachment `k`'s texture: 0 colour, 1 visibility, 2 position.
  GLuint attachment(int k) const { return color_[k].id(); }
  /// Copies the rectangle [x, x + w) × [0, height) of every colour attachment into `into` (three
  /// textures of that size) or, with `back`, from them into the target at the same place.
  void copyColumns(int x, int w, const Texture (&into)[3], bool back) const;

  /// Colour as RGBA8, rows bottom to top.
  std::vector<uint8_t> readColor() const;
  /// Visibility per pixel (1 lit, 0 shadowed), rows bottom to top.
  FloatImage readVisibility() const;
  /// World position per pixel (w: +1 facing the light, −1 facing away, 0 no surface).
  std::vector<glm::vec4> readPositions() const;
  /// Stencil value per pixel, rows bottom to top.
  std::vector<uint8_t> readStencil() const;

 private:
  Texture color_[3], depthStencil_;
  Framebuffer fbo_;
  glm::ivec2 size_{0};
  int samples_ = 1, msSamples_ = 1;  // asked for; allocated below
  Texture msColor_[3], msDepthStencil_;
  Framebuffer msFbo_;
  mutable bool multisampling_ = false;  // between clear() and resolve()
};

}  // namespace wb
