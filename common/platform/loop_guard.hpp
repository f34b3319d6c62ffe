/// @file loop_guard.hpp
/// A bound on every loop of an exercise's GLSL, the same on every GL implementation: each `for` and
/// `while` condition is wrapped so that one shader invocation stops after kLoopGuardSteps steps of
/// its exercise code's loops. Mesa 22's llvmpipe stopped a loop there by itself; Mesa 25's does not,
/// and a GPU hangs (a laptop's whole display with it). So a loop that never ends gives a wrong
/// picture or value everywhere, which the tests can name, not a hang. Lines and files are kept, so a
/// compile error still names the student's line. Which files are guarded is the exercise floor's
/// decision (SourceRules::guardsLoops, exercise/exercise_source_rules.cpp): the shader loader only
/// applies it.
#pragma once

#include <string>

namespace wb {

/// The most loop steps one invocation of an exercise's GLSL may take, below llvmpipe's own cap
/// (65535 steps of all loops of an invocation), so that the guard, not the implementation, decides
/// everywhere.
constexpr int kLoopGuardSteps = 50000;

/// `text` with every loop condition wrapped in wb_loop() (comments and preprocessor lines untouched),
/// line for line.
std::string guardLoops(const std::string& text);

/// The definition of wb_loop() and its counter, once per shader (an include guard), for the text
/// before the guarded file's first line.
std::string loopGuardPrelude();

}  // namespace wb
