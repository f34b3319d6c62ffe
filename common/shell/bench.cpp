#include "common/shell/bench.hpp"

#include "common/base/error.hpp"
#include "common/base/settings.hpp"
#include "common/base/strf.hpp"
#include "common/platform/context.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
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
                       "area_diff_%", "area_off_%", "texels_per_pixel"});
  if (o.metrics && seams) h.insert(h.end(), {"seam_err_%", "rest_err_%"});
  for (const auto& p : passes) h.push_back(p + "_gpu_ms");  // in the median round (below)
  // The frame's median over the rounds and its spread (fastest, slowest round), and the frame the
  // passes were timed in, the median of those rounds (with timer queries; the passes fit inside it).
  h.insert(h.end(), {"frame_ms", "frame_ms_min", "frame_ms_max", "timed_frame_ms"});
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
                                 area ? strf("%.2f", 100 * (m.area.lighterRate() + m.area.darkerRate())) : "n/a",
                                 m.texelsPerPixel < 0 ? "n/a" : strf("%.3f", m.texelsPerPixel)};
  if (seams)
    cells.insert(cells.end(), {strf("%.2f", 100 * m.seams.seam.meanAbs()), strf("%.2f", 100 * m.seams.rest.meanAbs())});
  return cells;
}

}  // namespace

void RollingTimes::add(double ms) {
  if (samples_.size() < capacity_)
    samples_.push_back(ms);
  else
    samples_[next_] = ms;
  next_ = (next_ + 1) % capacity_;
}

double RollingTimes::quantile(double q) const {
  if (samples_.empty()) return 0;
  std::vector<double> sorted = samples_;
  std::sort(sorted.begin(), sorted.end());
  return sorted[std::min(sorted.size() - 1, size_t(q * double(sorted.size())))];
}

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

// One row of a sweep: the settings' values, what was measured, and each round's times.
struct SweepRow {
  std::vector<std::string> cells;
  std::optional<MeasureResult> measured;
  std::vector<double> wallMs;                         // per round: the frame, timers off where they perturb
  std::vector<double> timedWallMs;                    // per round: the frame the passes were timed in
  std::vector<std::map<std::string, double>> passMs;  // per round: each pass drawn, its mean
  // The round whose timed frame is the median: its passes are reported, so that they add up to at
  // most its frame (medians taken pass by pass need not).
  size_t medianRound() const {
    std::vector<size_t> order(timedWallMs.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return timedWallMs[a] < timedWallMs[b]; });
    return order[order.size() / 2];
  }
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double wallOf(int frames, GpuTimers& timers, const std::function<void()>& frame) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) frame(), timers.collect(true, true);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / frames;
}

// One round of one row, the settings as they are: a warm-up frame, then `timed` frames on the wall
// clock; where timing passes slows the frame (gpu_timers.hpp: a software renderer), the passes are
// timed in frames of their own, whose wall time is kept too (the passes fit inside it).
void timeRound(int timed, GpuTimers& timers, const std::function<void()>& frame, SweepRow& r) {
  frame();  // warm-up: allocations, first use of a program after the settings changed
  timers.collect(true, false);
  timers.resetStats();
  const bool apart = timers.perturbs();
  timers.enable(!apart);
  const double wall = wallOf(timed, timers, frame);
  timers.enable(true);
  r.wallMs.push_back(wall);
  r.timedWallMs.push_back(apart ? wallOf(timed, timers, frame) : wall);
  r.passMs.emplace_back();
  for (const auto& [name, st] : timers.passes())
    if (st.count) r.passMs.back()[name] = st.mean();
}

// The settings of row n (the last key varies fastest), applied; returns their values.
std::vector<std::string> applyRow(const Options& o, Settings& settings, size_t n) {
  std::vector<std::string> values;
  for (auto it = o.sweeps.rbegin(); it != o.sweeps.rend(); ++it) {
    const std::string& v = it->second[n % it->second.size()];
    settings.assign(it->first + "=" + v);
    values.insert(values.begin(), v);
    n /= it->second.size();
  }
  return values;
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
  std::vector<SweepRow> rows(total);
  // Interleaved rounds (A B C A B C ...), so that a machine that slows down or speeds up during the
  // sweep moves every row alike; the measurements (--metrics) come after the first round, in frames
  // of their own that no timing includes.
  for (int round = 0; round < o.rounds; ++round)
    for (size_t n = 0; n < total; ++n) {
      if (!o.quiet) std::fprintf(stderr, "\rsweep: round %d/%d, row %zu/%zu ", round + 1, o.rounds, n + 1, total);
      rows[n].cells = applyRow(o, settings, n);
      timeRound(std::max(1, o.frames), timers, frame, rows[n]);
      if (o.metrics && round == 0) rows[n].measured = measure();
    }
  if (!o.quiet) std::fprintf(stderr, "\r%*s\r", 40, "");
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
    const size_t mid = r.medianRound();
    for (const auto& name : passNames) {
      const auto found = r.passMs[mid].find(name);
      r.cells.push_back(found == r.passMs[mid].end() ? "-" : strf("%.3f", found->second));
    }
    const auto [lo, hi] = std::minmax_element(r.wallMs.begin(), r.wallMs.end());
    r.cells.insert(r.cells.end(), {strf("%.2f", median(r.wallMs)), strf("%.2f", *lo), strf("%.2f", *hi),
                                   strf("%.2f", r.timedWallMs[mid])});
    row(r.cells, csv);
  }
  if (csv.is_open()) std::printf("wrote %s\n", std::filesystem::absolute(o.sweepCsv).string().c_str());
  return 0;
}

}  // namespace wb
