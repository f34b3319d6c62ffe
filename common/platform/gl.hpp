/// @file gl.hpp
/// The OpenGL loader and move-only RAII owners for GL objects.
#pragma once
#include <glad/gl.h>

#include <cstddef>
#include <initializer_list>
#include <utility>
#include <vector>

namespace wb {

/// A move-only owner of one GL object name; `Delete` frees it.
template <void (*Delete)(GLuint)>
class GlObject {
 public:
  GlObject() = default;
  /// Takes ownership of `id`.
  explicit GlObject(GLuint id) : id_(id) {}
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  /// Takes ownership from `o`, leaving it empty.
  GlObject(GlObject&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  /// Frees the current object, then takes ownership from `o`.
  GlObject& operator=(GlObject&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  ~GlObject() { reset(); }
  /// The GL name (0 when empty).
  GLuint id() const { return id_; }
  /// Frees the object now.
  void reset() {
    if (id_) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

/// Deleters for GlObject, one per kind of GL object.
namespace gldelete {
inline void buffer(GLuint id) { glDeleteBuffers(1, &id); }            ///< deletes one buffer
inline void texture(GLuint id) { glDeleteTextures(1, &id); }          ///< deletes one texture
inline void framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }  ///< deletes one framebuffer
inline void vertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }  ///< deletes one vertexArray
inline void program(GLuint id) { glDeleteProgram(id); }               ///< deletes one program
inline void query(GLuint id) { glDeleteQueries(1, &id); }             ///< deletes one query
inline void sampler(GLuint id) { glDeleteSamplers(1, &id); }          ///< deletes one sampler
}  // namespace gldelete

using Buffer = GlObject<gldelete::buffer>;            ///< owns a buffer object
using Texture = GlObject<gldelete::texture>;          ///< owns a texture object
using Framebuffer = GlObject<gldelete::framebuffer>;  ///< owns a framebuffer object
using VertexArray = GlObject<gldelete::vertexArray>;  ///< owns a vertex array object
using ProgramId = GlObject<gldelete::program>;        ///< owns a program object
using Query = GlObject<gldelete::query>;              ///< owns a query object
using Sampler = GlObject<gldelete::sampler>;          ///< owns a sampler object

/// OpenGL 4.1 core (macOS's ceiling) has no direct state access: an object is edited while it is
/// bound. Each of these binds one object for the edits of its scope, then puts back what was bound,
/// so that code drawing with the bound objects is not disturbed.
class BoundTexture {
 public:
  /// Binds texture `id` to `target` on the active unit.
  BoundTexture(GLenum target, GLuint id);
  ~BoundTexture();
  BoundTexture(const BoundTexture&) = delete;
  BoundTexture& operator=(const BoundTexture&) = delete;

 private:
  GLenum target_;
  GLint previous_ = 0;
};
/// Binds a framebuffer for drawing and reading (see BoundTexture).
class BoundFramebuffer {
 public:
  explicit BoundFramebuffer(GLuint id);  ///< binds `id` to GL_FRAMEBUFFER
  ~BoundFramebuffer();
  BoundFramebuffer(const BoundFramebuffer&) = delete;
  BoundFramebuffer& operator=(const BoundFramebuffer&) = delete;

 private:
  GLint draw_ = 0, read_ = 0;
};
/// Binds a vertex array, and puts back the vertex array and GL_ARRAY_BUFFER (see BoundTexture).
class BoundVertexArray {
 public:
  explicit BoundVertexArray(GLuint id);  ///< binds `id`
  ~BoundVertexArray();
  BoundVertexArray(const BoundVertexArray&) = delete;
  BoundVertexArray& operator=(const BoundVertexArray&) = delete;

 private:
  GLint vertexArray_ = 0, arrayBuffer_ = 0;
};

/// A framebuffer of its own, bound for its scope, reading level 0 of texture `id` (made by
/// makeTexture(); `layer` of a 2D array, or face of a cube map): colour attachment 0 as the read
/// buffer, or the depth attachment with `depth`. glReadPixels and glCopyTexSubImage* read from it,
/// where 4.1 has no glGetTextureSubImage or glCopyImageSubData. Throws wb::Error if it is incomplete.
class ReadFramebuffer {
 public:
  /// Makes and binds the framebuffer; the old binding comes back when it goes out of scope.
  explicit ReadFramebuffer(GLuint id, int layer = 0, bool depth = false);
  ReadFramebuffer(const ReadFramebuffer&) = delete;
  ReadFramebuffer& operator=(const ReadFramebuffer&) = delete;

 private:
  Framebuffer fbo_;
  BoundFramebuffer bound_;  // (after fbo_: it puts the old binding back before fbo_ is deleted)
};

/// Creates a texture object of `target` (GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_CUBE_MAP, ...),
/// and remembers its target for bindTexture().
Texture makeTexture(GLenum target);
/// The target a texture made by makeTexture() has; throws wb::Error for another name.
GLenum textureTarget(GLuint id);
/// Binds texture `id` (made by makeTexture(), or 0) to texture unit `unit`, which becomes the active
/// one: glBindTextureUnit, which GL 4.1 lacks.
void bindTexture(GLuint unit, GLuint id);
/// Copies a size.x x size.y rectangle of level 0 of 2D texture `from`, at `at`, into 2D texture `into`
/// at `to` (glCopyImageSubData, which GL 4.1 lacks: through a framebuffer, glCopyTexSubImage2D).
void copyTexture2D(GLuint from, const int (&at)[2], GLuint into, const int (&to)[2], const int (&size)[2]);
/// Writes a w x h rectangle at (x, y) of level 0 of 2D texture `id` from `data` (glTexSubImage2D).
void uploadTexture2D(GLuint id, int x, int y, int w, int h, GLenum format, GLenum type, const void* data);
/// Gives the texture bound to `target` `levels` levels of `internalFormat`, w x h at level 0 (each
/// face of a cube map; `layers` layers of an array), with no data, and no levels beyond them.
/// Throws wb::Error for a format this framework does not use.
void allocateTexture(GLenum target, int levels, GLenum internalFormat, int w, int h, int layers = 1);

/// Creates a 2D texture with storage (one level) and the given filter and wrap modes.
Texture makeTexture2D(GLenum internalFormat, int w, int h, GLenum filter = GL_NEAREST, GLenum wrap = GL_CLAMP_TO_EDGE);
/// Creates a sampler that reads texels as stored: nearest filtering, clamped to the edge, no depth
/// comparison (for reading a depth map that may be set up for a shadow sampler).
Sampler makePlainSampler();
/// Creates a sampler for a depth-compare lookup (sampler2DShadow and its array form): GL_LEQUAL,
/// linear filtering (2x2 PCF in hardware), clamped to a border that reads as lit.
Sampler makeComparisonSampler();
/// Creates an empty vertex array (for draws whose vertex shader makes its own vertices).
VertexArray makeEmptyVertexArray();
/// Creates a buffer with `bytes` of storage, optionally filled from `data`; `usage` is glBufferData's
/// hint (GL_STATIC_DRAW for data written once).
Buffer makeBuffer(size_t bytes, const void* data, GLenum usage = GL_DYNAMIC_DRAW);
/// Creates a framebuffer with the given color attachments and optional depth (or depth + stencil,
/// by the texture's format) attachment; throws
/// wb::Error if it is incomplete.
Framebuffer makeFramebuffer(std::initializer_list<GLuint> colors, GLuint depth);
/// True when the current context lists extension `name` (e.g. "GL_ARB_shader_viewport_layer_array").
bool hasGlExtension(const char* name);

}  // namespace wb
