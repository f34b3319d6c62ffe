#include "common/prefilter.hpp"

#include "common/error.hpp"
#include "common/settings.hpp"
#include "common/shader.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

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

void PrefilterSettings::addTo(Settings& settings) {
  settings.addChoice("prefilter.kernel", kernel, {"1", "3", "5", "7"}, "blur width in texels");
  settings.add("prefilter.gaussian", gaussian, "Gaussian weights (off: box)");
  settings.add("prefilter.mipmaps", mipmaps, "mipmaps with trilinear and 8x anisotropic filtering");
  settings.assign("shadow.map_size=512");
}

void FilteredShadowMap::resize(int size, const PrefilterOptions& o) {
  const bool same = size == size_ && o.format == options_.format && o.mipmaps == options_.mipmaps && color_.id();
  options_ = o;
  if (same) return;
  size_ = size;
  const int levels = o.mipmaps ? 1 + int(std::log2(size)) : 1;
  GLuint ids[2] = {0, 0};
  glCreateTextures(GL_TEXTURE_2D, 2, ids);
  color_ = Texture(ids[0]);
  scratch_ = Texture(ids[1]);
  glTextureStorage2D(ids[0], levels, o.format, size, size);
  glTextureStorage2D(ids[1], 1, o.format, size, size);
  for (GLuint id : ids) {
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, id == ids[0] && o.mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  if (o.mipmaps) glTextureParameterf(ids[0], GL_TEXTURE_MAX_ANISOTROPY, 8.0f);
  depth_ = makeTexture2D(GL_DEPTH_COMPONENT32F, size, size);
  fbo_ = makeFramebuffer({color_.id()}, depth_.id());
  scratchFbo_ = makeFramebuffer({scratch_.id()}, 0);
  backFbo_ = makeFramebuffer({color_.id()}, 0);
  if (!vao_.id()) {
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    vao_ = VertexArray(vao);
  }
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
    // Two passes of a 1D kernel: O(n) taps per texel instead of O(n²) for the 2D kernel.
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(vao_.id());
    blur.use();
    const int radius = options_.kernel / 2;
    const float sigma = float(options_.kernel) / 4.0f;
    float weights[8] = {}, total = 0;
    for (int i = -radius; i <= radius; ++i)
      total += options_.gaussian ? std::exp(-float(i * i) / (2 * sigma * sigma)) : 1.0f;
    for (int i = 0; i <= radius; ++i)
      weights[i] = (options_.gaussian ? std::exp(-float(i * i) / (2 * sigma * sigma)) : 1.0f) / total;
    glProgramUniform1fv(blur.id(), glGetUniformLocation(blur.id(), "u_weights"), 8, weights);
    blur.set("u_radius", radius);
    blur.set("u_source", 0);
    glViewport(0, 0, size_, size_);
    glBindFramebuffer(GL_FRAMEBUFFER, scratchFbo_.id());
    glBindTextureUnit(0, color_.id());
    glProgramUniform2i(blur.id(), glGetUniformLocation(blur.id(), "u_axis"), 1, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, backFbo_.id());
    glBindTextureUnit(0, scratch_.id());
    glProgramUniform2i(blur.id(), glGetUniformLocation(blur.id(), "u_axis"), 0, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
  }
  if (options_.mipmaps) glGenerateTextureMipmap(color_.id());
}

}  // namespace wb
