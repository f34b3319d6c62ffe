/// @file variant.hpp
/// Where one build of a lab (student, solution or mutant) finds its files. add_lab() generates the
/// definitions, so the same main.cpp and tests serve every variant. A program that hosts several
/// labs (the showcase) points them at the lab it is calling into (EmbeddedLab).
#pragma once

namespace wb::variant {
extern const char* kLab;          ///< lab folder name, e.g. "01_depth_map"
extern const char* kName;         ///< "student", "solution" or "mutant"
extern const char* kShaderPath;   ///< ';'-separated shader search path, first match wins
extern const char* kLabDir;       ///< labs/NN_name in the source tree
extern const char* kSolutionDir;  ///< solutions/NN_name, or "" in the student edition
extern const char* kSourceDir;    ///< the repository root
extern const char* kLabExe;       ///< the lab executable of this variant
extern const char* kSolutionExe;  ///< the solution build of this lab, or "" without solutions
extern const char* kOutputDir;    ///< where tests write their images
}  // namespace wb::variant
