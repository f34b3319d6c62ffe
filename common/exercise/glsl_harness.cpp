#include "common/exercise/glsl_harness.hpp"

#include "common/base/error.hpp"
#include "common/base/variant.hpp"
#include "common/exercise/exercise_chunks.hpp"
#include "common/exercise/exercise_source_rules.hpp"
#include "common/platform/shader.hpp"
#include "common/platform/texture_io.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace wb {

namespace {

// The kernel's vertex shader, one vertex per case (OpenGL 4.1 has no compute shaders): declarations,
// the functions (keeping their own source numbers, 0 = origin, then its includes, so errors name the
// student's file and line), then main(), whose `result` transform feedback captures.
ShaderSource kernelSource(const std::string& functions, const fs::path& origin, const std::string& body, int stride,
                          const std::vector<SamplerType>& types) {
  std::ostringstream src;
  src << "#version 410 core\n"
      << "uniform samplerBuffer wb_in;  // the inputs, a vec4 per texel\n"
      << "out vec4 wb_out;             // the results, captured by transform feedback\n"
      << "uniform sampler2DShadow wb_shadow0;  // a depth-compare sampler on unit 7, if bound\n";
  for (size_t t = 0; t < types.size(); ++t) src << "uniform " << glslSamplerName(types[t]) << " wb_tex" << t << ";\n";
  ShaderSource pre = preprocessShader(functions, origin, "", shaderSearchPath(), {}, &exerciseSourceRules());
  pre.unquoted[kReferenceSource] = kReferenceSourceNote;
  src << "#define IN(k) texelFetch(wb_in, wb_i * " << stride << " + (k))\n"
      << "#line 1 0\n"
      << pre.text << "\n#line 1 " << pre.files.size() << "\n"
      << "void main() {\n  int wb_i = gl_VertexID;\n"
      << "  vec4 result = vec4(0.0);\n  " << body << "\n  wb_out = result;\n}\n";
  pre.files.emplace_back("<harness main>");
  pre.text = src.str();
  return pre;
}

// "0x8513" for a GL enum in a message.
std::string hex(GLint v) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04X", unsigned(v));
  return text;
}

// `mine` with every exercise chunk except `keep`'s that the solution also has swapped for the
// solution's; the preamble (helpers above the first marker) stays the student's. #line keeps the
// compiler's messages on the student's line numbers.
std::string keepOnlyChunk(const std::string& mine, const std::string& solution, const std::string& keep) {
  auto lineAt = [](const std::string& t, size_t pos) { return 1 + std::count(t.begin(), t.begin() + long(pos), '\n'); };
  std::vector<size_t> starts;  // the first character of every marker's line
  for (size_t p = mine.find("// EXERCISE "); p != std::string::npos; p = mine.find("// EXERCISE ", p + 12))
    starts.push_back(p == 0 ? 0 : mine.rfind('\n', p) + 1);
  std::string out = mine.substr(0, starts.empty() ? mine.size() : starts[0]);
  for (size_t k = 0; k < starts.size(); ++k) {
    const size_t begin = starts[k], end = k + 1 < starts.size() ? starts[k + 1] : mine.size();
    const size_t marker = mine.find("// EXERCISE ", begin) + 12;
    const std::string id = mine.substr(marker, mine.find_first_of(" \t\r\n:", marker) - marker);
    // Only the exact id (a marker "// EXERCISE 01" is not 01.3's), and only the first marker of it.
    if (id == keep || findMarker(solution, id) == std::string::npos ||
        findMarker(mine, id) != mine.find("// EXERCISE ", begin)) {
      out += mine.substr(begin, end - begin);
      continue;
    }
    // The solution's chunk under a source number of its own, so that a compiler message about it
    // (the student's chunk can break it, with a #define) is named, never quoted (mapShaderLog).
    const auto [s0, s1] = chunkRange(solution, id);
    out += "#line " + std::to_string(lineAt(solution, s0)) + " " + std::to_string(kReferenceSource) + "\n" +
           solution.substr(s0, s1 - s0);
    if (!out.empty() && out.back() != '\n') out += "\n";
    out += "#line " + std::to_string(lineAt(mine, end)) + " " + std::to_string(kThisFileSource) + "\n";
  }
  return out;
}

}  // namespace

namespace {
// The lab's manifest: exercises.json's "exercises" list (empty when it cannot be read).
nlohmann::json manifestExercises() {
  try {
    return nlohmann::json::parse(readFile(fs::path(variant::kLabDir) / "exercises.json")).at("exercises");
  } catch (const std::exception&) {
    return nlohmann::json::array();
  }
}
}  // namespace

bool isGlslExercise(const std::string& file, const std::string& id) { return glslExerciseFile(id) == file; }

std::string glslExerciseFile(const std::string& id) {
  for (const auto& e : manifestExercises()) {
    const std::string f = e.value("file", "");
    if (e.value("id", "") == id && f.rfind("shaders/", 0) == 0) return f.substr(8);
  }
  return "";
}

std::vector<std::string> glslExerciseFiles() {
  std::vector<std::string> files;
  for (const auto& e : manifestExercises()) {
    const std::string f = e.value("file", "");
    if (f.rfind("shaders/", 0) == 0 && std::find(files.begin(), files.end(), f.substr(8)) == files.end())
      files.push_back(f.substr(8));
  }
  return files;
}

std::string exerciseAtLine(const std::string& file, int line) {
  std::string text, owner;
  int ownerLine = 0;
  for (const auto& e : manifestExercises()) {                // (one read of the manifest)
    if (e.value("file", "") != "shaders/" + file) continue;  // (scene.frag holds no exercise: "")
    try {
      if (text.empty()) text = readFile(submittedShaderFile(file));
    } catch (const std::exception&) {
      return "";
    }
    const std::string id = e.value("id", "");
    const size_t at = findMarker(text, id);
    const int markerLine = at == std::string::npos ? 0 : 1 + int(std::count(text.begin(), text.begin() + at, '\n'));
    if (markerLine > 0 && markerLine <= line && markerLine > ownerLine) owner = id, ownerLine = markerLine;
  }
  return owner;
}

fs::path handedOutShaderFile(const std::string& file) {
  const fs::path exported = fs::path(variant::kSourceDir) / "tests/stubs" / variant::kLab / "shaders" / file;
  return fs::exists(exported) ? exported : fs::path(variant::kLabDir) / "shaders" / file;
}

fs::path submittedShaderFile(const std::string& file) {
  const char* dir = std::getenv("WB_SUBMISSION_DIR");
  if (dir && *dir) return fs::absolute(fs::path(dir) / "shaders" / file);
  return findShaderFile(file, shaderSearchPath());
}

std::string isolatedExerciseSource(const std::string& file, const std::string& id) {
  const std::string mine = readFile(submittedShaderFile(file));
  const fs::path solution = fs::path(variant::kSolutionDir) / "shaders" / file;
  if (*variant::kSolutionDir == '\0' || !fs::exists(solution)) return mine;
  // A C++ exercise has no chunk here: its GLSL is all solution, so a GLSL stub never blocks it.
  if (!isGlslExercise(file, id)) return readFile(solution);
  // Fail closed: without this exercise's marker the student's whole file is what is graded.
  if (findMarker(mine, id) == std::string::npos) return mine;
  // The student's whole file (helpers outside the markers included), with the solution's chunks
  // for the other exercises: a mistake elsewhere then costs only the exercise it is in.
  return keepOnlyChunk(mine, readFile(solution), id);
}

const char* glslSamplerName(SamplerType type) {
  switch (type) {
    case SamplerType::Sampler2D:
      return "sampler2D";
    case SamplerType::Sampler2DShadow:
      return "sampler2DShadow";
    case SamplerType::SamplerCube:
      return "samplerCube";
    case SamplerType::SamplerCubeShadow:
      return "samplerCubeShadow";
    case SamplerType::Sampler2DArray:
      return "sampler2DArray";
    case SamplerType::Sampler2DArrayShadow:
      return "sampler2DArrayShadow";
    case SamplerType::Auto:
      break;
  }
  throw Error("glslSamplerName: SamplerType::Auto has no GLSL name (resolve it with samplerTypeOf())");
}

SamplerType samplerTypeOf(GLuint id) {
  if (id == 0) return SamplerType::Sampler2D;
  const GLenum target = textureTarget(id);
  const bool shadow = target != GL_TEXTURE_3D && target != GL_TEXTURE_BUFFER &&
                      textureParameter(id, GL_TEXTURE_COMPARE_MODE) == GL_COMPARE_REF_TO_TEXTURE;
  switch (target) {
    case GL_TEXTURE_2D:
      return shadow ? SamplerType::Sampler2DShadow : SamplerType::Sampler2D;
    case GL_TEXTURE_CUBE_MAP:
      return shadow ? SamplerType::SamplerCubeShadow : SamplerType::SamplerCube;
    case GL_TEXTURE_2D_ARRAY:
      return shadow ? SamplerType::Sampler2DArrayShadow : SamplerType::Sampler2DArray;
    default:
      throw Error("texture " + std::to_string(id) + " has target " + hex(target) +
                  "; a kernel texture must be GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP or GL_TEXTURE_2D_ARRAY");
  }
}

std::vector<glm::vec4> runGlslKernel(const std::string& functions, const fs::path& origin, const std::string& body,
                                     int count, int stride, const std::vector<glm::vec4>& inputs,
                                     const std::vector<GLuint>& textures) {
  std::vector<KernelTexture> typed;
  for (GLuint id : textures) typed.push_back({id, SamplerType::Auto, 0});
  return runGlslKernelWithSamplers(functions, origin, body, count, stride, inputs, typed);
}

std::string glslKernelError(const std::string& functions, const fs::path& origin, const std::string& body, int stride,
                            const std::vector<GLuint>& textures) {
  try {
    runGlslKernel(functions, origin, body, 0, stride, {}, textures);
    return "";
  } catch (const Error& e) {
    return e.what();
  }
}

namespace {
double g_lastKernelMs = 0.0;
}  // namespace

double lastKernelMilliseconds() { return g_lastKernelMs; }

std::vector<glm::vec4> runGlslKernelWithSamplers(const std::string& functions, const fs::path& origin,
                                                 const std::string& body, int count, int stride,
                                                 const std::vector<glm::vec4>& inputs,
                                                 const std::vector<KernelTexture>& textures) {
  std::vector<SamplerType> types;
  for (const auto& t : textures) types.push_back(t.type == SamplerType::Auto ? samplerTypeOf(t.id) : t.type);
  ProgramId prog;
  try {
    prog = linkProgram({{GL_VERTEX_SHADER, kernelSource(functions, origin, body, stride, types)}}, {"wb_out"});
  } catch (const Error& e) {
    // Mesa drops what follows a loop that can never end, the captured output included.
    if (std::string(e.what()).find("varying wb_out undeclared") != std::string::npos)
      throw Error(
          "your code never returns: the compiler found a loop that cannot end (does its counter "
          "change?) and removed everything after it (its words: " +
          firstErrorLine(e.what()) + ")");
    throw Error(std::string("compile error:\n") + e.what());
  }

  std::vector<glm::vec4> padded = inputs;
  padded.resize(std::max<size_t>(inputs.size(), 1));
  Buffer in = makeBuffer(padded.size() * sizeof(glm::vec4), padded.data(), GL_STATIC_DRAW);
  Buffer out = makeBuffer(size_t(std::max(count, 1)) * sizeof(glm::vec4), nullptr, GL_DYNAMIC_READ);
  Texture inTexels = makeTexture(GL_TEXTURE_BUFFER);
  {
    BoundTexture edit(GL_TEXTURE_BUFFER, inTexels.id());
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, in.id());
  }
  const GLuint inUnit = 15;  // (16 units a vertex shader has at least: 0.. for the textures, 7 the shadow sampler)
  glUseProgram(prog.id());
  glProgramUniform1i(prog.id(), glGetUniformLocation(prog.id(), "wb_in"), GLint(inUnit));
  glProgramUniform1i(prog.id(), glGetUniformLocation(prog.id(), "wb_shadow0"), 7);
  bindTexture(inUnit, inTexels.id());
  for (size_t t = 0; t < textures.size(); ++t) {
    bindTexture(GLuint(t), textures[t].id);
    if (textures[t].sampler) glBindSampler(GLuint(t), textures[t].sampler);
    const std::string name = "wb_tex" + std::to_string(t);
    glProgramUniform1i(prog.id(), glGetUniformLocation(prog.id(), name.c_str()), GLint(t));
  }
  const VertexArray points = makeEmptyVertexArray();
  BoundVertexArray draw(points.id());
  // A draw needs a complete framebuffer even when it rasterizes nothing (a headless context has none).
  const Texture pixel = makeTexture2D(GL_R8, 1, 1);
  const Framebuffer target = makeFramebuffer({pixel.id()}, 0);
  BoundFramebuffer into(target.id());
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, out.id());
  glEnable(GL_RASTERIZER_DISCARD);
  // Timed on the clock, to glFinish, as the judge compares a student's kernel with the reference's.
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, count);
  glEndTransformFeedback();
  glFinish();
  g_lastKernelMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  glDisable(GL_RASTERIZER_DISCARD);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  std::vector<glm::vec4> result(static_cast<size_t>(count));
  glBindBuffer(GL_COPY_READ_BUFFER, out.id());
  glGetBufferSubData(GL_COPY_READ_BUFFER, 0, GLsizeiptr(count * sizeof(glm::vec4)), result.data());
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  for (size_t t = 0; t < textures.size(); ++t)
    if (textures[t].sampler) glBindSampler(GLuint(t), 0);
  glUseProgram(0);  // (deleting inTexels unbinds it from its unit)
  return result;
}

}  // namespace wb
