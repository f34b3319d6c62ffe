#include "common/shell/panels.hpp"

#include "common/base/settings.hpp"
#include "common/platform/context.hpp"

#include <imgui.h>

#include <algorithm>

namespace wb {
namespace {

const ImVec4 kRed(1, 0.4f, 0.4f, 1), kGreen(0.5f, 1, 0.5f, 1), kYellow(1, 0.85f, 0.3f, 1), kGrey(0.7f, 0.7f, 0.7f, 1);
const float kWrapEm =
    22;  // the info panel's text width, in font heights: 352 px at 16 px, inside the left 20 % of 1920

// "llvmpipe (LLVM 15.0.6, 256 bits)" -> "llvmpipe": the panel stays narrow; the full name is a tooltip.
std::string shortName(const std::string& renderer) { return renderer.substr(0, renderer.find(" (")); }

std::string clipped(const std::string& s, size_t n) { return s.size() <= n ? s : s.substr(0, n - 3) + "..."; }

void wrappedRed(const std::string& text) {
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * kWrapEm);
  ImGui::TextColored(kRed, "  %s", text.c_str());
  ImGui::PopTextWrapPos();
}

// An ImGui widget per setting (the Settings window); true if any changed.
bool settingsWidgets(const Settings& settings) {
  // One collapsing header per group ("shadow", "bias", ...), in order of first registration; the
  // rarely used groups start closed.
  auto groupOf = [](const Setting& s) { return s.name.substr(0, s.name.find('.')); };
  std::vector<std::string> groups;
  for (const auto& s : settings.all())
    if (std::find(groups.begin(), groups.end(), groupOf(s)) == groups.end()) groups.push_back(groupOf(s));
  bool changed = false;
  for (const auto& g : groups) {
    const bool rare = g == "camera" || g == "alpha" || g == "light";
    if (!ImGui::CollapsingHeader(g.c_str(), rare ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) continue;
    for (const auto& s : settings.all()) {
      if (groupOf(s) != g) continue;
      const char* n = s.name.c_str();
      switch (s.kind) {
        case Setting::Kind::Float:
          changed |= ImGui::SliderFloat(n, static_cast<float*>(s.value), s.min, s.max, "%.4g");
          break;
        case Setting::Kind::Int:
          changed |= ImGui::SliderInt(n, static_cast<int*>(s.value), int(s.min), int(s.max));
          break;
        case Setting::Kind::Bool:
          changed |= ImGui::Checkbox(n, static_cast<bool*>(s.value));
          break;
        case Setting::Kind::Choice: {
          int* v = static_cast<int*>(s.value);
          if (ImGui::BeginCombo(n, s.choices[*v].c_str())) {
            for (int i = 0; i < int(s.choices.size()); ++i)
              if (ImGui::Selectable(s.choices[i].c_str(), i == *v)) {
                *v = i;
                changed = true;
              }
            ImGui::EndCombo();
          }
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.help.c_str());
    }
  }
  return changed;
}

void exerciseRow(const ExerciseStatus& e, const LiveChecks* checks, const std::map<std::string, CheckVerdict>& verdicts,
                 const std::string* symptom, bool unfinished) {
  const char* label = "not run yet";
  ImVec4 c = kGrey;
  if (e.state == ExerciseState::Implemented) label = "implemented, not checked", c = kGrey;
  if (e.hunt && e.state != ExerciseState::Failed)
    label = "bug hunt", c = kYellow;  // working code, judged by its symptom
  const auto v = verdicts.find(e.id);
  if (e.state == ExerciseState::Implemented && v != verdicts.end() && !(checks && checks->running())) {
    // The fast checks' word, never "done" for an answer that fails them.
    if (v->second.status == "passes its tests") label = "passes its checks", c = kGreen;
    if (v->second.status == "wrong") label = "wrong", c = kRed;
    if (v->second.status == "error") label = "error", c = kRed;
    if (v->second.status == "not implemented") label = "not implemented", c = kYellow;
  }
  if (e.state == ExerciseState::NotImplemented) label = "not implemented", c = kYellow;
  if (e.state == ExerciseState::Failed) label = "error (see below)", c = kRed;
  // One short row: the verdict and the start of the title; the whole title and message on hover.
  ImGui::BeginGroup();
  ImGui::TextColored(c, "%s %-17s", e.id.c_str(), label);
  ImGui::SameLine();
  ImGui::TextColored(kGrey, "%s", clipped(e.title, 22).c_str());
  ImGui::EndGroup();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s %s\n%s%s%s(./workbook check %s runs every test)", e.id.c_str(), e.title.c_str(),
                      e.message.c_str(), e.message.empty() ? "" : "\n",
                      e.hunt ? "The handout's scene and settings show the symptom; it is measured on this view\n"
                               "whenever the view, a setting or a shader changes and then holds still.\n"
                             : "",
                      e.id.substr(0, 2).c_str());
  if (e.hunt && symptom) ImGui::TextColored(kGrey, "  %s", symptom->c_str());
  if (e.hunt && symptom && unfinished) ImGui::TextColored(kGrey, "  (with the unfinished exercises above)");
  const bool checkedRed = label == std::string("wrong") || label == std::string("error");  // (by the checks)
  if (checkedRed && e.state == ExerciseState::Implemented) wrappedRed(v->second.headline);
  if (e.state != ExerciseState::Failed) return;
  // A compile error is shown once, under the exercises; a row says nothing more about it.
  const std::string first = firstErrorLine(e.message);
  if (first.find(": error") != std::string::npos) return;
  wrappedRed(first);
}

void infoPanel(const PanelInput& in, PanelState& state) {
  const ExerciseBoard& board = in.board;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  // "Lab 05: VSM" (the title up to its first colon) keeps the panel narrow; one id whatever the title.
  const std::string heading = board.heading();  // (up to the title's own colon, if it has one)
  const std::string title = heading.substr(0, heading.find(':', board.number() == "00" ? 0 : heading.find(':') + 1));
  ImGui::Begin((title + "###info").c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextColored(kGrey, "%.1f fps | %s | %dx%d", ImGui::GetIO().Framerate, shortName(Context::renderer()).c_str(),
                     in.frameSize.x, in.frameSize.y);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", Context::renderer().c_str());
  ImGui::Separator();
  if (in.checks && in.checks->running()) ImGui::TextColored(kGrey, "checking ...");
  if (const std::string note = in.checks ? in.checks->note() : ""; !note.empty()) {
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * kWrapEm);
    ImGui::TextColored(kYellow, "%s", note.c_str());
    ImGui::PopTextWrapPos();
  }
  const auto verdicts = in.checks ? in.checks->verdicts() : std::map<std::string, CheckVerdict>{};
  // A hunt runs in the whole pipeline: its numbers hold the unfinished exercises' pictures too.
  const bool unfinished = std::any_of(board.exercises().begin(), board.exercises().end(), [](const ExerciseStatus& e) {
    return !e.hunt && e.state != ExerciseState::Implemented;
  });
  for (const auto& e : board.exercises()) exerciseRow(e, in.checks, verdicts, in.symptom, unfinished);
  ImGui::Separator();
  if (ImGui::Button("Measure")) state.measureRequested = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("compare this frame with exact (ray-cast) visibility");
  if (!in.timers.passes().empty()) {
    ImGui::SameLine();
    ImGui::Checkbox("GPU ms", &state.showTimes);
  }
  if (!state.measured.empty()) {
    ImGui::SameLine();
    ImGui::Checkbox("heatmap", &state.showHeatmap);
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * kWrapEm);
    ImGui::TextUnformatted(state.measured.c_str());
    ImGui::PopTextWrapPos();
  }
  if (state.showTimes)
    for (const auto& [name, s] : in.timers.passes()) ImGui::Text("  %-12s %7.3f ms", name.c_str(), s.last);
  // Each distinct shader error once (one broken exercise.glsl breaks every program that includes
  // it), with what is on screen meanwhile.
  std::vector<std::string> shown;
  for (const auto& p : in.programs) {
    const std::string where = firstErrorLine(p.error());
    if (p.error().empty() || std::find(shown.begin(), shown.end(), where) != shown.end()) continue;
    shown.push_back(where);
    ImGui::Separator();
    const std::string meanwhile = !p.fallback().empty() ? p.fallback()
                                  : p.ok()              ? "the last version that compiled is drawn"
                                                        : "nothing drawn yet";
    wrappedRed("Shader error (" + meanwhile + "):");
    wrappedRed(where);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.error().c_str());
  }
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * kWrapEm);
  for (const auto& w : in.warnings) ImGui::TextColored(kYellow, "warning: %s", w.c_str());
  ImGui::PopTextWrapPos();
  if (!state.lastScreenshot.empty()) ImGui::TextColored(kGrey, "saved %s", state.lastScreenshot.c_str());
  ImGui::TextColored(kGrey, "H: hide panels | 1-9: views | F12: save");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("drag: orbit | wheel: zoom | 1-9: camera bookmarks | H: hide panels | F12: screenshot");
  ImGui::End();
}

void combo(const char* label, std::string& current, const std::vector<std::string>& options) {
  if (!ImGui::BeginCombo(label, current.c_str())) return;
  for (const auto& o : options)
    if (ImGui::Selectable(o.c_str(), o == current)) current = o;
  ImGui::EndCombo();
}

// Any setting with named choices can be compared: value A on the left, B on the right.
void compareSection(const Settings& settings, CompareChoice& c) {
  if (!ImGui::CollapsingHeader("compare (split screen)")) return;
  std::vector<const Setting*> choices;
  std::vector<std::string> names;
  for (const auto& s : settings.all())
    if (s.kind == Setting::Kind::Choice) choices.push_back(&s), names.push_back(s.name);
  ImGui::Checkbox("split screen", &c.on);
  if (c.key.empty() && !choices.empty())
    c.key = choices.back()->name, c.a = choices.back()->choices.front(), c.b = choices.back()->choices.back();
  const std::string oldKey = c.key;
  combo("setting", c.key, names);
  for (const auto* s : choices)
    if (s->name == c.key) {
      if (c.key != oldKey) c.a = s->choices.front(), c.b = s->choices.back();
      combo("left (A)", c.a, s->choices);
      combo("right (B)", c.b, s->choices);
    }
}

// While exercises are left: the next one, and the handout's picture of the finished lab beside the
// student's own render (the student edition's demo shows something to aim at).
void nextPanel(const PanelInput& in) {
  const ExerciseStatus* next = in.board.next();
  const bool broken = std::any_of(in.programs.begin(), in.programs.end(), [](const Program& p) { return !p.ok(); });
  if (!next || broken) return;  // (a frame that draws nothing says so where this panel would be)
  const float w = 180, h = in.pictureSize.x > 0 ? w * float(in.pictureSize.y) / float(in.pictureSize.x) : 0;
  ImGui::SetNextWindowPos(ImVec2(float(in.frameSize.x) - 8, float(in.frameSize.y) - 8), ImGuiCond_FirstUseEver,
                          ImVec2(1, 1));
  ImGui::Begin("Next", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + w);
  ImGui::TextColored(kYellow, "%s %s", next->id.c_str(), next->title.c_str());
  ImGui::TextColored(kGrey, "handout: labs/%s/README.md", in.board.lab().c_str());
  ImGui::PopTextWrapPos();
  if (in.picture) {
    ImGui::TextColored(kGrey, "the finished lab:");
    ImGui::Image((ImTextureID)(intptr_t)in.picture, ImVec2(w, h),
                 ImVec2(0, 0),  // (void* before 1.91.4, then an integer)
                 ImVec2(1, 1));
  }
  ImGui::End();
}

}  // namespace

void drawPanels(const PanelInput& in, PanelState& state) {
  if (state.hidePanels) {
    ImGui::SetNextWindowPos(ImVec2(8, 8));
    ImGui::Begin("##panels hidden", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted("H: show the panels");
    ImGui::End();
    return;
  }
  infoPanel(in, state);
  nextPanel(in);
  ImGui::SetNextWindowPos(ImVec2(float(in.frameSize.x) - 8, 8), ImGuiCond_FirstUseEver, ImVec2(1, 0));
  ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);  // one line until opened: the scene comes first
  ImGui::Begin("Settings", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::PushItemWidth(150);
  settingsWidgets(in.settings);
  compareSection(in.settings, state.compare);
  in.labUi();
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace wb
