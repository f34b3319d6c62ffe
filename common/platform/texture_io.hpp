/// @file texture_io.hpp
/// Moving texels in and out of textures, and editing a texture's parameters, without the direct
/// state access that OpenGL 4.1 core (macOS's ceiling) lacks: each call binds the texture made by
/// wb::makeTexture() for its own scope (BoundTexture), so code drawing with bound textures is not
/// disturbed.
#pragma once
#include "common/platform/gl.hpp"

namespace wb {

/// Sets integer parameter `pname` of texture `id` (glTexParameteri on its own target).
void setTextureParameter(GLuint id, GLenum pname, GLint value);
/// Sets the border colour of texture `id` (GL_TEXTURE_BORDER_COLOR).
void setTextureBorder(GLuint id, const float (&rgba)[4]);
/// Reads integer parameter `pname` of texture `id` (glGetTexParameteriv).
GLint textureParameter(GLuint id, GLenum pname);

/// Writes level 0 of texture `id` whole: w x h texels per layer, `layers` layers (a 2D array's, or
/// a cube map's six faces in GL's order +X, -X, +Y, -Y, +Z, -Z; 1 for a 2D texture), one after
/// another in `data`.
void uploadTextureLayers(GLuint id, int w, int h, int layers, GLenum format, GLenum type, const void* data);

/// Reads level `level` of texture `id` whole into `data` (a cube map's faces one after another, in
/// GL's order): glGetTexImage.
void readTexture(GLuint id, int level, GLenum format, GLenum type, void* data);

/// Reads a w x h rectangle at (x, y) of level 0, layer `layer` (a 2D array's layer or a cube map's
/// face; 0 for a 2D texture) of texture `id` into `data`, through a framebuffer (glReadPixels).
/// `format` GL_DEPTH_COMPONENT reads a depth texture.
void readTextureRect(GLuint id, int x, int y, int layer, int w, int h, GLenum format, GLenum type, void* data);

}  // namespace wb
