#include "common/platform/frame_target.hpp"

namespace wb {

namespace {
Texture makeMultisample(GLenum format, glm::ivec2 size, int samples) {
  Texture texture = makeTexture(GL_TEXTURE_2D_MULTISAMPLE);
  BoundTexture edit(GL_TEXTURE_2D_MULTISAMPLE, texture.id());
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, format, size.x, size.y, GL_TRUE);
  return texture;
}
}  // namespace

void FrameTarget::resize(glm::ivec2 size) {
  if (size == size_ && fbo_.id()) return;
  msSamples_ = 1, msFbo_ = Framebuffer();  // (reallocated at the next clear() if asked for)
  size_ = size;
  color_[0] = makeTexture2D(GL_RGBA8, size.x, size.y);
  color_[1] = makeTexture2D(GL_R32F, size.x, size.y);
  color_[2] = makeTexture2D(GL_RGBA32F, size.x, size.y);
  depthStencil_ = makeTexture2D(GL_DEPTH24_STENCIL8, size.x, size.y);
  fbo_ = makeFramebuffer({color_[0].id(), color_[1].id(), color_[2].id()}, depthStencil_.id());
}

void FrameTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, multisampling_ ? msFbo_.id() : fbo_.id());
  glViewport(0, 0, size_.x, size_.y);
}

void FrameTarget::clear() const {
  multisampling_ = samples_ > 1 && msSamples_ == samples_;
  bind();
  const float sky[4] = {0.55f, 0.65f, 0.78f, 1}, lit = 1, none[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, sky);
  glClearBufferfv(GL_COLOR, 1, &lit);
  glClearBufferfv(GL_COLOR, 2, none);
  glStencilMask(0xFF);  // glClear honours the write masks
  glDepthMask(GL_TRUE);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

void FrameTarget::resolve() {
  if (samples_ > 1 && msSamples_ != samples_) {  // allocated here, the first frame after it was asked for
    const GLenum formats[3] = {GL_RGBA8, GL_R32F, GL_RGBA32F};
    for (int k = 0; k < 3; ++k) msColor_[k] = makeMultisample(formats[k], size_, samples_);
    msDepthStencil_ = makeMultisample(GL_DEPTH24_STENCIL8, size_, samples_);
    msFbo_ = makeFramebuffer({msColor_[0].id(), msColor_[1].id(), msColor_[2].id()}, msDepthStencil_.id());
    msSamples_ = samples_;
  }
  if (!multisampling_) return;
  multisampling_ = false;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, msFbo_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.id());
  for (int k = 0; k < 3; ++k) {
    const GLenum buffer = GLenum(GL_COLOR_ATTACHMENT0 + k);
    glReadBuffer(buffer);
    const GLenum draw[3] = {k == 0 ? buffer : GL_NONE, k == 1 ? buffer : GL_NONE, k == 2 ? buffer : GL_NONE};
    glDrawBuffers(3, draw);  // (fbo_'s: it is the bound draw framebuffer)
    glBlitFramebuffer(0, 0, size_.x, size_.y, 0, 0, size_.x, size_.y,
                      k == 0 ? GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT : GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  const GLenum all[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glDrawBuffers(3, all);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  bind();
}

void FrameTarget::maskDataOutputs(bool masked) const {
  const GLboolean on = masked ? GL_FALSE : GL_TRUE;
  for (GLuint b : {1u, 2u}) glColorMaski(b, on, on, on, on);
}

void FrameTarget::copyColumns(int x, int w, const Texture (&into)[3], bool back) const {
  for (int t = 0; t < 3; ++t) {
    if (back)
      copyTexture2D(into[t].id(), {0, 0}, color_[t].id(), {x, 0}, {w, size_.y});
    else
      copyTexture2D(color_[t].id(), {x, 0}, into[t].id(), {0, 0}, {w, size_.y});
  }
}

std::vector<uint8_t> FrameTarget::readColor() const {
  std::vector<uint8_t> px(size_t(size_.x) * size_t(size_.y) * 4);
  BoundTexture read(GL_TEXTURE_2D, color_[0].id());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  return px;
}

FloatImage FrameTarget::readVisibility() const {
  FloatImage img{size_.x, size_.y, std::vector<float>(size_t(size_.x) * size_t(size_.y))};
  BoundTexture read(GL_TEXTURE_2D, color_[1].id());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, img.pixels.data());
  return img;
}

std::vector<glm::vec4> FrameTarget::readPositions() const {
  std::vector<glm::vec4> p(size_t(size_.x) * size_t(size_.y));
  BoundTexture read(GL_TEXTURE_2D, color_[2].id());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, p.data());
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
