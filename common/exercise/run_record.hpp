/// @file run_record.hpp
/// The machine-readable result of one lab run (--record F.json): the exercise states, the
/// measurements, the files written and how the run ended. Tests and the grader read this record,
/// never the text printed for people, so that text can change freely.
#pragma once
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace wb {

/// Builds and writes the record of one run.
class RunRecord {
 public:
  /// Sets a top-level field.
  void set(const std::string& key, nlohmann::json value) { json_[key] = std::move(value); }
  /// Notes a file the run wrote.
  void addOutput(const std::string& kind, const std::filesystem::path& path);
  /// Writes the record to `path` (atomically: a temporary file, then a rename); false on failure.
  bool write(const std::filesystem::path& path) const;
  /// The record so far.
  const nlohmann::json& json() const { return json_; }

 private:
  nlohmann::json json_ = nlohmann::json::object();
};

/// A record as the harness reads it back.
struct RunResult {
  std::string status;                                   ///< "ok", "usage_error", "context_error" or "error"
  std::string error;                                    ///< the error message, if the run failed
  std::map<std::string, std::string> exerciseStates;    ///< id → "implemented", "not_implemented", "failed", ...
  std::map<std::string, std::string> exerciseMessages;  ///< id → why it is not implemented or failed
  std::optional<double> acnePercent;                    ///< measurement (with --metrics)
  std::optional<double> leakPercent;                    ///< measurement (with --metrics)
  std::optional<double> gapTexels;                      ///< measurement, when defined for the light
  std::optional<double> shadowLightPercent;             ///< measurement (with --metrics)
  std::optional<double> areaMeanAbsPercent;             ///< against the area light, when the light has a size
  std::optional<double> areaOffPercent;                 ///< the share of pixels off by more than 0.1, the same
  std::optional<double> seamErrorPercent;               ///< a cube map's mean |error| near its face boundaries
  std::optional<double> restErrorPercent;               ///< the same away from them
  long todoPixels = 0;  ///< pixels that showed a stub's pattern: the measurements say nothing yet
  /// The penumbra probe's slabs: receiver-blocker distance, theory, rendered and reference widths.
  std::vector<std::array<double, 4>> penumbra;
};

/// Reads a record written by RunRecord::write; throws wb::Error if it is missing or malformed.
RunResult readRunRecord(const std::filesystem::path& path);

}  // namespace wb
