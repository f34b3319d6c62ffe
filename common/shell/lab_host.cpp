#include "common/shell/lab_host.hpp"

#include "common/base/variant.hpp"
#include "common/exercise/crash_report.hpp"
#include "common/platform/context.hpp"
#include "common/platform/image.hpp"
#include "common/platform/imgui_layer.hpp"
#include "common/shell/lab.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

namespace fs = std::filesystem;

namespace wb {

// ui.scale, or where it is 0, the monitor's content scale, more for a window taller than 1080 rows,
// and a quarter more while presenting (read from the back of a room).
float LabHost::pixelsPerPoint() const {
  const glm::ivec2 pixels = ctx_->framebufferSize(), window = ctx_->windowSize();
  return window.x > 0 && pixels.x > 0 ? float(pixels.x) / float(window.x) : 1.0f;
}

void LabHost::applyUiScale() {
  const float rows = float(ctx_->framebufferSize().y) / ctx_->contentScale();
  // A Retina display: ImGui draws pixelsPerPoint() times larger by itself (its DisplayFramebufferScale);
  // the monitor's content scale (2 there too) must not enlarge the panels a second time.
  const float automatic =
      ctx_->contentScale() / pixelsPerPoint() * std::max(1.0f, rows / 1080.0f) * (step_ > 0 ? 1.25f : 1.0f);
  imgui_->setScale(shared_.uiScale > 0 ? shared_.uiScale : automatic);
}

void LabHost::configure(Lab& lab) {
  shared_.addTo(lab.settings);
  const Options& o = options_;
  for (const auto& s : o.sets) lab.settings.assign(s);
  if (o.compare.on) {  // both values must be valid before anything renders
    const std::string keep = lab.settings.value(o.compare.key);
    for (const auto& v : {o.compare.a, o.compare.b}) lab.settings.assign(o.compare.key + "=" + v);
    lab.settings.assign(o.compare.key + "=" + keep);
  }
  for (const auto& [key, values] : o.sweeps)  // every swept value, before any rendering
    for (const auto& v : values) lab.settings.assign(key + "=" + v);
  for (const auto& s : o.sets) lab.settings.assign(s);
}

void LabHost::loadScene(Lab& lab) {
  const Options& o = options_;
  const fs::path path = o.scene.empty() ? fs::path(variant::kSourceDir) / lab.defaultScene() : fs::path(o.scene);
  Scene scene = Scene::load(path);
  if (o.vary >= 0) varyScene(scene, uint32_t(o.vary));
  lab.adoptScene(std::move(scene), o.names("light.size"));
  if (!shared_.goToBookmark(shared_.bookmark, lab.scene, lab.camera))
    throw UsageError("camera.bookmark=" + std::to_string(shared_.bookmark) + " but " + path.string() + " has " +
                     std::to_string(lab.scene.cameras.size()) + " camera bookmark(s), 1 to " +
                     std::to_string(lab.scene.cameras.size()));
}

int LabHost::runLab(int argc, char** argv, std::unique_ptr<Lab> lab) {
  installCrashReport();  // a crash in an exercise names its file:line
  const std::string exe = fs::path(argv[0]).filename().string();
  const ExerciseBoard exercises(LabStage::exercisesFile());  // the lab's number and title
  RunRecord record;
  record.set("lab", exercises.number());
  record.set("variant", variant::kName);
  Options options;
  for (int a = 1; a + 1 < argc; ++a)  // a record even when the rest of the command line is bad
    if (std::string(argv[a]) == "--record") options.record = argv[a + 1];
  auto fail = [&](int code, const char* status, const std::string& message) {
    std::fprintf(stderr, "%s: %s\n", exe.c_str(), message.c_str());
    record.set("status", status);
    record.set("error", message);
    if (!options.record.empty()) record.write(options.record);
    return code;
  };
  try {
    options = parseCommandLine(argc, argv);
    if (options.help) {
      std::printf("%s", usageText(exe, lab->defaultScene()).c_str());
      return 0;
    }
    if (options.headless && options.screenshot.empty() && options.visibility.empty() && options.bench.empty() &&
        !options.metrics && options.record.empty() && options.sweeps.empty() && options.video.empty())
      options.screenshot = "lab" + exercises.number() + ".png";  // a headless run asked for nothing: a picture
    LabHost app(options);
    app.configure(*lab);
    if (options.listSettings) {
      std::printf("settings of %s:\n", exercises.heading().c_str());
      lab->settings.list(std::cout);
      return 0;
    }
    app.loadScene(*lab);
    app.open(exercises.heading());
    app.host(std::move(lab));
    if (!options.sweeps.empty()) {
      if (const int code = app.sweep(); code != 0) return code;
      record.set("sweep", true);
    } else if (!options.video.empty()) {
      app.recordVideo();
      app.finish(record);
    } else {
      app.loop();
      app.finish(record);
    }
    record.set("status", "ok");
    if (!options.record.empty() && !record.write(options.record))
      return fail(1, "error", "cannot write --record file '" + options.record + "'");
    return 0;
  } catch (const UsageError& e) {
    return fail(2, "usage_error", e.what());
  } catch (const ContextError& e) {
    return fail(3, "context_error", e.what());
  } catch (const std::exception& e) {
    return fail(1, "error", e.what());
  }
}

LabHost::LabHost(const Options& options) : options_(options) {
  if (options_.frames < 0 && !options_.video.empty()) options_.frames = 90;
  if (options_.frames < 0 && (options_.headless || !options_.bench.empty()))
    options_.frames = options_.bench.empty() ? 1 : 60;
  wall_.warmup = options_.bench.empty() ? 0 : std::min(10, options_.frames / 4);
  frameSize_ = options_.size;
  panels_.compare = options_.compare;
#ifndef NDEBUG
  strictGl_ = true;
#endif
  if (const char* strict = std::getenv("WB_STRICT_GL")) strictGl_ = std::string(strict) != "0";
}

void LabHost::open(const std::string& title) {
  ctx_ = Context::create({options_.headless, frameSize_.x, frameSize_.y, title, true, options_.fullscreen});
  fullscreen_ = options_.fullscreen;
  if (!options_.bench.empty() && !options_.headless) glfwSwapInterval(0);  // measure, do not wait for vsync
  if (!ctx_->headless()) imgui_ = std::make_unique<ImGuiLayer>(ctx_->window());
  // Keys are polled once a frame; sticky keys keep a tap shorter than a frame (a presenter's clicker
  // sends Page Down that way) until it is seen.
  if (!ctx_->headless()) glfwSetInputMode(ctx_->window(), GLFW_STICKY_KEYS, GLFW_TRUE);
  debug_ = std::make_unique<DebugViews>();
}

LabHost::~LabHost() = default;

void LabHost::host(std::unique_ptr<Lab> lab) {
  lab_.reset(), stage_.reset();  // the previous lab's GL objects and programs go while the context lives
  measurement_ = Measurement();
  heatmap_.reset();
  lastMeasure_.reset();
  sides_[0] = sides_[1] = LightView{};
  timers_.collect(true, false);
  timers_.clear();
  wall_.sumMs = 0, wall_.frames = 0;
  panels_.measured.clear(), panels_.showHeatmap = false;
  bool known = false;  // a comparison carries over only if the new lab has that setting
  for (const auto& s : lab->settings.all()) known = known || s.name == panels_.compare.key;
  if (!known) panels_.compare = CompareChoice{};
  target_.resize(frameSize_);
  stage_ = std::make_unique<LabStage>(target_, timers_);
  if (!options_.recordExercises.empty()) stage_->tape.startRecording(options_.recordExercises);
  if (!options_.replayExercises.empty()) stage_->tape.startReplay(options_.replayExercises);
  motion_ = SceneMotion();  // (a new scene's lights are its own)
  lab_ = std::move(lab);
  if (ctx_->window()) glfwSetWindowTitle(ctx_->window(), stage_->board.heading().c_str());
  startPresenter();
  applyPresentation();  // (before init(): its programs are built with present.*)
  lab_->start(*stage_);
  // A window checks the exercises in the background (a headless run is what the checks start).
  checks_.reset();
  symptoms_.reset();
  if (imgui_ && stage_->board.hasHunts()) symptoms_ = std::make_unique<SymptomWatch>();
  loadPicture();
  // (the showcase has no exercises to check, and the bug gallery's build is a lecturer's demo)
  if (imgui_ && std::string(variant::kLab) != "00_showcase" && std::string(variant::kName) != "bugs") {
    // (the exercise folder is the first on the variant's shader path: <exercise_dir>/shaders)
    const std::string shaders =
        std::string(variant::kShaderPath).substr(0, std::string(variant::kShaderPath).find(';'));
    checks_ = std::make_unique<LiveChecks>(std::string(variant::kLabExe) + "_tests", variant::kLabExe,
                                           (fs::path(shaders).parent_path() / "exercise.cpp").string());
    checks_->start();
  }
}

void LabHost::loop() {
  auto last = std::chrono::steady_clock::now();
  while (!ctx_->shouldClose() && (options_.frames < 0 || frameIndex_ < options_.frames)) {
    const auto now = std::chrono::steady_clock::now();
    const float dt = options_.headless ? 1.0f / 60 : std::chrono::duration<float>(now - last).count();
    last = now;
    // Where timing a pass slows the frame (gpu_timers.hpp), --bench times passes on odd frames and
    // the frame rate on even ones, and a window times passes only while the panel shows them.
    const bool perturbs = timers_.perturbs(), bench = !options_.bench.empty();
    const bool timed = !perturbs || (bench ? frameIndex_ % 2 == 1 : imgui_ && panels_.showTimes);
    timers_.enable(timed);
    frame(dt);
    if (bench || options_.headless) glFinish();
    const auto end = std::chrono::steady_clock::now();
    const bool record = frameIndex_ >= wall_.warmup;
    if (record && frameIndex_ > 0 && !(perturbs && timed))
      wall_.sumMs += std::chrono::duration<double, std::milli>(end - now).count(), ++wall_.frames;
    timers_.collect(ctx_->headless(), record);
    for (const auto& e : takeGlErrors()) {
      if (strictGl_) throw Error("OpenGL error: " + e);
      stage_->warn("OpenGL error: " + e);
    }
    if (options_.metrics && imgui_ && frameIndex_ == 0) measureNow(true);  // a window shows it as an overlay
    if (measureStep_ && imgui_) measureStep_ = false, stepNumbers_ = Presenter::numbersLine(measureNow(false));
    ++frameIndex_;
  }
}

void LabHost::frame(float dt) {
  if (imgui_) beginUiFrame();
  hotReload();
  applyPresentation();
  stage_->comparison = panels_.compare;
  motion_.apply(shared_, lab_->scene, lab_->camera);
  lab_->update(dt);
  target_.resize(frameSize_);
  drawLab();
  // Shared debug views, drawn into the frame target so screenshots and headless runs show them.
  const FrameShown shown = lab_->shown();
  debug_->draw(shown.debug, shown.light, shown.viewProj, target_, panels_.showHeatmap ? heatmap_.id() : 0);
  if (imgui_) presentWindow();
}

void LabHost::hotReload() {
  // A changed file rebuilds its programs; a failed build keeps the last good program.
  if (frameIndex_ % 15 != 0) return;
  for (auto& p : stage_->programs) reloads_ += p.reloadIfChanged() ? 1 : 0;
  if (checks_) checks_->pollEdits();
  if (stage_->board.probedFilesChanged()) {
    stage_->board.probe();
    if (checks_) checks_->start();
  }
}

void LabHost::drawLab() {
  Lab& lab = *lab_;
  const std::list<Program>& programs = stage_->programs;
  const bool programsOk = std::all_of(programs.begin(), programs.end(), [](const Program& p) { return p.ok(); });
  if (!programsOk && ctx_->headless())
    for (const auto& p : programs)
      if (!p.ok()) throw Error(p.error());
  // The scene: once, or in split-screen comparison twice (left half with value A, right with B).
  split_.render(
      target_, lab.settings, panels_.compare,
      [&] {
        target_.setSamples(shared_.present.msaa ? 4 : 1);
        target_.clear();
        glEnable(GL_DEPTH_TEST);
        if (programsOk) lab.render();
        target_.resolve();
      },
      [&](int side) { sides_[side] = lab.shown().light; }, stretched() ? 0.0f : pixelsPerPoint());
  if (!programsOk) {  // a window whose shaders never compiled says so on the frame, not just sky
    const auto bad = std::find_if(programs.begin(), programs.end(), [](const Program& p) { return !p.ok(); });
    const std::string where = firstErrorLine(bad->error());
    target_.bind();
    const glm::ivec2 size = target_.size();
    const std::string said = "The shaders do not compile: nothing is drawn until they do (save a fix).";
    const float scale = std::min(label_.scaleToFit(said, size.x - 32), label_.scaleToFit(where, size.x - 32));
    label_.draw(said, {16, size.y - int(44 * scale)}, size, scale);  // below the panels, which say it too
    label_.draw(where, {16, size.y - int(22 * scale)}, size, scale);
  }
}

MeasureResult LabHost::measureFrame() {
  const FrameShown shown = lab_->shown();
  if (shown.ownMeasure) {  // the visibility output holds the lab's measure: nothing to hold against truth
    MeasureResult r;
    r.ownMeasure = shown.ownMeasure();
    r.text = r.ownMeasure + "\n(this view writes that measure where the visibility goes: no shadow numbers)";
    r.heatmap.assign(size_t(target_.size().x) * size_t(target_.size().y) * 4, 0);
    if (symptoms_) symptoms_->record(r);
    return r;
  }
  const CompareChoice& c = panels_.compare;
  const bool split = c.on && !c.key.empty();
  std::vector<std::string> halves;
  if (split) halves = {c.key + "=" + c.a, c.key + "=" + c.b};
  const MeasureResult r = measurement_.measure(
      {target_, lab_->scene, shown.alphaCutoff, shown.light, shown.litBy, halves, sides_, shown.lightRays});
  if (symptoms_) symptoms_->record(r);
  return r;
}

MeasureResult LabHost::measureNow(bool report) {
  const MeasureResult r = measureFrame();
  panels_.measured = r.text;
  lastMeasure_ = r;
  lab_->measured(Presenter::numbersLine(r), panels_.compare.on && !panels_.compare.key.empty());
  if (!report) return r;
  const glm::ivec2 size = target_.size();
  if (imgui_) {
    heatmap_ = makeTexture2D(GL_RGBA8, size.x, size.y);
    uploadTexture2D(heatmap_.id(), 0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, r.heatmap.data());
    panels_.showHeatmap = true;
  }
  say(r.text);
  if (!options_.heatmap.empty()) {
    writePng(options_.heatmap, size.x, size.y, r.heatmap);
    written_.emplace_back("heatmap", options_.heatmap);
    say("wrote " + fs::absolute(options_.heatmap).string());
  }
  return r;
}

int LabHost::sweep() {
  return runSweep(
      options_, lab_->settings, timers_,
      [&] {
        frame(1.0f / 60);
        glFinish();
      },
      [&] { return measureNow(false); });
}

void LabHost::finish(RunRecord& record) {
  stage_->tape.save();
  if (options_.metrics && !imgui_) measureNow(true);
  const glm::ivec2 size = target_.size();
  if (!options_.screenshot.empty() && !imgui_) {  // (a window writes its own, with the UI)
    writePng(options_.screenshot, size.x, size.y, target_.readColor());
    written_.emplace_back("screenshot", options_.screenshot);
    say("wrote " + fs::absolute(options_.screenshot).string());
  }
  if (!options_.visibility.empty()) {
    writePfm(options_.visibility, target_.readVisibility());
    written_.emplace_back("visibility", options_.visibility);
    say("wrote " + fs::absolute(options_.visibility).string());
  }
  if (!options_.bench.empty()) {
    writeBench(options_.bench, stage_->board.number(), size, timers_, wall_, !options_.quiet);
    written_.emplace_back("bench", options_.bench);
  }
  stage_->board.printUnfinished();
  record.set("title", stage_->board.title());
  record.set("renderer", Context::renderer());
  record.set("gl_version", Context::version());
  record.set("size", {size.x, size.y});
  record.set("frames", frameIndex_);
  record.set("exercises", stage_->board.toJson());
  record.set("measurement", lastMeasure_ ? lastMeasure_->toJson() : nlohmann::json());
  record.set("warnings", stage_->warnings);
  if (imgui_)  // (the panels' text height in the framebuffer's pixels: 16 per unit of scale, per point)
    record.set("panel_text_pixels", 16.0f * imgui_->scale() * pixelsPerPoint());
  if (step_ > 0) {
    const DemoStep& s = presenter_->step(step_);
    record.set("demo_step", {{"step", step_},
                             {"title", s.title},
                             {"caption", s.caption},
                             {"numbers", lastMeasure_ ? Presenter::numbersLine(*lastMeasure_) : ""}});
  }
  for (const auto& [kind, path] : written_) record.addOutput(kind, path);
}

void LabHost::showStep(int k) {
  Lab& lab = *lab_;
  step_ = 0, measureStep_ = false, stepNumbers_.clear();
  if (k == 0 || !presenter_) return;
  const DemoStep& s = presenter_->apply(k, lab.settings);
  const std::string where = "demo step " + std::to_string(k) + " (\"" + s.title + "\"): ";
  if (s.bookmark > 0 && !shared_.goToBookmark(s.bookmark, lab.scene, lab.camera))
    throw UsageError(where + "bookmark " + std::to_string(s.bookmark) + " but the scene has " +
                     std::to_string(lab.scene.cameras.size()));
  if (s.compare.on) {  // both values must exist before a frame is split
    const std::string keep = lab.settings.value(s.compare.key);
    for (const auto& v : {s.compare.a, s.compare.b}) lab.settings.assign(s.compare.key + "=" + v);
    lab.settings.assign(s.compare.key + "=" + keep);
  }
  panels_.compare = s.compare, panels_.showHeatmap = false;
  step_ = k, measureStep_ = s.measure;
  if (s.measure && ctx_->headless()) options_.metrics = true;
  say("step " + std::to_string(k) + "/" + std::to_string(presenter_->count()) + ": " + s.title);
}

// present.* are compiled into every program (shaders/wb/outputs.glsl): a change rebuilds them now.
void LabHost::applyPresentation() {
  const std::string defines = std::string(shared_.present.srgb ? "#define WB_PRESENT_SRGB\n" : "") +
                              (shared_.present.grid ? "#define WB_PRESENT_GRID\n" : "");
  if (setSharedShaderDefines(defines))
    for (auto& p : stage_->programs) p.reloadIfChanged();
}

void LabHost::say(const std::string& text) const {
  if (options_.quiet) return;
  std::printf("%s\n", text.c_str());
  std::fflush(stdout);  // (a window's log is read while it runs: a presenter's steps, a screenshot's path)
}

int runLab(int argc, char** argv, std::unique_ptr<Lab> lab) { return LabHost::runLab(argc, argv, std::move(lab)); }

}  // namespace wb
