#include "common/platform/shader.hpp"

#include "common/base/error.hpp"
#include "common/base/variant.hpp"
#include "common/platform/loop_guard.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace wb {
namespace {

std::vector<fs::path> splitPath(const std::string& s) {
  std::vector<fs::path> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ';');)
    if (!item.empty()) out.emplace_back(item);
  return out;
}

// Appends `text` (source number `index`) to `out`, expanding includes depth-first.
// Files saved on Windows: a UTF-8 byte-order mark and CRLF line ends, which GLSL compilers reject.
std::string withoutBomAndCr(const std::string& text) {
  std::string s = text.rfind("\xEF\xBB\xBF", 0) == 0 ? text.substr(3) : text;
  s.erase(std::remove(s.begin(), s.end(), '\r'), s.end());
  return s;
}

// The text of `file`: its substitute when it has one (hot reload's last good texts), else its own.
std::string textOf(const fs::path& file, const Substitutes& substitutes) {
  const auto s = substitutes.find(file);
  return s == substitutes.end() ? readFile(file) : s->second;
}

// What a preprocessing run reads with: the search path, substitute texts and the rules above.
struct Reading {
  const std::vector<fs::path>& path;
  const Substitutes& substitutes;
  const SourceRules* rules;
};

// Where `#include "name"` at origin:line resolves: as the rules say, else the search path first (so
// that a solution's or an overlay's exercise.glsl wins over the stub beside the including file),
// then the including file's folder.
fs::path includeTarget(const std::string& name, const fs::path& origin, int line, const Reading& r) {
  if (r.rules)
    if (auto ruled = r.rules->resolveInclude(name, origin, line)) return *ruled;
  for (const auto& dir : r.path)
    if (fs::exists(dir / name)) return dir / name;
  if (fs::exists(origin.parent_path() / name)) return origin.parent_path() / name;
  return findShaderFile(name, r.path);  // (throws, naming every folder searched)
}

void expand(const std::string& rawText, const fs::path& origin, const std::string& defines, const Reading& r,
            ShaderSource& src, std::ostringstream& out, int depth) {
  if (depth > 16) throw Error(origin.string() + ": #include nested too deeply (a cycle?)");
  // A file the rules guard (a student's GLSL) has every loop bounded, line for line (loop_guard.hpp).
  const bool exercise = r.rules && r.rules->guardsLoops(origin);
  const std::string text = exercise ? guardLoops(withoutBomAndCr(rawText)) : withoutBomAndCr(rawText);
  const int index = static_cast<int>(src.files.size());
  src.files.push_back(origin);
  // (its definitions come first, or after a #version line, which must precede them)
  const bool versioned = text.rfind("#version", 0) == 0 || text.find("\n#version") != std::string::npos;
  if (exercise && !versioned) out << loopGuardPrelude() << "#line 1 " << index << "\n";
  static const std::regex includeRe(R"(^\s*#\s*include\s+\"([^\"]+)\")");
  static const std::regex thisFileRe("^#line (\\d+) " + std::to_string(kThisFileSource) + "$");
  std::istringstream in(text);
  // An included file's lines are its own from its first (the top file's #version must come first).
  if (depth > 0 && !exercise) out << "#line 1 " << index << "\n";
  int line = 0;
  for (std::string s; std::getline(in, s);) {
    ++line;
    std::smatch m;
    if (s.rfind("#version", 0) == 0) {
      out << s << "\n"
          << defines << (exercise ? loopGuardPrelude() : "") << "#line " << line + 1 << " " << index << "\n";
    } else if (std::regex_search(s, m, includeRe)) {
      const fs::path target = includeTarget(m[1].str(), origin, line, r);
      expand(textOf(target, r.substitutes), target, "", r, src, out, depth + 1);
      out << "#line " << line + 1 << " " << index << "\n";
    } else if (std::regex_search(s, m, thisFileRe)) {
      out << "#line " << m[1].str() << " " << index << "\n";  // (see kThisFileSource)
    } else {
      out << s << "\n";
    }
  }
}

}  // namespace

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw Error("cannot read " + p.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<fs::path> shaderSearchPath() {
  std::vector<fs::path> path;
  if (const char* overlay = std::getenv("WB_SHADER_OVERLAY"); overlay && *overlay) path = splitPath(overlay);
  for (auto& p : splitPath(variant::kShaderPath)) path.push_back(p);
  return path;
}

fs::path findShaderFile(const std::string& name, const std::vector<fs::path>& path) {
  std::string searched;
  for (const auto& dir : path) {
    if (fs::exists(dir / name)) return dir / name;
    searched += "\n  " + dir.string();
  }
  throw Error("shader file '" + name + "' not found; searched:" + searched);
}

ShaderSource preprocessShader(const std::string& text, const fs::path& origin, const std::string& defines,
                              const std::vector<fs::path>& path, const Substitutes& substitutes,
                              const SourceRules* rules) {
  ShaderSource src;
  std::ostringstream out;
  expand(text, origin, defines, Reading{path, substitutes, rules}, src, out, 0);
  src.text = out.str();
  return src;
}

Program::Program(std::vector<ShaderStage> stages, std::string defines)
    : stages_(std::move(stages)), defines_(std::move(defines)) {
  program_ = build();
}

Program Program::fromSource(GLenum type, const std::string& text, const std::string& origin,
                            const std::string& defines) {
  Program p;
  p.stages_ = {{type, origin}};
  p.defines_ = defines;
  p.inlineText_ = text;
  p.program_ = p.build();
  return p;
}

ProgramId linkProgram(const std::vector<std::pair<GLenum, ShaderSource>>& stages,
                      const std::vector<std::string>& feedback) {
  ProgramId program(glCreateProgram());
  std::vector<GLuint> shaders;
  std::string errors;
  for (const auto& [type, src] : stages) {
    GLuint sh = glCreateShader(type);
    const char* text = src.text.c_str();
    glShaderSource(sh, 1, &text, nullptr);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint len = 0;
      glGetShaderiv(sh, GL_INFO_LOG_LENGTH, &len);
      std::string log(std::max(len, 1), '\0');
      glGetShaderInfoLog(sh, len, nullptr, log.data());
      errors += mapShaderLog(logAsVendor(log.c_str()), src.files, src.unquoted);
    }
    glAttachShader(program.id(), sh);
    shaders.push_back(sh);
  }
  if (errors.empty()) {
    std::vector<const char*> names;
    for (const auto& f : feedback) names.push_back(f.c_str());
    if (!names.empty())
      glTransformFeedbackVaryings(program.id(), GLsizei(names.size()), names.data(), GL_INTERLEAVED_ATTRIBS);
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
      GLint len = 0;
      glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
      std::string log(std::max(len, 1), '\0');
      glGetProgramInfoLog(program.id(), len, nullptr, log.data());
      errors = "link error: " + std::string(log.c_str());
    }
  }
  for (GLuint sh : shaders) glDeleteShader(sh);
  if (!errors.empty()) throw Error(errors);
  return program;
}

namespace {
std::string& sharedDefines() {
  static std::string defines;
  return defines;
}
}  // namespace

bool setSharedShaderDefines(const std::string& defines) {
  if (sharedDefines() == defines) return false;
  sharedDefines() = defines;
  return true;
}

ProgramId Program::build(const Substitutes& substitutes) {
  const auto path = shaderSearchPath();
  builtShared_ = sharedDefines();
  const std::string defines = builtShared_ + defines_;
  inputs_.clear();
  std::vector<std::pair<GLenum, ShaderSource>> sources;
  std::string names;
  for (const auto& stage : stages_) {
    if (!inlineText_.empty()) {
      sources.emplace_back(stage.type, preprocessShader(inlineText_, stage.file, defines, path, {}, rules_));
    } else {
      const fs::path file = findShaderFile(stage.file, path);
      sources.emplace_back(stage.type,
                           preprocessShader(textOf(file, substitutes), file, defines, path, substitutes, rules_));
    }
    for (const auto& f : sources.back().second.files)
      if (fs::exists(f)) inputs_.emplace_back(f, fs::last_write_time(f));
    names += (names.empty() ? "" : " + ") + stage.file;
  }
  try {
    return linkProgram(sources);
  } catch (const Error& e) {
    throw Error("shader " + names + " failed to build:\n" + e.what());
  }
}

Program Program::tryLoad(std::vector<ShaderStage> stages, std::string defines, const SourceRules* rules) {
  Program p;
  p.stages_ = std::move(stages);
  p.defines_ = std::move(defines);
  p.rules_ = rules;
  try {
    p.program_ = p.build();
    p.rememberGoodTexts();
  } catch (const Error& e) {
    p.error_ = e.what();
    p.blameFailure();
  }
  return p;
}

void Program::blameFailure() {
  if (!rules_) return;
  std::vector<fs::path> files;
  for (const auto& input : inputs_) files.push_back(input.first);
  const auto inputs = inputs_;  // (a trial build records its own inputs)
  const std::string shared = builtShared_;
  const std::string line = rules_->blame(files, [&](const Substitutes& texts) {
    try {
      build(texts);
      return true;
    } catch (const Error&) {
      return false;
    }
  });
  inputs_ = inputs, builtShared_ = shared;
  if (!line.empty()) error_ = line + "\n" + error_;
}

void Program::rememberGoodTexts() {
  goodTexts_.clear();
  if (!rules_) return;
  for (const auto& input : inputs_) try {
      if (std::string text = readFile(input.first); rules_->remembers(text)) goodTexts_[input.first] = std::move(text);
    } catch (const Error&) {  // gone since: nothing to fall back to
    }
}

bool Program::buildFallback() {
  if (!rules_ || goodTexts_.empty()) return false;
  Substitutes now;
  for (const auto& [file, good] : goodTexts_) try {
      now[file] = readFile(file);
    } catch (const Error&) {
    }
  for (const auto& fallback : rules_->fallbacks(goodTexts_, now)) {
    try {
      program_ = build(fallback.texts);
    } catch (const Error&) {
      continue;
    }
    fallback_ = fallback.note;
    return true;
  }
  return false;
}

bool Program::reloadIfChanged() {
  bool changed = builtShared_ != sharedDefines();
  for (const auto& [file, time] : inputs_) {
    std::error_code ec;
    if (fs::last_write_time(file, ec) != time) changed = true;
  }
  if (!changed) return false;
  fallback_.clear();
  try {
    program_ = build();
    error_.clear();
    rememberGoodTexts();
    return true;
  } catch (const Error& e) {
    error_ = e.what();  // keep drawing: a fallback the rules offer, or the last good program
    blameFailure();
    return buildFallback();
  }
}

void Program::set(const char* n, float v) const { glProgramUniform1f(id(), glGetUniformLocation(id(), n), v); }
void Program::set(const char* n, int v) const { glProgramUniform1i(id(), glGetUniformLocation(id(), n), v); }
void Program::set(const char* n, const glm::vec2& v) const {
  glProgramUniform2fv(id(), glGetUniformLocation(id(), n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec3& v) const {
  glProgramUniform3fv(id(), glGetUniformLocation(id(), n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec4& v) const {
  glProgramUniform4fv(id(), glGetUniformLocation(id(), n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
  glProgramUniformMatrix4fv(id(), glGetUniformLocation(id(), n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace wb
