#include "common/platform/gl.hpp"

#include "common/base/error.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

namespace wb {
namespace {

// The query that names what is bound to texture `target`.
GLenum bindingOf(GLenum target) {
  switch (target) {
    case GL_TEXTURE_2D:
      return GL_TEXTURE_BINDING_2D;
    case GL_TEXTURE_2D_ARRAY:
      return GL_TEXTURE_BINDING_2D_ARRAY;
    case GL_TEXTURE_CUBE_MAP:
      return GL_TEXTURE_BINDING_CUBE_MAP;
    case GL_TEXTURE_CUBE_MAP_ARRAY:
      return GL_TEXTURE_BINDING_CUBE_MAP_ARRAY;
    case GL_TEXTURE_2D_MULTISAMPLE:
      return GL_TEXTURE_BINDING_2D_MULTISAMPLE;
    case GL_TEXTURE_3D:
      return GL_TEXTURE_BINDING_3D;
    case GL_TEXTURE_BUFFER:
      return GL_TEXTURE_BINDING_BUFFER;
    default:
      throw Error("no texture binding for target " + std::to_string(target));
  }
}

// A format and type that glTexImage* accepts, with no data, for `internalFormat`.
std::pair<GLenum, GLenum> uploadFormatOf(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_R8:
    case GL_R16F:
    case GL_R32F:
      return {GL_RED, GL_FLOAT};
    case GL_RG8:
    case GL_RG16F:
    case GL_RG32F:
      return {GL_RG, GL_FLOAT};
    case GL_RGB8:
    case GL_RGB16F:
    case GL_RGB32F:
      return {GL_RGB, GL_FLOAT};
    case GL_RGBA8:
    case GL_SRGB8_ALPHA8:
    case GL_RGBA16F:
    case GL_RGBA32F:
      return {GL_RGBA, GL_FLOAT};
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32F:
      return {GL_DEPTH_COMPONENT, GL_FLOAT};
    case GL_DEPTH24_STENCIL8:
      return {GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
    case GL_DEPTH32F_STENCIL8:
      return {GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV};
    default:
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%04X", internalFormat);
      throw Error(std::string("allocateTexture: internal format ") + hex + " is not one the framework uses");
  }
}

}  // namespace

BoundTexture::BoundTexture(GLenum target, GLuint id) : target_(target) {
  glGetIntegerv(bindingOf(target), &previous_);
  glBindTexture(target, id);
}
BoundTexture::~BoundTexture() { glBindTexture(target_, GLuint(previous_)); }

BoundFramebuffer::BoundFramebuffer(GLuint id) {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
  glBindFramebuffer(GL_FRAMEBUFFER, id);
}
BoundFramebuffer::~BoundFramebuffer() {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read_));
}

BoundVertexArray::BoundVertexArray(GLuint id) {
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
  glBindVertexArray(id);
}
BoundVertexArray::~BoundVertexArray() {
  glBindVertexArray(GLuint(vertexArray_));
  glBindBuffer(GL_ARRAY_BUFFER, GLuint(arrayBuffer_));
}

// The target of every texture makeTexture() made (a name GL reuses after a delete is made again).
static std::map<GLuint, GLenum>& textureTargets() {
  static std::map<GLuint, GLenum> targets;
  return targets;
}

Texture makeTexture(GLenum target) {
  GLuint id = 0;
  glGenTextures(1, &id);
  BoundTexture first(target, id);  // (the first bind makes it a texture of `target`)
  textureTargets()[id] = target;
  return Texture(id);
}

GLenum textureTarget(GLuint id) {
  const auto t = textureTargets().find(id);
  if (t == textureTargets().end())
    throw Error("texture " + std::to_string(id) + " was not made by wb::makeTexture: its target is unknown");
  return t->second;
}

void bindTexture(GLuint unit, GLuint id) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(id ? textureTarget(id) : GL_TEXTURE_2D, id);
}

namespace {
GLuint newFramebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return id;
}
}  // namespace

ReadFramebuffer::ReadFramebuffer(GLuint id, int layer, bool depth) : fbo_(newFramebuffer()), bound_(fbo_.id()) {
  const GLenum target = textureTarget(id), attachment = depth ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0;
  if (target == GL_TEXTURE_CUBE_MAP)
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(layer), id, 0);
  else if (target == GL_TEXTURE_2D_ARRAY)
    glFramebufferTextureLayer(GL_FRAMEBUFFER, attachment, id, 0, layer);
  else
    glFramebufferTexture(GL_FRAMEBUFFER, attachment, id, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(depth ? GL_NONE : GL_COLOR_ATTACHMENT0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw Error("texture " + std::to_string(id) + " cannot be read through a framebuffer");
}

void copyTexture2D(GLuint from, const int (&at)[2], GLuint into, const int (&to)[2], const int (&size)[2]) {
  ReadFramebuffer source(from);  // (glCopyTexSubImage2D reads from the read framebuffer)
  BoundTexture edit(GL_TEXTURE_2D, into);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, to[0], to[1], at[0], at[1], size[0], size[1]);
}

void uploadTexture2D(GLuint id, int x, int y, int w, int h, GLenum format, GLenum type, const void* data) {
  BoundTexture edit(GL_TEXTURE_2D, id);
  glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, w, h, format, type, data);
}

void allocateTexture(GLenum target, int levels, GLenum internalFormat, int w, int h, int layers) {
  const auto [format, type] = uploadFormatOf(internalFormat);
  for (int level = 0; level < levels; ++level) {
    const int lw = std::max(1, w >> level), lh = std::max(1, h >> level);
    if (target == GL_TEXTURE_2D_ARRAY)
      glTexImage3D(target, level, GLint(internalFormat), lw, lh, layers, 0, format, type, nullptr);
    else if (target == GL_TEXTURE_CUBE_MAP)
      for (GLenum face = 0; face < 6; ++face)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, level, GLint(internalFormat), lw, lh, 0, format, type,
                     nullptr);
    else
      glTexImage2D(target, level, GLint(internalFormat), lw, lh, 0, format, type, nullptr);
  }
  glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, levels - 1);
}

Texture makeTexture2D(GLenum internalFormat, int w, int h, GLenum filter, GLenum wrap) {
  Texture texture = makeTexture(GL_TEXTURE_2D);
  BoundTexture edit(GL_TEXTURE_2D, texture.id());
  allocateTexture(GL_TEXTURE_2D, 1, internalFormat, w, h);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(wrap));
  return texture;
}

Sampler makePlainSampler() {
  GLuint id = 0;
  glGenSamplers(1, &id);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  for (GLenum axis : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glSamplerParameteri(id, axis, GL_CLAMP_TO_EDGE);
  return Sampler(id);
}

Sampler makeComparisonSampler() {
  GLuint id = 0;
  glGenSamplers(1, &id);
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
  glGenVertexArrays(1, &id);
  BoundVertexArray first(id);  // (glGen* names no object until it is first bound)
  return VertexArray(id);
}

Buffer makeBuffer(size_t bytes, const void* data, GLenum usage) {
  GLuint id = 0;
  glGenBuffers(1, &id);
  GLint previous = 0;                              // (GL_COPY_WRITE_BUFFER: a binding nothing draws with)
  glGetIntegerv(GL_COPY_WRITE_BUFFER, &previous);  // (the binding query: its 4.2 name is ..._BINDING)
  glBindBuffer(GL_COPY_WRITE_BUFFER, id);
  glBufferData(GL_COPY_WRITE_BUFFER, GLsizeiptr(bytes), data, usage);
  glBindBuffer(GL_COPY_WRITE_BUFFER, GLuint(previous));
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
  glGenFramebuffers(1, &id);
  Framebuffer fbo(id);
  BoundFramebuffer edit(id);
  std::vector<GLenum> buffers;
  for (GLuint c : colors) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(buffers.size());
    glFramebufferTexture(GL_FRAMEBUFFER, attachment, c, 0);
    buffers.push_back(attachment);
  }
  if (buffers.empty())
    glDrawBuffer(GL_NONE);
  else
    glDrawBuffers(GLsizei(buffers.size()), buffers.data());
  if (depth) {  // a depth + stencil format attaches to both
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth, 0);
    GLint stencilBits = 0;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                                          &stencilBits);
    if (stencilBits > 0) glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, depth, 0);
  }
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error("framebuffer incomplete (status 0x" + std::to_string(status) + ")");
  return fbo;
}

}  // namespace wb
