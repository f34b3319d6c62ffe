#include "common/shader.hpp"

#include "common/error.hpp"
#include "common/exercise_chunks.hpp"
#include "common/include_policy.hpp"
#include "common/variant.hpp"

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

// The text of `file`: its substitute when it has one (hot reload's last good chunks), else its own.
std::string textOf(const fs::path& file, const Substitutes& substitutes) {
  const auto s = substitutes.find(file);
  return s == substitutes.end() ? readFile(file) : s->second;
}

void expand(const std::string& rawText, const fs::path& origin, const std::string& defines,
            const std::vector<fs::path>& path, const Substitutes& substitutes, ShaderSource& src,
            std::ostringstream& out, int depth) {
  if (depth > 16) throw Error(origin.string() + ": #include nested too deeply (a cycle?)");
  const std::string text = withoutBomAndCr(rawText);
  const int index = static_cast<int>(src.files.size());
  src.files.push_back(origin);
  const auto allowed = exerciseIncludes(origin);  // a student's file: only its stub's includes
  static const std::regex includeRe(R"(^\s*#\s*include\s+\"([^\"]+)\")");
  static const std::regex thisFileRe("^#line (\\d+) " + std::to_string(kThisFileSource) + "$");
  std::istringstream in(text);
  // An included file's lines are its own from its first (the top file's #version must come first).
  if (depth > 0) out << "#line 1 " << index << "\n";
  int line = 0;
  for (std::string s; std::getline(in, s);) {
    ++line;
    std::smatch m;
    if (s.rfind("#version", 0) == 0) {
      out << s << "\n" << defines << "#line " << line + 1 << " " << index << "\n";
    } else if (std::regex_search(s, m, includeRe)) {
      fs::path target = allowed ? resolveExerciseInclude(m[1].str(), origin, line, *allowed) : fs::path();
      // The search path comes first, so a solution's or an overlay's exercise.glsl wins over the
      // stub that sits next to the including file.
      if (!allowed) target = origin.parent_path() / m[1].str();
      for (const auto& dir : allowed ? std::vector<fs::path>{} : path)
        if (fs::exists(dir / m[1].str())) {
          target = dir / m[1].str();
          break;
        }
      if (!fs::exists(target)) target = findShaderFile(m[1].str(), path);
      expand(textOf(target, substitutes), target, "", path, substitutes, src, out, depth + 1);
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
                              const std::vector<fs::path>& path, const Substitutes& substitutes) {
  ShaderSource src;
  std::ostringstream out;
  expand(text, origin, defines, path, substitutes, src, out, 0);
  src.text = out.str();
  return src;
}

std::string firstErrorLine(const std::string& message) {
  std::string line = message.substr(0, message.find('\n'));
  if (const auto at = message.find(": error"); at != std::string::npos) {
    const size_t begin = message.rfind('\n', at) == std::string::npos ? 0 : message.rfind('\n', at) + 1;
    line = message.substr(begin, message.find('\n', at) - begin);
  }
  // labs/03_pcf/shaders/exercise.glsl:14, not the checkout's absolute path: short enough to read.
  if (const std::string root = std::string(variant::kSourceDir) + "/"; line.rfind(root, 0) == 0)
    line = line.substr(root.size());
  return line;
}

std::string mapShaderLog(const std::string& log, const std::vector<fs::path>& files) {
  // Mesa writes "2:14(3): error: ...", NVIDIA "2(14) : error ..."; both start with the source number.
  static const std::regex posRe(R"((\d+):(\d+)\((\d+)\)|(\d+)\((\d+)\))");
  std::string out;
  std::istringstream in(log);
  for (std::string s; std::getline(in, s);) {
    std::smatch m;
    if (std::regex_search(s, m, posRe)) {
      const size_t file = std::stoul(m[1].matched ? m[1].str() : m[4].str());
      const std::string line = m[1].matched ? m[2].str() : m[5].str();
      if (file == size_t(kReferenceSource))
        s = "(the reference code of another exercise, which your chunk is compiled with): an error there, "
            "caused by your code (a #define, an unclosed brace?); the message is not shown";
      else if (file < files.size())
        s = m.prefix().str() + files[file].string() + ":" + line + m.suffix().str();
    }
    out += s + "\n";
  }
  return out;
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
      errors += mapShaderLog(log.c_str(), src.files);
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
      sources.emplace_back(stage.type, preprocessShader(inlineText_, stage.file, defines, path));
    } else {
      const fs::path file = findShaderFile(stage.file, path);
      sources.emplace_back(stage.type, preprocessShader(textOf(file, substitutes), file, defines, path, substitutes));
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

Program Program::tryLoad(std::vector<ShaderStage> stages, std::string defines) {
  Program p;
  p.stages_ = std::move(stages);
  p.defines_ = std::move(defines);
  try {
    p.program_ = p.build();
    p.rememberGoodChunks();
  } catch (const Error& e) {
    p.error_ = e.what();
  }
  return p;
}

void Program::rememberGoodChunks() {
  goodTexts_.clear();
  for (const auto& input : inputs_) try {
      if (std::string text = readFile(input.first); text.find("// EXERCISE ") != std::string::npos)
        goodTexts_[input.first] = std::move(text);
    } catch (const Error&) {  // gone since: nothing to fall back to
    }
}

// True when exercise `id`'s chunk of `text` still returns the stubs' WB_TODO.
static bool stillStub(const std::string& text, const std::string& id) {
  if (id.empty() || findMarker(text, id) == std::string::npos) return false;
  const auto [begin, end] = chunkRange(text, id);
  return text.find("WB_TODO", begin) < end;
}

// What a fallback build drew, for the panel: `swapped` holds (file, chunk id) pairs.
static std::string fallbackNote(const std::vector<std::pair<fs::path, std::string>>& swapped, bool stub) {
  if (swapped.size() != 1) return "the last version that compiled is drawn";
  const std::string& id = swapped[0].second;
  if (id.empty())
    return "drawn with your last helpers that compiled (above the first exercise) and your current exercises";
  return "drawn with your last " + id + " that compiled" + (stub ? " (still the stub: stripes)" : "") +
         " and your current other exercises";
}

bool Program::buildWithLastGoodChunks() {
  std::vector<std::pair<fs::path, std::string>> changed;  // (file, chunk id)
  Substitutes now;
  for (const auto& [file, good] : goodTexts_) try {
      now[file] = readFile(file);
      for (const auto& id : changedChunks(good, now[file])) changed.emplace_back(file, id);
    } catch (const Error&) {
    }
  // Each changed chunk alone from its last good text (the one that broke is found by trying), then
  // all of them: the whole last good text of every exercise file.
  std::vector<std::vector<std::pair<fs::path, std::string>>> tries;
  for (const auto& c : changed) tries.push_back({c});
  if (changed.size() > 1) tries.push_back(changed);
  for (const auto& swap : tries) {
    Substitutes texts;
    for (const auto& [file, good] : goodTexts_) {
      std::set<std::string> ids;
      for (const auto& [f, id] : swap)
        if (f == file) ids.insert(id);
      if (!ids.empty()) texts[file] = withChunksFrom(now[file], good, ids);
    }
    try {
      program_ = build(texts);
    } catch (const Error&) {
      continue;
    }
    fallback_ = fallbackNote(swap, stillStub(goodTexts_[swap[0].first], swap[0].second));
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
    rememberGoodChunks();
    return true;
  } catch (const Error& e) {
    error_ = e.what();  // keep drawing: the broken exercise's last good chunk, or the last good program
    return buildWithLastGoodChunks();
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
