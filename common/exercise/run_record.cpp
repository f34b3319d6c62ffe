#include "common/exercise/run_record.hpp"

#include "common/base/error.hpp"
#include "common/platform/shader.hpp"

#include <fstream>

namespace fs = std::filesystem;

namespace wb {

void RunRecord::addOutput(const std::string& kind, const fs::path& path) {
  json_["outputs"].push_back({{"kind", kind}, {"path", fs::absolute(path).string()}});
}

bool RunRecord::write(const fs::path& path) const {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) return false;
    out << json_.dump(2) << "\n";
    if (!out) return false;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  return !ec;
}

RunResult readRunRecord(const fs::path& path) {
  RunResult r;
  try {
    const auto j = nlohmann::json::parse(readFile(path));
    r.status = j.at("status").get<std::string>();
    r.error = j.value("error", "");
    for (const auto& e : j.value("exercises", nlohmann::json::array())) {
      r.exerciseStates[e.at("id").get<std::string>()] = e.at("state").get<std::string>();
      r.exerciseMessages[e.at("id").get<std::string>()] = e.value("message", "");
    }
    if (j.contains("measurement") && j["measurement"].is_object()) {
      const auto& m = j["measurement"];
      auto number = [&](const char* key) -> std::optional<double> {
        if (m.contains(key) && m[key].is_number()) return m[key].get<double>();
        return std::nullopt;
      };
      r.acnePercent = number("acne_percent"), r.leakPercent = number("leak_percent");
      r.gapTexels = number("contact_gap_texels"), r.shadowLightPercent = number("shadow_light_percent");
      r.areaMeanAbsPercent = number("area_mean_abs_percent"), r.areaOffPercent = number("area_off_percent");
      r.seamErrorPercent = number("seam_error_percent"), r.restErrorPercent = number("rest_error_percent");
      r.todoPixels = long(number("todo_pixels").value_or(0));
      for (const auto& p : m.value("penumbra", nlohmann::json::array()))
        r.penumbra.push_back({p.at("distance").get<double>(), p.at("theory").get<double>(), p.at("width").get<double>(),
                              p.at("reference_width").get<double>()});
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error("the run record " + path.string() + " is malformed: " + e.what());
  }
  return r;
}

}  // namespace wb
