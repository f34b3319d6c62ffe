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
/// Creates a buffer with `bytes` of immutable storage, optionally filled from `data`.
Buffer makeBuffer(size_t bytes, const void* data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
/// Creates a framebuffer with the given color attachments and optional depth (or depth + stencil,
/// by the texture's format) attachment; throws
/// wb::Error if it is incomplete.
Framebuffer makeFramebuffer(std::initializer_list<GLuint> colors, GLuint depth);
/// True when the current context lists extension `name` (e.g. "GL_ARB_shader_viewport_layer_array").
bool hasGlExtension(const char* name);

}  // namespace wb
