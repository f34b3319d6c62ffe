#include "common/exercise/exercise_tape.hpp"

#include "common/base/error.hpp"
#include "common/base/value_codec.hpp"
#include "common/platform/gl.hpp"

#include <fstream>
#include <iterator>

namespace fs = std::filesystem;
using nlohmann::json;

namespace wb {
namespace {

ExerciseState stateFromName(const std::string& name) {
  for (auto s : {ExerciseState::Implemented, ExerciseState::NotImplemented, ExerciseState::Failed})
    if (name == stateName(s)) return s;
  throw Error("unknown exercise state '" + name + "'");
}

}  // namespace

json parseShallowJson(const std::string& text, int maxDepth) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {  // nesting outside strings, before nlohmann recurses into it
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;  // the escaped character
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth) throw Error("JSON nested more than " + std::to_string(maxDepth) + " deep");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return json::parse(text);
}

void ExerciseTape::startRecording(const fs::path& file) { recordFile_ = file; }

void ExerciseTape::startReplay(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot read --replay-exercises file '" + file.string() + "'");
  try {
    const json j = parseShallowJson(std::string(std::istreambuf_iterator<char>(in), {}));
    for (const auto& [id, calls] : j.at("calls").items()) {
      replayed_[id];  // an exercise with no calls is still replayed: as failed, never as the app's own code
      for (const auto& c : calls)
        replayed_[id].push_back({stateFromName(c.at("state").get<std::string>()), c.value("message", std::string()),
                                 c.value("value", json())});
    }
  } catch (const std::exception& e) {
    throw Error("malformed --replay-exercises file '" + file.string() + "': " + e.what());
  }
  replaying_ = true;
}

void ExerciseTape::add(const std::string& id, Call call) {
  auto& calls = recorded_[id];
  // A run that calls an exercise every frame repeats itself: keep the first calls and the last.
  if (calls.size() >= 64) calls.pop_back();
  calls.push_back(std::move(call));
}

ExerciseTape::Call ExerciseTape::next(const std::string& id) {
  const auto& calls = replayed_.at(id);
  if (calls.empty()) return {ExerciseState::Failed, "the recorded run holds no call of this exercise", {}};
  size_t& k = used_[id];
  const Call& c = calls[std::min(k, calls.size() - 1)];
  ++k;
  return c;
}

void ExerciseTape::save() const {
  if (!recording()) return;
  json all = json::object();
  for (const auto& [id, calls] : recorded_)
    for (const auto& c : calls)
      all[id].push_back({{"state", stateName(c.state)}, {"message", c.message}, {"value", c.value}});
  std::ofstream out(recordFile_);
  out << json{{"calls", all}}.dump(-1, ' ', false, json::error_handler_t::replace) << "\n";
  if (!out) throw Error("cannot write --record-exercises file '" + recordFile_.string() + "'");
}

json captureRasterState() {
  GLfloat factor = 0, units = 0;
  GLint cullMode = GL_BACK, frontFace = GL_CCW;
  glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &factor);
  glGetFloatv(GL_POLYGON_OFFSET_UNITS, &units);
  glGetIntegerv(GL_CULL_FACE_MODE, &cullMode);
  glGetIntegerv(GL_FRONT_FACE, &frontFace);
  return {{"offset_fill", glIsEnabled(GL_POLYGON_OFFSET_FILL) == GL_TRUE},
          {"factor", encode(float(factor))},
          {"units", encode(float(units))},
          {"cull", glIsEnabled(GL_CULL_FACE) == GL_TRUE},
          {"cull_mode", cullMode},
          {"front_face", frontFace}};
}

void applyRasterState(const json& s) {
  const GLint mode = s.at("cull_mode").get<GLint>(), front = s.at("front_face").get<GLint>();
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) throw Error("bad recorded cull mode");
  if (front != GL_CW && front != GL_CCW) throw Error("bad recorded front face");
  s.at("offset_fill").get<bool>() ? glEnable(GL_POLYGON_OFFSET_FILL) : glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(decode<float>(s.at("factor")), decode<float>(s.at("units")));
  s.at("cull").get<bool>() ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
  glCullFace(GLenum(mode));
  glFrontFace(GLenum(front));
}

}  // namespace wb
