#include "common/shadows/prefilter.hpp"

#include "common/base/error.hpp"
#include "common/base/settings.hpp"
#include "common/platform/shader.hpp"
#include "common/shadows/shadow_map.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <utility>

namespace wb {

double formatMax(GLenum format) {
  switch (format) {
    case GL_R16F:
    case GL_RG16F:
    case GL_RGBA16F:
      return 65504.0;
    default:
      return double(FLT_MAX);
  }
}

void blurWeights(int kernel, bool gaussian, float weights[8]) {
  const int radius = std::clamp(kernel / 2, 0, 7);
  const float sigma = float(kernel) / 4.0f;
  auto weight = [&](int i) { return gaussian ? std::exp(-float(i * i) / (2 * sigma * sigma)) : 1.0f; };
  float total = 0;
  for (int i = -radius; i <= radius; ++i) total += weight(i);
  for (int i = 0; i < 8; ++i) weights[i] = i <= radius ? weight(i) / total : 0.0f;
}

std::vector<float> PcfReference::render(GLuint positions, int width, int height, GLuint depthMap, int mapSize,
                                        const glm::mat4& lightViewProj, int kernel, bool gaussian, float biasTexels) {
  if (!program_) {
    program_ = std::make_unique<Program>(std::vector<ShaderStage>{{GL_VERTEX_SHADER, "wb/fullscreen.vert"},
                                                                  {GL_FRAGMENT_SHADER, "wb/pcf_reference.frag"}});
    vao_ = makeEmptyVertexArray();
    sampler_ = makePlainSampler();
  }
  GLint size[2] = {0, 0};
  if (target_.id()) {
    BoundTexture ask(GL_TEXTURE_2D, target_.id());
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &size[0]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &size[1]);
  }
  if (size[0] != width || size[1] != height) {
    target_ = makeTexture2D(GL_R32F, width, height);
    fbo_ = makeFramebuffer({target_.id()}, 0);
  }
  // Depth changes by |grad z| per world unit; a 45° receiver changes one texel's width per texel.
  const glm::vec3 depthRow(lightViewProj[0][2], lightViewProj[1][2], lightViewProj[2][2]);
  const float texelWorld = texelWorldSize(lightViewProj, mapSize);
  float weights[8];
  blurWeights(kernel, gaussian, weights);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  program_->use();
  program_->set("u_positions", 0);
  program_->set("u_depth", 1);
  program_->set("u_lightViewProj", lightViewProj);
  program_->set("u_bias", biasTexels * texelWorld * 0.5f * glm::length(depthRow));
  program_->set("u_radius", kernel / 2);
  glProgramUniform1fv(program_->id(), glGetUniformLocation(program_->id(), "u_weights"), 8, weights);
  bindTexture(0, positions);
  bindTexture(1, depthMap);
  glBindSampler(1, sampler_.id());
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(1, 0);
  glEnable(GL_DEPTH_TEST);
  std::vector<float> out(size_t(width) * size_t(height));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, out.data());
  return out;
}

void PrefilterSettings::addTo(Settings& settings) {
  settings.addChoice("prefilter.kernel", kernel, {"1", "3", "5", "7"}, "blur width in texels");
  settings.add("prefilter.gaussian", gaussian, "Gaussian weights (off: box)");
  settings.add("prefilter.mipmaps", mipmaps, "mipmaps with trilinear and 8x anisotropic filtering");
  settings.assign("shadow.map_size=512");
}

void FilteredShadowMapArray::resize(int size, int layers, GLenum format) {
  if (size == size_ && format == format_ && layers == int(layers_.size()) && array_.id()) return;
  layers_.resize(size_t(layers));
  size_ = size, format_ = format;
  array_ = makeTexture(GL_TEXTURE_2D_ARRAY);
  BoundTexture edit(GL_TEXTURE_2D_ARRAY, array_.id());
  allocateTexture(GL_TEXTURE_2D_ARRAY, 1, format, size, size, layers);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void FilteredShadowMapArray::copy(int k) const {
  const FilteredShadowMap& m = layers_.at(size_t(k));
  ReadFramebuffer source(m.texture());  // (glCopyImageSubData is 4.3)
  BoundTexture edit(GL_TEXTURE_2D_ARRAY, array_.id());
  glCopyTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, k, 0, 0, size_, size_);
}

void FilteredShadowMap::resize(int size, const PrefilterOptions& o) {
  const bool same = size == size_ && o.format == options_.format && o.mipmaps == options_.mipmaps && color_.id();
  options_ = o;
  if (same) return;
  size_ = size;
  const int levels = o.mipmaps ? 1 + int(std::log2(size)) : 1;
  color_ = makeTexture(GL_TEXTURE_2D);
  scratch_ = makeTexture(GL_TEXTURE_2D);
  // Anisotropic filtering is an extension before 4.6 (everywhere in practice, macOS included).
  static const bool anisotropic =
      hasGlExtension("GL_ARB_texture_filter_anisotropic") || hasGlExtension("GL_EXT_texture_filter_anisotropic");
  for (const Texture* t : {&color_, &scratch_}) {
    BoundTexture edit(GL_TEXTURE_2D, t->id());
    const bool mipmapped = t == &color_ && o.mipmaps;
    allocateTexture(GL_TEXTURE_2D, mipmapped ? levels : 1, o.format, size, size);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mipmapped ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (mipmapped && anisotropic) glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, 8.0f);
  }
  depth_ = makeTexture2D(GL_DEPTH_COMPONENT32F, size, size);
  fbo_ = makeFramebuffer({color_.id()}, depth_.id());
  scratchFbo_ = makeFramebuffer({scratch_.id()}, 0);
  backFbo_ = makeFramebuffer({color_.id()}, 0);
  if (!vao_.id()) vao_ = makeEmptyVertexArray();
}

void FilteredShadowMap::begin(const float clear[4]) const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size_, size_);
  glClearBufferfv(GL_COLOR, 0, clear);
  glClear(GL_DEPTH_BUFFER_BIT);
}

void FilteredShadowMap::fill(const Program& program) const {
  glBindVertexArray(vao_.id());
  program.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void FilteredShadowMap::prefilter(const Program& blur) {
  if (options_.kernel > 1) {
    const Program& p = blur;
    p.use();
    float weights[8];
    blurWeights(options_.kernel, options_.gaussian, weights);
    glProgramUniform1fv(p.id(), glGetUniformLocation(p.id(), "u_weights"), 8, weights);
    p.set("u_radius", options_.kernel / 2);
    p.set("u_source", 0);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(vao_.id());
    glViewport(0, 0, size_, size_);
    // Two passes of a 1D kernel (horizontal into scratch, vertical back): O(n) taps per texel
    // instead of O(n²) for the 2D kernel.
    const GLuint from[2] = {color_.id(), scratch_.id()};
    const GLuint fbo[2] = {scratchFbo_.id(), backFbo_.id()};
    for (int pass = 0; pass < 2; ++pass) {
      glProgramUniform2i(p.id(), glGetUniformLocation(p.id(), "u_axis"), pass == 0, pass == 1);
      bindTexture(0, from[pass]);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo[pass]);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glEnable(GL_DEPTH_TEST);
  }
  if (options_.mipmaps) {
    BoundTexture edit(GL_TEXTURE_2D, color_.id());
    glGenerateMipmap(GL_TEXTURE_2D);
  }
}

}  // namespace wb
