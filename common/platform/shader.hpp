/// @file shader.hpp
/// GLSL programs loaded from files on a search path, with `#include "…"`, injected `#define`s,
/// errors mapped back to the original file and line, and hot reload that keeps the last good program.
#pragma once
#include "common/platform/gl.hpp"
#include "common/platform/shader_log.hpp"  // mapShaderLog(), firstErrorLine()

#include <glm/mat4x4.hpp>

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace wb {

/// One stage of a program: its type and its file name, looked up on the search path.
struct ShaderStage {
  GLenum type;       ///< GL_VERTEX_SHADER, GL_GEOMETRY_SHADER or GL_FRAGMENT_SHADER
  std::string file;  ///< e.g. "depth.frag"; resolved on shaderSearchPath()
};

/// Reads a whole file; throws wb::Error naming it if it cannot be read.
std::string readFile(const std::filesystem::path& file);

/// This build's shader search path: $WB_SHADER_OVERLAY (if set), then the variant's folders.
std::vector<std::filesystem::path> shaderSearchPath();

/// Finds `name` on `path` (first match wins); throws wb::Error naming every folder searched.
std::filesystem::path findShaderFile(const std::string& name, const std::vector<std::filesystem::path>& path);

/// GLSL text after include expansion, with the list of files it came from (index = source number).
struct ShaderSource {
  std::string text;                          ///< the expanded source, ready for glShaderSource
  std::vector<std::filesystem::path> files;  ///< files read; `#line L N` refers to files[N]
  /// Source numbers whose compiler messages are not quoted, with what to say instead (text the
  /// reader must not see, such as a reference put in by the exercise floor).
  std::map<int, std::string> unquoted;
};

/// Texts to read instead of files' own, by path (hot reload's last good texts).
using Substitutes = std::map<std::filesystem::path, std::string>;

/// What a floor above decides about the GLSL files a program reads: where an include may resolve,
/// and what to build when an edit stops compiling. The exercise floor's rules for students' files
/// are exercise/exercise_source_rules.hpp; a program without rules includes from the including
/// file's folder and the search path, and keeps its last good program when an edit breaks it.
class SourceRules {
 public:
  virtual ~SourceRules() = default;
  /// Where `#include "name"` at `origin`:`line` resolves, when these rules govern `origin`'s
  /// includes; std::nullopt leaves it to the search path. Throws wb::Error to refuse it.
  virtual std::optional<std::filesystem::path> resolveInclude(const std::string& name,
                                                              const std::filesystem::path& origin, int line) const = 0;
  /// True when a file read at a good build should be remembered for fallbacks().
  virtual bool remembers(const std::string& text) const = 0;
  /// True when every loop of `file` is to be bounded (loop_guard.hpp): a student's.
  virtual bool guardsLoops(const std::filesystem::path& /*file*/) const { return false; }
  /// One way to build after an edit stopped compiling: texts to read instead of the files' own, and
  /// what the panel says is drawn then.
  struct Fallback {
    Substitutes texts;  ///< by path, as preprocessShader() takes them
    std::string note;   ///< e.g. "drawn with your last 09.3 that compiled and your current other exercises"
  };
  /// The fallbacks to try, in order, from the remembered texts of the last good build and the same
  /// files' texts now.
  virtual std::vector<Fallback> fallbacks(const Substitutes& good, const Substitutes& now) const = 0;
  /// Whether the program would build with these texts instead of the files' own.
  using BuildsFn = std::function<bool(const Substitutes&)>;
  /// After a failed build of a program that read `files`: a line naming what in them keeps it from
  /// building, found with `builds` (never by reading the compiler's log, which every vendor words
  /// differently), or "" when the rules cannot name it.
  virtual std::string blame(const std::vector<std::filesystem::path>& /*files*/, const BuildsFn& /*builds*/) const {
    return "";
  }
};

/// Expands `text` (read from `origin`): inserts `defines` after `#version`, resolves `#include` as
/// `rules` decide, else relative to the including file and then on `path` (an included file in
/// `substitutes` is read from there), and emits `#line` so errors map back.
ShaderSource preprocessShader(const std::string& text, const std::filesystem::path& origin, const std::string& defines,
                              const std::vector<std::filesystem::path>& path, const Substitutes& substitutes = {},
                              const SourceRules* rules = nullptr);

/// A GLSL source number that means "back to this file": the preprocessor turns `#line L 9998` into
/// the including file's own number, so that text spliced into a file keeps its line numbers.
constexpr int kThisFileSource = 9998;

/// Compiles and links preprocessed stages, with `feedback` the outputs that transform feedback
/// captures (interleaved); throws wb::Error with every message mapped to file:line.
ProgramId linkProgram(const std::vector<std::pair<GLenum, ShaderSource>>& stages,
                      const std::vector<std::string>& feedback = {});

/// Defines every program is built with besides its own: the app's present.* settings
/// (WB_PRESENT_SRGB, WB_PRESENT_GRID), compiled in rather than branched on, so that they cost
/// nothing when off (llvmpipe runs both sides of a branch). Returns true when they changed; every
/// program then rebuilds at its next reloadIfChanged().
bool setSharedShaderDefines(const std::string& defines);

/// A linked program built from files. Construction throws wb::Error (with file:line) on failure;
/// reloadIfChanged() never throws and keeps the last good program.
class Program {
 public:
  Program() = default;
  /// Builds the program from files on shaderSearchPath(), with `defines` injected.
  Program(std::vector<ShaderStage> stages, std::string defines = {});
  /// Builds a program from in-memory stages; `origin` names the text in error messages.
  static Program fromSource(GLenum type, const std::string& text, const std::string& origin,
                            const std::string& defines = {});

  /// Like the constructor, but never throws: on failure ok() is false and error() says why, and
  /// reloadIfChanged() retries when a file changes. Labs use this so a broken edit never stops them.
  /// `rules` (kept by pointer: they outlive the program) govern includes and fallbacks.
  static Program tryLoad(std::vector<ShaderStage> stages, std::string defines = {}, const SourceRules* rules = nullptr);
  /// True once a program has been built successfully.
  bool ok() const { return program_.id() != 0; }

  /// Rebuilds if any file it was read from changed, or the shared defines did; returns true when a
  /// new program is in use. When the edit does not compile, the rules' fallbacks are tried (for
  /// an exercise file, its changed chunks one by one with their last good text, so that the
  /// exercises that still compile are drawn as they are now); failing that, the last good program
  /// stays.
  bool reloadIfChanged();
  /// The error of the last failed build ("" when the current program is up to date).
  const std::string& error() const { return error_; }
  /// What is drawn meanwhile when error() is set and a fallback was built (SourceRules::Fallback's
  /// note); "" otherwise.
  const std::string& fallback() const { return fallback_; }
  /// The GL program name.
  GLuint id() const { return program_.id(); }
  /// Binds the program.
  void use() const { glUseProgram(program_.id()); }

  /// Sets a uniform of the bound program by name (missing names are ignored, as GL does).
  void set(const char* name, float v) const;
  void set(const char* name, int v) const;               ///< @copydoc set(const char*,float) const
  void set(const char* name, const glm::vec2& v) const;  ///< @copydoc set(const char*,float) const
  void set(const char* name, const glm::vec3& v) const;  ///< @copydoc set(const char*,float) const
  void set(const char* name, const glm::vec4& v) const;  ///< @copydoc set(const char*,float) const
  void set(const char* name, const glm::mat4& v) const;  ///< @copydoc set(const char*,float) const

 private:
  ProgramId build(const Substitutes& substitutes = {});  // throws wb::Error
  void rememberGoodTexts();  // the texts the rules remember, after a build from the files alone
  bool buildFallback();      // after a failed build; true when a new program is in use
  void blameFailure();       // after a failed build: the rules' blame() first in error_
  std::vector<ShaderStage> stages_;
  std::string builtShared_;  // the shared defines it was built with
  std::string defines_;
  std::string inlineText_;  // for fromSource(): the text of stages_[0]
  std::vector<std::pair<std::filesystem::path, std::filesystem::file_time_type>> inputs_;
  ProgramId program_;
  std::string error_;
  std::string fallback_;
  const SourceRules* rules_ = nullptr;
  Substitutes goodTexts_;  // the remembered files at the last good build
};

}  // namespace wb
