/// @file exercise_source_rules.hpp
/// The exercise floor's rules for GLSL (platform/shader.hpp's SourceRules): an exercise file may
/// include only what its stub includes (include_policy.hpp), and when an edit stops compiling, its
/// changed chunks (exercise_chunks.hpp) are tried one by one with their last good text, so that the
/// exercises that still compile are drawn as they are now. Every program that may read a student's
/// file is built with these rules: the lab's (Lab::loadProgram) and the GLSL harness's.
#pragma once
#include "common/platform/shader.hpp"

namespace wb {

/// The rules, one instance for the whole process (programs keep a pointer to it).
const SourceRules& exerciseSourceRules();

/// The source number of another exercise's reference chunk, which isolation puts into a student's
/// file (glsl_harness.hpp); a compiler message about it is named, never quoted.
constexpr int kReferenceSource = 9999;

/// What a student sees instead of a compiler message about the reference chunk.
extern const char* const kReferenceSourceNote;

}  // namespace wb
