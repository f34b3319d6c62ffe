#include "common/bench.hpp"

#include "common/context.hpp"
#include "common/error.hpp"
#include "common/settings.hpp"
#include "common/strf.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

namespace wb {
namespace {

// One row of the sweep table, printed as Markdown and (when open) written as CSV.
void row(const std::vector<std::string>& cells, std::ofstream& csv) {
  std::string line = "|";
  for (const auto& c : cells) line += " " + c + " |";
  std::printf("%s\n", line.c_str());
  if (!csv.is_open()) return;
  for (size_t c = 0; c < cells.size(); ++c) csv << (c ? "," : "") << cells[c];
  csv << "\n";
}

// The table's columns; `seams` adds a cube map's seam and rest error.
std::vector<std::string> header(const Options& o, const std::vector<std::string>& passes, bool seams) {
  std::vector<std::string> h;
  for (const auto& sw : o.sweeps) h.push_back(sw.first);
  if (o.metrics)
    h.insert(h.end(), {"acne_%", "leak_%", "contact_gap_texels", "shadow_light_%", "pcf_diff_%", "pcf_lighter_%",
                       "area_diff_%", "area_off_%"});
  if (o.metrics && seams) h.insert(h.end(), {"seam_err_%", "rest_err_%"});
  for (const auto& p : passes) h.push_back(p + "_gpu_ms");
  h.emplace_back("frame_ms");
  return h;
}

std::vector<std::string> measuredCells(const MeasureResult& m, bool seams) {
  const bool ref = m.reference.pixels > 0, area = m.area.pixels > 0;
  std::vector<std::string> cells{strf("%.2f", 100 * m.metrics.acneRate()),
                                 strf("%.2f", 100 * m.metrics.leakRate()),
                                 m.gapTexels < 0 ? "n/a" : strf("%.1f", m.gapTexels),
                                 strf("%.2f", 100 * m.metrics.meanShadowLight()),
                                 ref ? strf("%.2f", 100 * m.reference.meanAbs()) : "n/a",
                                 ref ? strf("%.2f", 100 * m.reference.lighterRate()) : "n/a",
                                 area ? strf("%.2f", 100 * m.area.meanAbs()) : "n/a",
                                 area ? strf("%.2f", 100 * (m.area.lighterRate() + m.area.darkerRate())) : "n/a"};
  if (seams)
    cells.insert(cells.end(), {strf("%.2f", 100 * m.seams.seam.meanAbs()), strf("%.2f", 100 * m.seams.rest.meanAbs())});
  return cells;
}

}  // namespace

void writeBench(const std::string& path, const std::string& lab, glm::ivec2 size, const GpuTimers& timers,
                const WallClock& wall, bool print) {
  std::ofstream csv(path);
  if (!csv) throw UsageError("cannot write --bench file '" + path + "'");
  const std::string renderer = Context::renderer(), where = std::to_string(size.x) + "x" + std::to_string(size.y);
  csv << "lab,renderer,size,pass,gpu_ms_mean,gpu_ms_min,gpu_ms_max,frames\n";
  if (print) {
    std::printf("lab %s on %s, %s, %d frames measured after %d warm-up\n", lab.c_str(), renderer.c_str(), where.c_str(),
                wall.frames, wall.warmup);
    std::printf("  %-14s %10s %10s %10s\n", "pass", "mean ms", "min ms", "max ms");
  }
  for (const auto& [name, s] : timers.passes()) {
    csv << "lab" << lab << ",\"" << renderer << "\"," << where << "," << name << "," << s.mean() << ","
        << (s.count ? s.min : 0) << "," << s.max << "," << s.count << "\n";
    if (print && s.count == 0) std::printf("  %-14s %10s   (not drawn in the measured frames)\n", name.c_str(), "-");
    if (print && s.count > 0) std::printf("  %-14s %10.3f %10.3f %10.3f\n", name.c_str(), s.mean(), s.min, s.max);
  }
  const double frameMs = wall.meanMs();
  csv << "lab" << lab << ",\"" << renderer << "\"," << where << ",frame_wall," << frameMs << ",,," << wall.frames
      << "\n";
  if (print)
    std::printf("  %-14s %10.3f   => %.1f fps\nwrote %s\n", "frame (wall)", frameMs, frameMs > 0 ? 1000 / frameMs : 0.0,
                std::filesystem::absolute(path).string().c_str());
}

namespace {

// One row of a sweep: the settings' values, what was measured, and the mean of each pass and frame.
struct SweepRow {
  std::vector<std::string> cells;
  std::optional<MeasureResult> measured;
  std::vector<std::pair<std::string, double>> passes;  // name, mean ms (passes drawn in this row only)
  double wallMs = 0;
};

// Times `timed` frames of the settings as they are: the wall clock over frames of their own where
// timing passes slows the frame (gpu_timers.hpp), then the passes.
SweepRow timeRow(int timed, GpuTimers& timers, const std::function<void()>& frame) {
  SweepRow r;
  frame();  // warm-up: allocations, first use of a program
  timers.collect(true, false);
  timers.resetStats();
  const bool apart = timers.perturbs();
  timers.enable(!apart);
  const auto t0 = std::chrono::steady_clock::now();
  for (int f = 0; f < timed; ++f) {
    frame();
    timers.collect(true, true);
  }
  r.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / timed;
  timers.enable(true);
  for (int f = 0; apart && f < timed; ++f) {
    frame();
    timers.collect(true, true);
  }
  for (const auto& [name, st] : timers.passes())
    if (st.count) r.passes.emplace_back(name, st.mean());
  return r;
}

}  // namespace

int runSweep(const Options& o, Settings& settings, GpuTimers& timers, const std::function<void()>& frame,
             const std::function<MeasureResult()>& measure) {
  std::ofstream csv;
  if (!o.sweepCsv.empty()) {
    csv.open(o.sweepCsv);
    if (!csv) throw UsageError("cannot write --sweep-csv file '" + o.sweepCsv + "'");
  }
  size_t total = 1;
  for (const auto& sw : o.sweeps) total *= sw.second.size();
  std::vector<SweepRow> rows;
  for (size_t n = 0; n < total; ++n) {
    std::vector<std::string> values;
    size_t k = n;
    for (auto it = o.sweeps.rbegin(); it != o.sweeps.rend(); ++it) {  // the last key varies fastest
      const std::string& v = it->second[k % it->second.size()];
      settings.assign(it->first + "=" + v);
      values.insert(values.begin(), v);
      k /= it->second.size();
    }
    std::fprintf(stderr, "\rsweep %zu/%zu ", n + 1, total);
    rows.push_back(timeRow(std::max(1, o.frames), timers, frame));
    rows.back().cells = values;
    if (o.metrics) rows.back().measured = measure();
  }
  std::fprintf(stderr, "\r%*s\r", 24, "");
  // The table, once every row's passes (a technique may have passes of its own) are known.
  std::vector<std::string> passNames;
  for (const auto& [name, st] : timers.passes()) passNames.push_back(name);
  const bool seams = !rows.empty() && rows[0].measured &&
                     rows[0].measured->seams.seam.pixels + rows[0].measured->seams.rest.pixels > 0;
  const auto h = header(o, passNames, seams);
  row(h, csv);
  std::string rule = "|";
  for (size_t c = 0; c < h.size(); ++c) rule += "---|";
  std::printf("%s\n", rule.c_str());
  for (SweepRow& r : rows) {
    if (r.measured) {
      const auto m = measuredCells(*r.measured, seams);
      r.cells.insert(r.cells.end(), m.begin(), m.end());
    }
    for (const auto& name : passNames) {
      std::string cell = "-";
      for (const auto& [n, ms] : r.passes)
        if (n == name) cell = strf("%.3f", ms);
      r.cells.push_back(cell);
    }
    r.cells.push_back(strf("%.2f", r.wallMs));
    row(r.cells, csv);
  }
  if (csv.is_open()) std::printf("wrote %s\n", std::filesystem::absolute(o.sweepCsv).string().c_str());
  return 0;
}

}  // namespace wb
