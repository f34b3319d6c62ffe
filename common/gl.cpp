#include "common/gl.hpp"

#include "common/error.hpp"

#include <string>

namespace wb {

Texture makeTexture2D(GLenum internalFormat, int w, int h, GLenum filter, GLenum wrap) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, 1, internalFormat, w, h);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, filter);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, filter);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, wrap);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, wrap);
  return Texture(id);
}

Sampler makePlainSampler() {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  for (GLenum axis : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glSamplerParameteri(id, axis, GL_CLAMP_TO_EDGE);
  return Sampler(id);
}

Sampler makeComparisonSampler() {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float lit[4] = {1, 1, 1, 1};
  glSamplerParameterfv(id, GL_TEXTURE_BORDER_COLOR, lit);
  return Sampler(id);
}

VertexArray makeEmptyVertexArray() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}

Buffer makeBuffer(size_t bytes, const void* data, GLbitfield flags) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferStorage(id, GLsizeiptr(bytes), data, flags);
  return Buffer(id);
}

bool hasGlExtension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint k = 0; k < count; ++k)
    if (const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(k)));
        e && std::string(e) == name)
      return true;
  return false;
}

Framebuffer makeFramebuffer(std::initializer_list<GLuint> colors, GLuint depth) {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  Framebuffer fbo(id);
  std::vector<GLenum> buffers;
  for (GLuint c : colors) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(buffers.size());
    glNamedFramebufferTexture(id, attachment, c, 0);
    buffers.push_back(attachment);
  }
  if (buffers.empty())
    glNamedFramebufferDrawBuffer(id, GL_NONE);
  else
    glNamedFramebufferDrawBuffers(id, GLsizei(buffers.size()), buffers.data());
  if (depth) {  // a depth + stencil format attaches to both
    GLint format = 0;
    glGetTextureLevelParameteriv(depth, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    const bool stencil = format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8;
    glNamedFramebufferTexture(id, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, depth, 0);
  }
  const GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error("framebuffer incomplete (status 0x" + std::to_string(status) + ")");
  return fbo;
}

}  // namespace wb
