#include "common/platform/texture_io.hpp"

#include "common/base/error.hpp"

namespace wb {

void setTextureParameter(GLuint id, GLenum pname, GLint value) {
  const GLenum target = textureTarget(id);
  BoundTexture edit(target, id);
  glTexParameteri(target, pname, value);
}

void setTextureBorder(GLuint id, const float (&rgba)[4]) {
  const GLenum target = textureTarget(id);
  BoundTexture edit(target, id);
  glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, rgba);
}

GLint textureParameter(GLuint id, GLenum pname) {
  const GLenum target = textureTarget(id);
  BoundTexture read(target, id);
  GLint value = 0;
  glGetTexParameteriv(target, pname, &value);
  return value;
}

namespace {
// Bytes per texel of a format and type the framework moves (a float or a byte per channel).
size_t texelBytes(GLenum format, GLenum type) {
  const size_t channels = format == GL_RGBA ? 4 : format == GL_RGB ? 3 : format == GL_RG ? 2 : 1;
  return channels * (type == GL_UNSIGNED_BYTE ? 1 : 4);
}
}  // namespace

void uploadTextureLayers(GLuint id, int w, int h, int layers, GLenum format, GLenum type, const void* data) {
  const GLenum target = textureTarget(id);
  BoundTexture edit(target, id);
  const auto* bytes = static_cast<const unsigned char*>(data);
  const size_t layerBytes = size_t(w) * size_t(h) * texelBytes(format, type);
  if (target == GL_TEXTURE_2D_ARRAY)
    glTexSubImage3D(target, 0, 0, 0, 0, w, h, layers, format, type, data);
  else if (target == GL_TEXTURE_CUBE_MAP)
    for (int face = 0; face < layers; ++face)
      glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), 0, 0, 0, w, h, format, type,
                      bytes + size_t(face) * layerBytes);
  else if (target == GL_TEXTURE_2D && layers == 1)
    glTexSubImage2D(target, 0, 0, 0, w, h, format, type, data);
  else
    throw Error("uploadTextureLayers: texture " + std::to_string(id) + " is not a 2D texture, 2D array or cube map");
}

void readTexture(GLuint id, int level, GLenum format, GLenum type, void* data) {
  const GLenum target = textureTarget(id);
  BoundTexture read(target, id);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (target != GL_TEXTURE_CUBE_MAP) {
    glGetTexImage(target, level, format, type, data);
    return;
  }
  GLint w = 0, h = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X, level, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X, level, GL_TEXTURE_HEIGHT, &h);
  const size_t faceBytes = size_t(w) * size_t(h) * texelBytes(format, type);
  for (GLenum face = 0; face < 6; ++face)
    glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, level, format, type,
                  static_cast<unsigned char*>(data) + face * faceBytes);
}

void readTextureRect(GLuint id, int x, int y, int layer, int w, int h, GLenum format, GLenum type, void* data) {
  ReadFramebuffer from(id, layer, format == GL_DEPTH_COMPONENT);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, w, h, format, type, data);
}

}  // namespace wb
