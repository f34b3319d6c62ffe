/// @file prefilter.hpp
/// The prefilter pipeline of the filterable shadow maps (ESM, VSM, EVSM, MSM): a colour shadow map
/// that stores what the technique can average (warped depth, moments), a separable blur (box or
/// Gaussian, 1 to 7 taps wide), and optional mipmaps for trilinear or anisotropic lookups.
#pragma once
#include "common/platform/gl.hpp"

#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

namespace wb {

class Program;
class Settings;

/// How a FilteredShadowMap stores and filters its values.
struct PrefilterOptions {
  GLenum format = GL_RG32F;  ///< GL_R32F, GL_RG32F, GL_RGBA32F or their 16-bit (…16F) forms
  int kernel = 3;            ///< blur width in texels: 1 (no blur), 3, 5 or 7
  bool gaussian = true;      ///< Gaussian weights (sigma = kernel / 4) instead of a box
  bool mipmaps = false;      ///< build mipmaps after the blur (trilinear, anisotropic 8x)
};

/// The prefilter's settings, the same in every filterable lab: prefilter.kernel, prefilter.gaussian
/// and prefilter.mipmaps.
struct PrefilterSettings {
  int kernel = 0;        ///< width index into 1, 3, 5, 7 texels (1: bilinear only, interactive on a CPU)
  bool gaussian = true;  ///< Gaussian weights instead of a box
  bool mipmaps = false;  ///< mipmaps with trilinear and 8x anisotropic lookups
  /// Registers the three settings, and makes 512² the default map size: the blur's cost grows with
  /// the map's area.
  void addTo(Settings& settings);
  /// The options for a map stored in `format`.
  PrefilterOptions options(GLenum format) const { return {format, 1 + 2 * kernel, gaussian, mipmaps}; }
};

/// A colour shadow map with a depth buffer, blurred in place after it is drawn.
class FilteredShadowMap {
 public:
  /// (Re)allocates when the size or format changes.
  void resize(int size, const PrefilterOptions& options);
  /// Binds the framebuffer, sets the viewport and clears colour to `clear` and depth to 1.
  void begin(const float clear[4]) const;
  /// Draws one full-map triangle with `program` (a synthetic map for experiments); call after begin().
  void fill(const Program& program) const;
  /// Blurs horizontally then vertically with `blurProgram` (the framework's shaders/wb/blur.frag, or
  /// a lab's own), as two fragment passes; then builds the mipmaps if asked.
  void prefilter(const Program& blurProgram);
  /// The filtered texture (linear filtering; trilinear and anisotropic with mipmaps).
  GLuint texture() const { return color_.id(); }
  /// The unfiltered depth buffer of the same render (for a PCF fallback).
  GLuint depthTexture() const { return depth_.id(); }
  /// Width and height in texels.
  int size() const { return size_; }
  /// The options it was allocated with.
  const PrefilterOptions& options() const { return options_; }

 private:
  Texture color_, scratch_, depth_;
  Framebuffer fbo_, scratchFbo_, backFbo_;
  VertexArray vao_;
  int size_ = 0;
  PrefilterOptions options_;
};

/// Filtered maps for cascades: one FilteredShadowMap per layer, each with a blur of its own width,
/// copied into one array texture after its prefilter, so a lab reads every cascade through one
/// sampler2DArray (lab 10's csm.filter=vsm).
class FilteredShadowMapArray {
 public:
  /// (Re)allocates the array when the size, layer count or format changes.
  void resize(int size, int layers, GLenum format);
  /// Layer k's map: resize() it with that layer's options, draw and prefilter it, then copy().
  FilteredShadowMap& layer(int k) { return layers_.at(size_t(k)); }
  /// Copies layer k's filtered map into the array.
  void copy(int k) const;
  /// The array texture (linear filtering, clamped).
  GLuint texture() const { return array_.id(); }

 private:
  std::vector<FilteredShadowMap> layers_;
  Texture array_;
  int size_ = 0;
  GLenum format_ = 0;
};

/// The prefilter's normalised weights for taps 0..r of a kernel `kernel` texels wide (r = kernel / 2):
/// Gaussian with sigma = kernel / 4, or a box.
void blurWeights(int kernel, bool gaussian, float weights[8]);

/// The reference the filtered techniques approximate: PCF over the same footprint as the prefilter
/// (kernel × kernel weights, bilinear taps) from a plain depth map, for every pixel of a frame whose
/// world positions are in `positions` (see shaders/wb/outputs.glsl). Pixels not facing the light
/// get -1. Only for orthographic (directional) light maps: the bias is `biasTexels` texels of a
/// 45° slope in depth units.
class PcfReference {
 public:
  /// Renders the reference and reads it back (rows bottom to top).
  std::vector<float> render(GLuint positions, int width, int height, GLuint depthMap, int mapSize,
                            const glm::mat4& lightViewProj, int kernel, bool gaussian, float biasTexels = 1.5f);

 private:
  std::unique_ptr<Program> program_;
  Texture target_;
  Framebuffer fbo_;
  VertexArray vao_;
  Sampler sampler_;  // nearest, no comparison: the depth map may be set up for sampler2DShadow
};

/// The largest value a format can hold: FLT_MAX for 32-bit floats, 65504 for 16-bit ones.
double formatMax(GLenum format);

}  // namespace wb
