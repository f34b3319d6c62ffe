/// @file glsl_harness.hpp
/// Runs GLSL functions on synthetic inputs in a compute shader, and assembles exercise files so an
/// exercise can be run with the solution versions of the others. Tests and the lab's status panel
/// both use it.
#pragma once
#include "common/gl.hpp"

#include <glm/vec4.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace wb {

/// Replaces the chunk of exercise `id` (from its "// EXERCISE NN.k" marker to the next marker) in
/// `base` with the same chunk from `donor`. Throws wb::Error if either text lacks the marker.
std::string takeExerciseChunk(const std::string& base, const std::string& donor, const std::string& id);

/// The exercise GLSL this build would run for exercise `id`: this variant's file, with every other
/// exercise taken from the solution when the solution exists (so one mistake is counted once); all
/// solution when `id` has no chunk in the file (a C++ exercise).
/// `file` is the name on the shader search path, e.g. "exercise.glsl".
std::string isolatedExerciseSource(const std::string& file, const std::string& id);

/// Runs `body` once per invocation `wb_i` in [0, count) in a compute shader that first includes
/// `functions` (read as if it were the file `origin`). The body reads its inputs with IN(k) =
/// inputs[wb_i * stride + k] and writes `vec4 result`. Textures are bound to units 0.. as the
/// uniforms wb_tex0, wb_tex1, ...; a depth texture with a compare sampler bound to unit 7 is
/// `wb_shadow0`. Throws wb::Error with file:line on a compile error.
std::vector<glm::vec4> runGlslKernel(const std::string& functions, const std::filesystem::path& origin,
                                     const std::string& body, int count, int stride,
                                     const std::vector<glm::vec4>& inputs, const std::vector<GLuint>& textures = {});

/// True if `v` is the GLSL stubs' sentinel WB_TODO (see shaders/wb/exercise.glsl).
inline bool isTodo(float v) { return v <= -1e29f; }

}  // namespace wb
