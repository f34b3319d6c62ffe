/// @file variant.hpp
/// Where one build of a lab (student, solution or mutant) finds its files. add_lab() generates the
/// definitions, so the same main.cpp and tests serve every variant.
#pragma once

namespace wb::variant {
extern const char* const kLab;          ///< lab folder name, e.g. "01_depth_map"
extern const char* const kName;         ///< "student", "solution" or "mutant"
extern const char* const kShaderPath;   ///< ';'-separated shader search path, first match wins
extern const char* const kLabDir;       ///< labs/NN_name in the source tree
extern const char* const kSolutionDir;  ///< solutions/NN_name, or "" in the student edition
extern const char* const kSourceDir;    ///< the repository root
extern const char* const kLabExe;       ///< the lab executable of this variant
extern const char* const kSolutionExe;  ///< the solution build of this lab, or "" without solutions
extern const char* const kOutputDir;    ///< where tests write their images
}  // namespace wb::variant
