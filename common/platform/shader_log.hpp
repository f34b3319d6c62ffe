/// @file shader_log.hpp
/// What a GLSL compiler says, in one form: every vendor's positions ("2:14(3): error", "2(14) : error",
/// "ERROR: 2:14:") mapped to "file:14: error". The log is shown to people and never decides which
/// exercise is wrong (exercise/exercise_chunks.hpp decides that by compiling).
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace wb {

/// The line of a compiler's message that names file:line ("labs/03_pcf/shaders/exercise.glsl:13: error:
/// ...", relative to the checkout), or its first line.
std::string firstErrorLine(const std::string& message);

/// Rewrites compiler positions into "shaders/exercise.glsl:14: error: ..." whichever vendor wrote
/// them: Mesa "2:14(3): error: ...", NVIDIA "2(14) : error C0000: ...", and glslang's form, which
/// AMD, Intel on Windows and Apple print too, "ERROR: 2:14: ..." (the fixtures in
/// tests/framework/fixtures/compiler_logs/ hold real lines of each). `files[N]` is source N; a
/// message about a source number in `unquoted` is replaced by what it says there.
std::string mapShaderLog(const std::string& log, const std::vector<std::filesystem::path>& files,
                         const std::map<int, std::string>& unquoted = {});

/// A stand-in for other vendors' compilers on this one, for tests: with WB_SHADER_LOG_AS=nvidia (or
/// glslang), Mesa's `log` is rewritten in that vendor's syntax and led by a follow-on error at line 1
/// of every source it names, as NVIDIA reports errors in functions that are fine; a reader of the
/// log alone then blames the wrong place. Without it, `log` as it is. The verdict stays the driver's.
std::string logAsVendor(const std::string& log);

}  // namespace wb
