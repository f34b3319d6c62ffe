/// @file glsl_harness.hpp
/// Runs GLSL functions on synthetic inputs in a vertex shader with transform feedback, and assembles exercise files so
/// an exercise can be run with the solution versions of the others. Tests and the lab's status panel both use it.
#pragma once
#include "common/base/error.hpp"                // isTodo()
#include "common/exercise/exercise_chunks.hpp"  // findMarker()
#include "common/platform/gl.hpp"

#include <glm/vec4.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace wb {

/// The exercise GLSL this build would run for exercise `id`: this variant's whole file (helpers
/// above the first marker included), with every other exercise's chunk taken from the solution when
/// the solution exists (so one mistake is counted once). The whole file as it is when its marker
/// for `id` is missing (fail closed: never the solution's code for the exercise graded); all
/// solution when `id` is a C++ exercise (so a GLSL stub never blocks it).
/// `file` is the name on the shader search path, e.g. "exercise.glsl".
std::string isolatedExerciseSource(const std::string& file, const std::string& id);
/// The student's shader `file`: from the submission being graded when WB_SUBMISSION_DIR names one
/// (a judge, which was built with the solution, reads the student's GLSL there), else found on the
/// shader search path.
std::filesystem::path submittedShaderFile(const std::string& file);
/// The lab's shaders/`file` as handed out: the student edition's tests/stubs/NN_name/shaders/, else
/// the lab's own folder (the stubs, in the instructor edition). Compile-based isolation swaps chunks
/// for its (exercise_chunks.hpp); it may not exist (a program's own file: no exercise in it).
std::filesystem::path handedOutShaderFile(const std::string& file);
/// The GLSL exercise whose chunk of the student's shaders/`file` holds line `line` (1-based): the
/// one with the nearest "// EXERCISE" marker above it; "" above the first marker or for no such file.
std::string exerciseAtLine(const std::string& file, int line);
/// True when the lab's manifest puts exercise `id` in shaders/`file`.
bool isGlslExercise(const std::string& file, const std::string& id);
/// The shader file (name under shaders/) that the manifest puts GLSL exercise `id` in, e.g.
/// "exercise.glsl" or "exercise_layered.geom"; "" for a C++ exercise or an unknown id.
std::string glslExerciseFile(const std::string& id);
/// Every shader file (name under shaders/) that holds a GLSL exercise of this lab, each once, in
/// the manifest's order.
std::vector<std::string> glslExerciseFiles();

/// The GLSL sampler types a kernel texture can be declared as.
enum class SamplerType {
  Auto,                 ///< from the texture itself: see samplerTypeOf()
  Sampler2D,            ///< sampler2D: texture(s, uv)
  Sampler2DShadow,      ///< sampler2DShadow: texture(s, vec3(uv, ref))
  SamplerCube,          ///< samplerCube: texture(s, dir)
  SamplerCubeShadow,    ///< samplerCubeShadow: texture(s, vec4(dir, ref))
  Sampler2DArray,       ///< sampler2DArray: texture(s, vec3(uv, layer))
  Sampler2DArrayShadow  ///< sampler2DArrayShadow: texture(s, vec4(uv, layer, ref))
};

/// The GLSL spelling of `type`, e.g. "samplerCubeShadow"; throws wb::Error for SamplerType::Auto.
const char* glslSamplerName(SamplerType type);

/// The sampler type of texture `id` from its target (GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP,
/// GL_TEXTURE_2D_ARRAY) and its own GL_TEXTURE_COMPARE_MODE (GL_COMPARE_REF_TO_TEXTURE: the shadow
/// variant); Sampler2D for id 0. A compare mode set on a sampler object is not seen: name the type
/// in a KernelTexture then. Throws wb::Error for another target.
SamplerType samplerTypeOf(GLuint id);

/// One texture of a kernel: `id` bound to the unit of its place in the list and declared as
/// `type`; `sampler`, when not 0, is bound to that unit during the run (and unbound after).
struct KernelTexture {
  GLuint id = 0;                         ///< the texture
  SamplerType type = SamplerType::Auto;  ///< its GLSL sampler type (Auto: samplerTypeOf(id))
  GLuint sampler = 0;                    ///< a sampler object for its unit, or 0 for the texture's own state
};

/// Runs `body` once per case `wb_i` in [0, count) in a vertex shader (one point per case, `result`
/// captured by transform feedback: OpenGL 4.1 has no compute shaders) that first includes
/// `functions` (read as if it were the file `origin`). The body reads its inputs with IN(k) =
/// inputs[wb_i * stride + k] (a texel of a buffer texture) and writes `vec4 result`. Textures are bound to units 0.. as
/// the uniforms wb_tex0, wb_tex1, ..., each declared with the sampler type samplerTypeOf() gives (sampler2D,
/// sampler2DShadow, samplerCube, samplerCubeShadow, sampler2DArray or sampler2DArrayShadow); a depth texture with a
/// compare sampler bound to unit 7 by the caller is `wb_shadow0` (a sampler2DShadow). Throws wb::Error with file:line
/// on a compile error.
std::vector<glm::vec4> runGlslKernel(const std::string& functions, const std::filesystem::path& origin,
                                     const std::string& body, int count, int stride,
                                     const std::vector<glm::vec4>& inputs, const std::vector<GLuint>& textures = {});

/// Why `functions` would not compile in a kernel with `body` (which runs none of it: nothing is
/// drawn), or "" when it compiles: compile-based isolation's compiler (exercise_chunks.hpp).
std::string glslKernelError(const std::string& functions, const std::filesystem::path& origin,
                            const std::string& body = "", int stride = 1, const std::vector<GLuint>& textures = {});

/// The time of the last runGlslKernel() dispatch, in milliseconds (to glFinish, on the clock):
/// the judge holds a student's kernel against the reference's to catch endless loops, which
/// the loop guard (loop_guard.hpp) cuts off after 50000 steps instead of hanging.
double lastKernelMilliseconds();

/// runGlslKernel() with each texture's sampler type (or Auto) and sampler object given.
std::vector<glm::vec4> runGlslKernelWithSamplers(const std::string& functions, const std::filesystem::path& origin,
                                                 const std::string& body, int count, int stride,
                                                 const std::vector<glm::vec4>& inputs,
                                                 const std::vector<KernelTexture>& textures);

/// True if any component of any result is WB_TODO.
inline bool anyTodo(const std::vector<glm::vec4>& results) {
  for (const auto& r : results)
    if (isTodo(r.x) || isTodo(r.y) || isTodo(r.z) || isTodo(r.w)) return true;
  return false;
}

}  // namespace wb
