#include "common/exercise/exercise_board.hpp"

#include "common/base/error.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/platform/shader.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <map>
#include <set>

namespace fs = std::filesystem;

namespace wb {
namespace {

// The lab's shaders/`file` as handed out, or "" (then nothing is swapped).
std::string handedOutText(const std::string& file) {
  try {
    return readFile(handedOutShaderFile(file));
  } catch (const Error&) {
    return "";
  }
}

}  // namespace

const char* stateName(ExerciseState state) {
  switch (state) {
    case ExerciseState::Implemented:
      return "implemented";
    case ExerciseState::NotImplemented:
      return "not_implemented";
    case ExerciseState::Failed:
      return "failed";
    case ExerciseState::Unknown:
      break;
  }
  return "unknown";
}

ExerciseBoard::ExerciseBoard(const fs::path& manifest) {
  try {
    auto j = nlohmann::json::parse(readFile(manifest));
    number_ = j.at("lab").get<std::string>().substr(0, 2);
    title_ = j.at("title").get<std::string>();
    lab_ = j.at("lab").get<std::string>();
    if (j.contains("picture")) pictureName_ = j.at("picture").get<std::string>();
    if (!pictureName_.empty()) picture_ = manifest.parent_path() / pictureName_;
    for (const auto& e : j.at("exercises"))
      exercises_.push_back({e.at("id").get<std::string>(),
                            e.at("title").get<std::string>(),
                            {},
                            {},
                            e.value("kind", std::string()) == "hunt"});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "warning: cannot read %s (%s); the exercise list will be empty\n", manifest.string().c_str(),
                 e.what());
  }
}

const ExerciseStatus* ExerciseBoard::next() const {
  for (const auto& e : exercises_)
    if (e.state == ExerciseState::NotImplemented || e.state == ExerciseState::Failed) return &e;
  return nullptr;
}

bool ExerciseBoard::hasHunts() const {
  for (const auto& e : exercises_)
    if (e.hunt) return true;
  return false;
}

ExerciseState ExerciseBoard::stateOf(const std::string& id) const {
  for (const auto& e : exercises_)
    if (e.id == id) return e.state;
  return ExerciseState::Unknown;
}

void ExerciseBoard::set(const std::string& id, ExerciseState state, const std::string& message) {
  for (auto& e : exercises_)
    if (e.id == id) e.state = state, e.message = message;
}

void ExerciseBoard::addProbe(const std::string& id, const std::string& file, const std::string& expression) {
  probes_.push_back({id, file, expression});
}

void ExerciseBoard::probe() {
  // One kernel per file: probe k writes result k, so a file costs one compile however many it has.
  std::map<std::string, std::vector<const Probe*>> byFile;
  for (const auto& p : probes_) {
    if (p.expression.empty()) {  // a stage a kernel cannot include (a geometry shader): read its text
      probeText(p);
      continue;
    }
    byFile[p.file].push_back(&p);
  }
  // Probes may read wb_tex0 (a 2D texture) and wb_tex1 (a cube map, for lab 08's lookups).
  Texture dummy = makeTexture2D(GL_R32F, 1, 1);
  Texture cube = makeTexture(GL_TEXTURE_CUBE_MAP);
  {
    BoundTexture edit(GL_TEXTURE_CUBE_MAP, cube.id());
    allocateTexture(GL_TEXTURE_CUBE_MAP, 1, GL_R32F, 1, 1);
  }
  for (const auto& [file, probes] : byFile) {
    std::string body;
    for (size_t k = 0; k < probes.size(); ++k)
      body += "if (wb_i == " + std::to_string(k) + ") result.x = float(" + probes[k]->expression + ");\n  ";
    try {
      const fs::path path = findShaderFile(file, shaderSearchPath());
      probedFiles_[path] = fs::last_write_time(path);
      const std::string text = readFile(path);
      std::set<std::string> broken;                 // the exercises whose chunks do not compile
      std::map<std::string, std::string> messages;  // and each one's compiler messages, compiled alone
      const int count = int(probes.size());         // (a lambda may not name a structured binding before C++20)
      auto run = [&](const std::string& t) {
        return runGlslKernel(t, path, body, count, 1, {}, {dummy.id(), cube.id()});
      };
      std::vector<glm::vec4> r;
      try {
        r = run(text);
        lastGood_[path] = text;
      } catch (const Error&) {
        // A chunk that does not compile is its exercise's error alone: found by compiling each chunk
        // alone (never from the log), the others are probed with its last good text in its place,
        // as hot reload draws them (shader.hpp), or with the stub's before anything compiled.
        const std::string fallback = lastGood_.count(path) ? lastGood_[path] : handedOutText(file);
        std::map<std::string, std::string> errors;  // each text compiled, and why it did not
        broken = chunksThatDoNotCompile(text, fallback, [&](const std::string& t) {
          return (errors[t] = glslKernelError(t, path, "", 1, {dummy.id(), cube.id()})).empty();
        });
        if (broken.empty()) throw;
        r = run(withChunksFrom(text, fallback, broken));
        for (const auto& id : broken) messages[id] = errors[chunkAlone(text, fallback, id)];  // its own alone
      }
      for (size_t k = 0; k < probes.size(); ++k)
        if (broken.count(probes[k]->id))
          set(probes[k]->id, ExerciseState::Failed, messages[probes[k]->id]);
        else
          set(probes[k]->id, isTodo(r[k].x) ? ExerciseState::NotImplemented : ExerciseState::Implemented,
              isTodo(r[k].x) ? "the GLSL function still returns WB_TODO" : "");
    } catch (const Error& e) {
      for (const auto* p : probes) set(p->id, ExerciseState::Failed, e.what());
    }
  }
}

void ExerciseBoard::probeText(const Probe& p) {
  try {
    const fs::path path = findShaderFile(p.file, shaderSearchPath());
    probedFiles_[path] = fs::last_write_time(path);
    const std::string text = readFile(path);
    const size_t at = findMarker(text, p.id);
    const size_t end = text.find("// EXERCISE ", at == std::string::npos ? 0 : at + 1);
    const std::string chunk = at == std::string::npos ? text : text.substr(at, end - at);
    const bool todo = chunk.find("WB_TODO") != std::string::npos;
    set(p.id, todo ? ExerciseState::NotImplemented : ExerciseState::Implemented,
        todo ? "the shader still holds WB_TODO" : "");
  } catch (const Error& e) {
    set(p.id, ExerciseState::Failed, e.what());
  }
}

bool ExerciseBoard::probedFilesChanged() const {
  for (const auto& [file, time] : probedFiles_) {
    std::error_code ec;
    if (fs::last_write_time(file, ec) != time) return true;
  }
  return false;
}

void ExerciseBoard::printUnfinished() const {
  for (const auto& e : exercises_) {
    if (e.state != ExerciseState::NotImplemented && e.state != ExerciseState::Failed) continue;
    // A stub's message repeats what this line says already ("NOT IMPLEMENTED: exercise 01.1 f"): keep "f".
    std::string why = e.message;
    if (const std::string said = "NOT IMPLEMENTED: exercise " + e.id + " "; why.rfind(said, 0) == 0)
      why = why.substr(said.size()) + " is still the stub";
    std::fprintf(stderr, "Exercise %s (%s) is %s: %s\n", e.id.c_str(), e.title.c_str(),
                 e.state == ExerciseState::Failed ? "failing" : "not implemented yet", why.c_str());
  }
  if (const ExerciseStatus* n = next()) {
    std::string where = "Next: exercise " + n->id + ", in the handout labs/" + lab_ + "/README.md";
    if (!pictureName_.empty()) where += "; the finished lab looks like labs/" + lab_ + "/" + pictureName_;
    std::fprintf(stderr, "%s\n", where.c_str());
  }
}

nlohmann::json ExerciseBoard::toJson() const {
  auto list = nlohmann::json::array();
  for (const auto& e : exercises_)
    list.push_back({{"id", e.id}, {"title", e.title}, {"state", stateName(e.state)}, {"message", e.message}});
  return list;
}

}  // namespace wb
