/// @file error.hpp
/// The exceptions of the workbook. Every message says what went wrong, where, and what to try.
#pragma once
#include <stdexcept>
#include <string>

namespace wb {

/// A failure the user can act on (bad file, bad shader, bad GL state); the lab shows it and goes on.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Bad command-line input or a bad file named on it; labs exit with code 2.
struct UsageError : Error {
  using Error::Error;
};

/// No OpenGL 4.1 context could be created; labs exit with code 3.
struct ContextError : Error {
  using Error::Error;
};

/// Thrown by an exercise stub: "01.3 worldToShadowCoord". The app and the tests report it as
/// "not implemented" instead of showing garbage.
struct NotImplemented : Error {
  /// @param what the exercise ID and function name, e.g. "01.3 worldToShadowCoord"
  explicit NotImplemented(const std::string& what) : Error("NOT IMPLEMENTED: exercise " + what) {}
};

/// True if `v` is the GLSL stubs' sentinel WB_TODO (shaders/wb/exercise.glsl), their way of saying
/// "not implemented" in a value: a probe's result, or a pixel of the visibility a frame wrote.
inline bool isTodo(float v) { return v <= -1e29f; }

}  // namespace wb
