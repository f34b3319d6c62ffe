/// @file include_policy.hpp
/// What a student's GLSL may `#include`. The judge expands the includes of a submission's exercise
/// files itself, as root, so the filesystem's permissions cannot protect anything: an exercise file
/// (exercise.glsl, exercise_layered.geom: the GLSL files a lab's exercises.json names) may include
/// only what the handed-out file includes (the manifest's "glsl_includes"), found only in the
/// public shader folders (the lab's own shaders/ and the framework's shaders/). No solution, held-out
/// file or other copy anywhere on the machine can be reached from it.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace wb {

/// The includes the lab's manifest allows in `file` (e.g. ".../exercise.glsl") when its name is one
/// of the lab's GLSL exercise files; std::nullopt for any other file, which may include freely.
std::optional<std::vector<std::string>> exerciseIncludes(const std::filesystem::path& file);

/// Where `name`, included at `origin`:`line` (an exercise file allowed `allowed`), is found: in the
/// lab's shaders/ or the framework's. Throws wb::Error ("FILE:LINE: error: ...") when the name is
/// not allowed, and says what is.
std::filesystem::path resolveExerciseInclude(const std::string& name, const std::filesystem::path& origin, int line,
                                             const std::vector<std::string>& allowed);

}  // namespace wb
