#include "common/frame_target.hpp"

namespace wb {

void FrameTarget::resize(glm::ivec2 size) {
  if (size == size_ && fbo_.id()) return;
  size_ = size;
  color_[0] = makeTexture2D(GL_RGBA8, size.x, size.y);
  color_[1] = makeTexture2D(GL_R32F, size.x, size.y);
  color_[2] = makeTexture2D(GL_RGBA32F, size.x, size.y);
  depthStencil_ = makeTexture2D(GL_DEPTH24_STENCIL8, size.x, size.y);
  fbo_ = makeFramebuffer({color_[0].id(), color_[1].id(), color_[2].id()}, depthStencil_.id());
}

void FrameTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size_.x, size_.y);
}

void FrameTarget::clear() const {
  bind();
  const float sky[4] = {0.55f, 0.65f, 0.78f, 1}, lit = 1, none[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, sky);
  glClearBufferfv(GL_COLOR, 1, &lit);
  glClearBufferfv(GL_COLOR, 2, none);
  glStencilMask(0xFF);  // glClear honours the write masks
  glDepthMask(GL_TRUE);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

void FrameTarget::maskDataOutputs(bool masked) const {
  const GLboolean on = masked ? GL_FALSE : GL_TRUE;
  for (GLuint b : {1u, 2u}) glColorMaski(b, on, on, on, on);
}

void FrameTarget::copyColumns(int x, int w, const Texture (&into)[3], bool back) const {
  for (int t = 0; t < 3; ++t) {
    if (back)
      glCopyImageSubData(into[t].id(), GL_TEXTURE_2D, 0, 0, 0, 0, color_[t].id(), GL_TEXTURE_2D, 0, x, 0, 0, w, size_.y,
                         1);
    else
      glCopyImageSubData(color_[t].id(), GL_TEXTURE_2D, 0, x, 0, 0, into[t].id(), GL_TEXTURE_2D, 0, 0, 0, 0, w, size_.y,
                         1);
  }
}

std::vector<uint8_t> FrameTarget::readColor() const {
  std::vector<uint8_t> px(size_t(size_.x) * size_t(size_.y) * 4);
  glGetTextureImage(color_[0].id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(px.size()), px.data());
  return px;
}

FloatImage FrameTarget::readVisibility() const {
  FloatImage img{size_.x, size_.y, std::vector<float>(size_t(size_.x) * size_t(size_.y))};
  glGetTextureImage(color_[1].id(), 0, GL_RED, GL_FLOAT, GLsizei(img.pixels.size() * sizeof(float)), img.pixels.data());
  return img;
}

std::vector<glm::vec4> FrameTarget::readPositions() const {
  std::vector<glm::vec4> p(size_t(size_.x) * size_t(size_.y));
  glGetTextureImage(color_[2].id(), 0, GL_RGBA, GL_FLOAT, GLsizei(p.size() * sizeof(glm::vec4)), p.data());
  return p;
}

std::vector<uint8_t> FrameTarget::readStencil() const {
  std::vector<uint8_t> s(size_t(size_.x) * size_t(size_.y));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size_.x, size_.y, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s.data());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  return s;
}

}  // namespace wb
