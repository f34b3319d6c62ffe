#include "common/shell/embedded_lab.hpp"

#include "common/base/variant.hpp"

#include <filesystem>

namespace fs = std::filesystem;

namespace wb {

std::unique_ptr<Lab>* g_hostedLab = nullptr;

// Shader paths, the manifest and error messages are found through wb::variant; while a hosted lab
// is called, they name that lab's folders (restored afterwards, for the host).
class EmbeddedLab::Use {
 public:
  explicit Use(const EmbeddedLab& h)
      : saved_{variant::kLab, variant::kShaderPath, variant::kLabDir, variant::kSolutionDir} {
    variant::kLab = h.labName_.c_str(), variant::kShaderPath = h.shaderPath_.c_str();
    variant::kLabDir = h.labDir_.c_str(), variant::kSolutionDir = h.solutionDir_.c_str();
  }
  ~Use() {
    variant::kLab = saved_[0], variant::kShaderPath = saved_[1];
    variant::kLabDir = saved_[2], variant::kSolutionDir = saved_[3];
  }
  Use(const Use&) = delete;
  Use& operator=(const Use&) = delete;

 private:
  const char* saved_[4];
};

EmbeddedLab::EmbeddedLab(const std::string& lab, MainFunction mainOf, const std::vector<std::string>& sets)
    : labName_(lab) {
  const fs::path root(variant::kSourceDir);
  labDir_ = (root / "labs" / lab).string();
  solutionDir_ = (root / "solutions" / lab).string();
  shaderPath_ = solutionDir_ + "/shaders;" + labDir_ + "/shaders;" + (root / "shaders").string();
  if (!fs::is_directory(solutionDir_)) throw Error("the showcase needs the solutions: " + solutionDir_ + " is missing");
  Use use(*this);
  g_hostedLab = &lab_;
  char name[] = "showcase";
  char* argv[] = {name, nullptr};
  mainOf(1, argv);
  g_hostedLab = nullptr;
  if (!lab_) throw Error("lab " + lab + " was not made (its main() does not call wb::run<Lab>)");
  for (const auto& s : sets) lab_->settings.assign(s);
}

EmbeddedLab::~EmbeddedLab() {
  Use use(*this);  // (its programs and maps go while the host's context lives)
  lab_.reset(), stage_.reset();
}

void EmbeddedLab::render(const Lab& host, float dt) {
  Use use(*this);
  Lab& l = *lab_;
  if (!stage_) {
    l.adoptScene(host.scene, false);
    stage_ = std::make_unique<LabStage>(host.stage().target, host.stage().timers);  // (its exercises: this lab's)
    l.start(*stage_);  // (some labs draw from the exercises' states: start() probes them)
  }
  if (++frames_ % 15 == 0)
    for (auto& p : stage_->programs) p.reloadIfChanged();  // a lecturer may edit a solution's shader live
  for (const auto& p : stage_->programs)
    if (!p.ok()) throw Error(p.error());
  l.camera = host.camera;
  l.update(dt);
  l.render();
}

void EmbeddedLab::ui() {
  Use use(*this);
  if (stage_) lab_->ui();
}

std::vector<std::string> EmbeddedLab::takeWarnings() {
  std::vector<std::string> fresh;
  for (; stage_ && warningsSeen_ < stage_->warnings.size(); ++warningsSeen_)
    fresh.push_back(labName_ + ": " + stage_->warnings[warningsSeen_]);
  return fresh;
}

}  // namespace wb
