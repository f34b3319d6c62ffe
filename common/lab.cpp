#include "common/lab.hpp"

#include "common/context.hpp"
#include "common/glsl_harness.hpp"
#include "common/ground_truth.hpp"
#include "common/image.hpp"
#include "common/shadow_map.hpp"
#include "common/variant.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace wb {
namespace {

const char* const kUsage =
    "usage: %s [--headless] [--scene FILE] [--size WxH] [--set key=value]... [--frames N]\n"
    "          [--screenshot out.png] [--dump-visibility out.pfm] [--bench out.csv] [--list-settings]\n"
    "  --headless            render without a window (EGL, Mesa llvmpipe); writes a PNG if no output is named\n"
    "  --scene FILE          scene file (default %s)\n"
    "  --size WxH            frame size in pixels (default 960x540)\n"
    "  --set key=value       change a setting; --list-settings shows them all\n"
    "  --frames N            frames to render before writing outputs and exiting\n"
    "  --screenshot F.png    write the final frame as PNG\n"
    "  --dump-visibility F   write per-pixel light visibility (1 lit, 0 shadowed) as a float PFM\n"
    "  --bench F.csv         time every pass (GPU ms) and the frame (wall ms) over the frames\n"
    "  --metrics             compare with exact (ray-cast) visibility: acne rate and light leak\n"
    "  --heatmap F.png       with --metrics: write acne (red) and leaks (blue) as a picture\n"
    "  --sweep key=a,b,...   time every combination of the listed settings (repeatable; with\n"
    "                        --metrics also measure it; --frames N timed frames each)\n"
    "  --sweep-csv F.csv     with --sweep: also write the table as CSV\n"
    "  --compare key=a,b     split screen: the left half with key=a, the right half with key=b\n";

const int kMapSizes[] = {512, 1024, 2048, 4096, 8192};

struct Options {
  bool headless = false, listSettings = false;
  std::string scene, screenshot, visibility, bench, heatmap;
  bool metrics = false;
  glm::ivec2 size{960, 540};
  int frames = -1;  // -1: until the window closes (headless: 1, bench: 60)
};

// printf into a std::string (the measurement texts).
template <typename... Args>
std::string strf(const char* format, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, format, args...);
  return text;
}

struct PassStats {
  double last = 0, sum = 0, min = 1e30, max = 0;
  int count = 0;
};

}  // namespace

struct Lab::Impl {
  Options opt;
  std::unique_ptr<Context> ctx;
  Framebuffer fbo;
  Texture color, visibility, position, depth;
  std::unique_ptr<Program> lines, inset, overlay;
  VertexArray emptyVao;
  // GPU timers: queries in flight, a pool of free ones, and per-pass statistics.
  std::vector<std::pair<std::string, GLuint>> pending;
  std::vector<GLuint> freeQueries;
  std::vector<std::pair<std::string, PassStats>> passes;
  std::string activePass;
  // GLSL exercise probes: id, file, expression; and the file times they were last run against.
  struct Probe {
    std::string id, file, expr;
  };
  std::vector<Probe> probes;
  std::map<fs::path, fs::file_time_type> probedFiles;
  bool strictGl = false, imgui = false, screenshotRequested = false;
  std::string lastScreenshot;
  // Exact-visibility measurement: the ray-cast scene (rebuilt when the alpha cutoff changes), the
  // last result as text, and its heatmap shown over the frame in a window.
  std::unique_ptr<RayScene> rays;
  float raysCutoff = -1;
  std::string measured;
  Texture heatmap;
  bool showHeatmap = false;
  // Split-screen comparison: one setting, value A on the left and B on the right.
  bool compareOn = false;
  std::string compareKey, compareA, compareB;
  Texture saved[3];
  glm::ivec2 savedSize{0};
  VisibilityMetrics lastMetrics, leftMetrics, rightMetrics;
  double lastGap = -1;
  // The PCF reference of the filtered techniques, and the light each half of a split screen used.
  PcfReference pcf;
  LightView sideLight[2];
  ReferenceDifference lastReference;
  // --sweep key=v1,v2,...: every combination is rendered and measured; --sweep-csv saves the table.
  std::vector<std::pair<std::string, std::vector<std::string>>> sweeps;
  std::string sweepCsv;
  int frameIndex = 0, warmup = 0;
  double wallSum = 0;
  int wallCount = 0;
  glm::dvec2 lastMouse{0};
  bool keyDown[GLFW_KEY_LAST + 1] = {};
  bool hidePanels = false;  // H: the scene alone, for a lecture

  PassStats& stats(const std::string& name) {
    for (auto& [n, s] : passes)
      if (n == name) return s;
    passes.emplace_back(name, PassStats{});
    return passes.back().second;
  }
  // Collects finished timer queries; `wait` blocks until all are done (headless frames).
  void collect(bool wait, bool record) {
    for (auto it = pending.begin(); it != pending.end();) {
      GLint ready = 0;
      if (!wait) glGetQueryObjectiv(it->second, GL_QUERY_RESULT_AVAILABLE, &ready);
      if (!wait && !ready) {
        ++it;
        continue;
      }
      GLuint64 ns = 0;
      glGetQueryObjectui64v(it->second, GL_QUERY_RESULT, &ns);
      PassStats& s = stats(it->first);
      s.last = ns * 1e-6;
      if (record) {
        s.sum += s.last, ++s.count;
        s.min = std::min(s.min, s.last), s.max = std::max(s.max, s.last);
      }
      freeQueries.push_back(it->second);
      it = pending.erase(it);
    }
  }
  // True once per key press (edge), so holding a key does not repeat.
  bool pressed(GLFWwindow* w, int key) {
    bool down = glfwGetKey(w, key) == GLFW_PRESS, was = keyDown[key];
    keyDown[key] = down;
    return down && !was;
  }
};

Lab::Lab(std::string defaultScene) : impl_(std::make_unique<Impl>()), defaultScene_(std::move(defaultScene)) {
  // The manifest is the one list of this lab's exercises (also used by the tests and grading).
  const fs::path manifest = fs::path(variant::kLabDir) / "exercises.json";
  try {
    auto j = nlohmann::json::parse(readFile(manifest));
    number_ = j.at("lab").get<std::string>().substr(0, 2);
    title_ = j.at("title").get<std::string>();
    for (const auto& e : j.at("exercises"))
      exercises_.push_back({e.at("id").get<std::string>(), e.at("title").get<std::string>(), {}, {}});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "warning: cannot read %s (%s); the exercise list will be empty\n", manifest.string().c_str(),
                 e.what());
  }
  std::vector<std::string> sizes;
  for (int s : kMapSizes) sizes.push_back(std::to_string(s));
  settings.addChoice("shadow.map_size", mapSizeChoice_, sizes,
                     "shadow map resolution in texels (clamped to GL_MAX_TEXTURE_SIZE)");
  settings.add("shadow.bias", bias_, 0.0f, 0.05f, "constant depth bias subtracted from the receiver depth");
  settings.add("alpha.cutoff", alphaCutoff_, 0.0f, 1.0f, "leaf texels with lower alpha are holes and cast no shadow");
  settings.add("light.index", lightIndex, 0, 7, "which light of the scene casts shadows");
  settings.addChoice("debug.view", debugView_, {"camera", "light"}, "see the scene from the camera or from the light");
  settings.add("debug.shadow_map", showMap_, "show the shadow map (linearised for perspective lights) in a corner");
  settings.add("debug.frustum", showFrustum_, "draw the light's frustum in the scene");
  settings.add("camera.bookmark", bookmark_, 0, 8, "camera bookmark from the scene file (keys 1-9)");
}

Lab::~Lab() {
  if (impl_->imgui) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  programs_.clear();
  gpuScene.reset();
  if (impl_->ctx) {
    for (GLuint q : impl_->freeQueries) glDeleteQueries(1, &q);
    for (auto& p : impl_->pending) glDeleteQueries(1, &p.second);
  }
  Impl* i = impl_.get();
  i->fbo.reset(), i->color.reset(), i->visibility.reset(), i->depth.reset();
  i->lines.reset(), i->inset.reset(), i->emptyVao.reset();
  i->ctx.reset();
}

Program& Lab::loadProgram(std::vector<ShaderStage> stages, std::string defines) {
  programs_.push_back(Program::tryLoad(std::move(stages), std::move(defines)));
  return programs_.back();
}

void Lab::glslExercise(const std::string& id, const std::string& file, const std::string& probe) {
  impl_->probes.push_back({id, file, probe});
}

void Lab::setStatus(const std::string& id, ExerciseState state, const std::string& message) {
  for (auto& e : exercises_)
    if (e.id == id) e.state = state, e.message = message;
}

void Lab::warn(const std::string& message) {
  if (std::find(warnings_.begin(), warnings_.end(), message) != warnings_.end()) return;
  warnings_.push_back(message);
  std::fprintf(stderr, "warning: %s\n", message.c_str());
}

int Lab::shadowMapSize() {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  const int wanted = kMapSizes[mapSizeChoice_];
  if (wanted > maxSize) {
    warn("shadow.map_size " + std::to_string(wanted) + " exceeds GL_MAX_TEXTURE_SIZE; using " +
         std::to_string(maxSize));
    return maxSize;
  }
  return wanted;
}

glm::mat4 Lab::viewProj() const {
  if (debugView_ == 1 && light_.depthMap) {  // the light's square view, letterboxed, not stretched
    const float aspect = float(frameSize_.x) / float(frameSize_.y);
    const glm::vec3 fit = aspect > 1 ? glm::vec3(1 / aspect, 1, 1) : glm::vec3(1, aspect, 1);
    return glm::scale(glm::mat4(1), fit) * light_.viewProj;
  }
  return camera.projection(float(frameSize_.x) / float(frameSize_.y)) * camera.view();
}

glm::vec3 Lab::viewPosition() const {
  if (debugView_ == 1 && light_.depthMap) {
    glm::vec4 p = glm::inverse(light_.viewProj) * glm::vec4(0, 0, -1, 1);
    return glm::vec3(p) / p.w;
  }
  return camera.eye();
}

void Lab::renderShadowMap(const Program& depthProgram, const ShadowMap& map, const Light& light,
                          const glm::mat4& lightViewProj) {
  map.begin();
  depthProgram.set("u_lightViewProj", lightViewProj);
  depthProgram.set("u_alphaCutoff", alphaCutoff_);
  gpuScene->draw(depthProgram);
  showLight({light, lightViewProj, map.texture(), map.size()});
}

void Lab::renderFilteredShadowMap(const Program& writer, FilteredShadowMap& map, const float far[4],
                                  const Program& blur, const Light& light, const glm::mat4& lightViewProj) {
  {
    auto timer = timePass("shadow");
    map.begin(far);
    writer.set("u_lightViewProj", lightViewProj);
    writer.set("u_alphaCutoff", alphaCutoff_);
    gpuScene->draw(writer);
  }
  {
    auto timer = timePass("prefilter");
    map.prefilter(blur);
  }
  showLight({light, lightViewProj, map.depthTexture(), map.size(), map.options().kernel, map.options().gaussian});
}

void Lab::beginCameraPass(const Program& program, const glm::mat4& lightViewProj, GLuint shadowMap) {
  bindFrameTarget();
  program.set("u_viewProj", viewProj());
  program.set("u_lightViewProj", lightViewProj);
  program.set("u_alphaCutoff", alphaCutoff_);
  program.set("u_shadowMap", 0);
  glBindTextureUnit(0, shadowMap);
}

void Lab::bindFrameTarget() const {
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->fbo.id());
  glViewport(0, 0, frameSize_.x, frameSize_.y);
}

Lab::PassTimer::PassTimer(Lab& lab, const char* name) : lab_(lab) {
  auto& i = *lab.impl_;
  GLuint q = 0;
  if (i.freeQueries.empty())
    glGenQueries(1, &q);
  else
    q = i.freeQueries.back(), i.freeQueries.pop_back();
  i.pending.emplace_back(name, q);
  glBeginQuery(GL_TIME_ELAPSED, q);
}

Lab::PassTimer::~PassTimer() { glEndQuery(GL_TIME_ELAPSED); }

void Lab::probeGlslExercises() {
  auto& i = *impl_;
  std::map<std::string, std::vector<const Impl::Probe*>> byFile;
  for (const auto& p : i.probes) byFile[p.file].push_back(&p);
  Texture dummy = makeTexture2D(GL_R32F, 1, 1);
  for (const auto& [file, probes] : byFile) {
    std::string body;
    for (size_t k = 0; k < probes.size(); ++k)
      body += "if (wb_i == " + std::to_string(k) + ") result.x = float(" + probes[k]->expr + ");\n  ";
    try {
      const fs::path path = findShaderFile(file, shaderSearchPath());
      i.probedFiles[path] = fs::last_write_time(path);
      auto r = runGlslKernel(readFile(path), path, body, int(probes.size()), 1, {}, {dummy.id()});
      for (size_t k = 0; k < probes.size(); ++k)
        setStatus(probes[k]->id, isTodo(r[k].x) ? ExerciseState::NotImplemented : ExerciseState::Implemented,
                  isTodo(r[k].x) ? "the GLSL function still returns WB_TODO" : "");
    } catch (const Error& e) {
      for (const auto* p : probes) setStatus(p->id, ExerciseState::Failed, e.what());
    }
  }
}

int Lab::main(int argc, char** argv) {
  auto& i = *impl_;
  const std::string exe = fs::path(argv[0]).filename().string();
  try {
    // ---- Command line: everything is checked before a GL context exists. ----
    std::vector<std::string> sets;
    for (int a = 1; a < argc; ++a) {
      std::string arg = argv[a];
      auto value = [&]() -> std::string {
        if (a + 1 >= argc) throw UsageError(arg + " needs a value; see --help");
        return argv[++a];
      };
      if (arg == "--help" || arg == "-h") {
        std::printf(kUsage, exe.c_str(), defaultScene_.c_str());
        return 0;
      } else if (arg == "--headless")
        i.opt.headless = true;
      else if (arg == "--list-settings")
        i.opt.listSettings = true;
      else if (arg == "--scene")
        i.opt.scene = value();
      else if (arg == "--set")
        sets.push_back(value());
      else if (arg == "--screenshot")
        i.opt.screenshot = value();
      else if (arg == "--dump-visibility")
        i.opt.visibility = value();
      else if (arg == "--bench")
        i.opt.bench = value();
      else if (arg == "--metrics")
        i.opt.metrics = true;
      else if (arg == "--sweep") {
        const std::string v = value();
        const auto eq = v.find('=');
        if (eq == std::string::npos || eq + 1 >= v.size())
          throw UsageError("--sweep expects key=v1,v2,..., got '" + v + "'");
        std::vector<std::string> values;
        std::stringstream list(v.substr(eq + 1));
        for (std::string item; std::getline(list, item, ',');) values.push_back(item);
        i.sweeps.emplace_back(v.substr(0, eq), values);
      } else if (arg == "--compare") {
        const std::string v = value();
        const auto eq = v.find('='), comma = v.find(',', eq == std::string::npos ? 0 : eq);
        if (eq == std::string::npos || comma == std::string::npos || v.find(',', comma + 1) != std::string::npos)
          throw UsageError("--compare expects key=a,b (two values of one setting), got '" + v + "'");
        i.compareKey = v.substr(0, eq), i.compareA = v.substr(eq + 1, comma - eq - 1), i.compareB = v.substr(comma + 1);
        i.compareOn = true;
      } else if (arg == "--sweep-csv")
        i.sweepCsv = value();
      else if (arg == "--heatmap")
        i.opt.heatmap = value(), i.opt.metrics = true;
      else if (arg == "--size") {
        std::string v = value();
        char x = 0, extra = 0;
        std::istringstream in(v);
        if (!(in >> i.opt.size.x >> x >> i.opt.size.y) || x != 'x' || in >> extra || i.opt.size.x < 16 ||
            i.opt.size.y < 16 || i.opt.size.x > 8192 || i.opt.size.y > 8192)
          throw UsageError("bad --size '" + v + "': expected WxH between 16x16 and 8192x8192, e.g. 960x540");
      } else if (arg == "--frames") {
        std::string v = value();
        try {
          size_t used = 0;
          i.opt.frames = std::stoi(v, &used);
          if (used != v.size() || i.opt.frames < 1) throw 0;
        } catch (...) {
          throw UsageError("bad --frames '" + v + "': expected a whole number of at least 1");
        }
      } else
        throw UsageError("unknown option '" + arg +
                         "'; accepted: --headless --scene --size --set --frames "
                         "--screenshot --dump-visibility --bench --metrics --heatmap --sweep --sweep-csv --compare "
                         "--list-settings --help");
    }
    for (const auto& s : sets) settings.assign(s);
    if (i.compareOn) {  // both values must be valid before anything renders
      const std::string keep = settings.value(i.compareKey);
      for (const auto& v : {i.compareA, i.compareB}) settings.assign(i.compareKey + "=" + v);
      settings.assign(i.compareKey + "=" + keep);
    }
    for (const auto& [key, values] : i.sweeps)  // check every swept value now, before any rendering
      for (const auto& v : values) settings.assign(key + "=" + v);
    for (const auto& s : sets) settings.assign(s);
    if (i.opt.listSettings) {
      std::printf("settings of lab %s (%s):\n", number_.c_str(), title_.c_str());
      settings.list(std::cout);
      return 0;
    }
    const fs::path scenePath =
        i.opt.scene.empty() ? fs::path(variant::kSourceDir) / defaultScene_ : fs::path(i.opt.scene);
    scene = Scene::load(scenePath);
    if (lightIndex >= int(scene.lights.size()))
      throw UsageError("light.index=" + std::to_string(lightIndex) + " but " + scenePath.string() + " has " +
                       std::to_string(scene.lights.size()) + " light(s)");
    camera.pose = scene.cameras[std::min<size_t>(bookmark_, scene.cameras.size() - 1)];
    const bool writeSomething =
        !i.opt.screenshot.empty() || !i.opt.visibility.empty() || !i.opt.bench.empty() || i.opt.metrics;
    if (i.opt.headless && !writeSomething) i.opt.screenshot = "lab" + number_ + ".png";
    if (i.opt.frames < 0 && (i.opt.headless || !i.opt.bench.empty())) i.opt.frames = i.opt.bench.empty() ? 1 : 60;
    i.warmup = i.opt.bench.empty() ? 0 : std::min(10, i.opt.frames / 4);
    frameSize_ = i.opt.size;

    // ---- Context, frame target, shared debug programs, scene, then the lab's own init(). ----
    const char* strict = std::getenv("WB_STRICT_GL");
#ifndef NDEBUG
    i.strictGl = true;
#endif
    if (strict) i.strictGl = std::string(strict) != "0";
    i.ctx = Context::create({i.opt.headless, i.opt.size.x, i.opt.size.y, "Lab " + number_ + ": " + title_, true});
    if (!i.opt.bench.empty() && !i.opt.headless) glfwSwapInterval(0);  // measure, do not wait for vsync
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    i.emptyVao = VertexArray(vao);
    i.lines = std::make_unique<Program>(
        std::vector<ShaderStage>{{GL_VERTEX_SHADER, "wb/frustum.vert"}, {GL_FRAGMENT_SHADER, "wb/flat.frag"}});
    i.inset = std::make_unique<Program>(
        std::vector<ShaderStage>{{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/depth_view.frag"}});
    i.overlay = std::make_unique<Program>(
        std::vector<ShaderStage>{{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/overlay.frag"}});
    gpuScene = std::make_unique<GpuScene>(scene);
    if (!i.ctx->headless()) {
      IMGUI_CHECKVERSION();
      ImGui::CreateContext();
      ImGui::GetIO().IniFilename = nullptr;
      ImGui_ImplGlfw_InitForOpenGL(i.ctx->window(), true);
      ImGui_ImplOpenGL3_Init("#version 450 core");
      i.imgui = true;
    }
    init();
    probeGlslExercises();

    if (!i.sweeps.empty()) return sweep();

    // ---- The frame loop. ----
    auto last = std::chrono::steady_clock::now();
    while (!i.ctx->shouldClose() && (i.opt.frames < 0 || i.frameIndex < i.opt.frames)) {
      auto now = std::chrono::steady_clock::now();
      float dt = i.opt.headless ? 1.0f / 60 : std::chrono::duration<float>(now - last).count();
      last = now;
      frame(dt);
      if (!i.opt.bench.empty() || i.opt.headless) glFinish();
      auto end = std::chrono::steady_clock::now();
      const bool record = i.frameIndex >= i.warmup;
      if (record && i.frameIndex > 0)
        i.wallSum += std::chrono::duration<double, std::milli>(end - now).count(), ++i.wallCount;
      i.collect(i.ctx->headless(), record);
      for (const auto& e : takeGlErrors()) {
        if (i.strictGl) throw Error("OpenGL error: " + e);
        warn("OpenGL error: " + e);
      }
      if (i.opt.metrics && i.imgui && i.frameIndex == 0) measure();  // a window shows it as an overlay
      ++i.frameIndex;
    }
    if (i.opt.metrics && !i.imgui) measure();
    writeOutputs();
    for (const auto& e : exercises_)
      if (e.state == ExerciseState::NotImplemented || e.state == ExerciseState::Failed)
        std::fprintf(stderr, "Exercise %s (%s) is %s: %s\n", e.id.c_str(), e.title.c_str(),
                     e.state == ExerciseState::Failed ? "failing" : "not implemented yet", e.message.c_str());
    return 0;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s\n", exe.c_str(), e.what());
    return 2;
  } catch (const ContextError& e) {
    std::fprintf(stderr, "%s: %s\n", exe.c_str(), e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", exe.c_str(), e.what());
    return 1;
  }
}

void Lab::frame(float dt) {
  auto& i = *impl_;
  GLFWwindow* win = i.ctx->window();
  if (i.imgui) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    glm::dvec2 mouse;
    glfwGetCursorPos(win, &mouse.x, &mouse.y);
    if (!io.WantCaptureMouse) {  // never steal the mouse from a widget
      if (glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS && mouse != i.lastMouse) {
        camera.orbit(float(mouse.x - i.lastMouse.x), float(mouse.y - i.lastMouse.y));
        i.showHeatmap = false;  // it was measured for the old view
      }
      camera.zoom(io.MouseWheel);
    }
    i.lastMouse = mouse;
    if (!io.WantCaptureKeyboard) {
      for (int k = 0; k < 9; ++k)
        if (i.pressed(win, GLFW_KEY_1 + k) && k < int(scene.cameras.size()))
          bookmark_ = k, camera.pose = scene.cameras[k];
      if (i.pressed(win, GLFW_KEY_F12) || i.pressed(win, GLFW_KEY_P)) i.screenshotRequested = true;
      if (i.pressed(win, GLFW_KEY_H)) i.hidePanels = !i.hidePanels;
    }
    frameSize_ = glm::max(i.ctx->framebufferSize(), glm::ivec2(16));
  }

  // Hot reload: a changed file rebuilds its programs; a failed build keeps the last good program.
  if (i.frameIndex % 15 == 0) {
    for (auto& p : programs_) p.reloadIfChanged();
    for (const auto& [file, time] : i.probedFiles) {
      std::error_code ec;
      if (fs::last_write_time(file, ec) != time) {
        probeGlslExercises();
        break;
      }
    }
  }
  update(dt);

  // The offscreen frame target follows the window; its visibility attachment is cleared to "lit".
  if (!i.fbo.id() || i.color.id() == 0 || frameSize_ != i.opt.size) {
    i.opt.size = frameSize_;
    i.color = makeTexture2D(GL_RGBA8, frameSize_.x, frameSize_.y);
    i.visibility = makeTexture2D(GL_R32F, frameSize_.x, frameSize_.y);
    i.position = makeTexture2D(GL_RGBA32F, frameSize_.x, frameSize_.y);
    i.depth = makeTexture2D(GL_DEPTH_COMPONENT24, frameSize_.x, frameSize_.y);
    i.fbo = makeFramebuffer({i.color.id(), i.visibility.id(), i.position.id()}, i.depth.id());
  }
  // The scene: once, or in split-screen comparison twice (left half with value A, right with B).
  bool programsOk = std::all_of(programs_.begin(), programs_.end(), [](const Program& p) { return p.ok(); });
  if (!programsOk && i.ctx->headless())
    for (const auto& p : programs_)
      if (!p.ok()) throw Error(p.error());
  const bool split = i.compareOn && !i.compareKey.empty();
  const std::string before = split ? settings.value(i.compareKey) : "";
  if (split) settings.assign(i.compareKey + "=" + i.compareA);
  drawScene(programsOk);
  i.sideLight[0] = light_;
  if (split) {
    const int half = frameSize_.x / 2;
    if (!i.saved[0].id() || i.savedSize != frameSize_) {  // copies of the left half's attachments
      i.saved[0] = makeTexture2D(GL_RGBA8, half, frameSize_.y);
      i.saved[1] = makeTexture2D(GL_R32F, half, frameSize_.y);
      i.saved[2] = makeTexture2D(GL_RGBA32F, half, frameSize_.y);
      i.savedSize = frameSize_;
    }
    const GLuint targets[3] = {i.color.id(), i.visibility.id(), i.position.id()};
    for (int t = 0; t < 3; ++t)
      glCopyImageSubData(targets[t], GL_TEXTURE_2D, 0, 0, 0, 0, i.saved[t].id(), GL_TEXTURE_2D, 0, 0, 0, 0, half,
                         frameSize_.y, 1);
    settings.assign(i.compareKey + "=" + i.compareB);
    drawScene(programsOk);
    i.sideLight[1] = light_;
    for (int t = 0; t < 3; ++t)
      glCopyImageSubData(i.saved[t].id(), GL_TEXTURE_2D, 0, 0, 0, 0, targets[t], GL_TEXTURE_2D, 0, 0, 0, 0, half,
                         frameSize_.y, 1);
    settings.assign(i.compareKey + "=" + before);
    bindFrameTarget();  // a white divider between the halves
    glEnable(GL_SCISSOR_TEST);
    glScissor(half - 1, 0, 2, frameSize_.y);
    const float white[4] = {1, 1, 1, 1};
    glClearBufferfv(GL_COLOR, 0, white);
    glDisable(GL_SCISSOR_TEST);
  }

  // Shared debug views, drawn into the frame target so screenshots and headless runs show them.
  bindFrameTarget();
  for (GLuint b : {1u, 2u}) glColorMaski(b, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // overlays: colour only
  glBindVertexArray(i.emptyVao.id());
  if (showFrustum_ && light_.depthMap) {
    i.lines->use();
    i.lines->set("u_viewProj", viewProj());
    i.lines->set("u_invLight", glm::inverse(light_.viewProj));
    i.lines->set("u_color", glm::vec3(1, 0.85f, 0.1f));
    glDrawArrays(GL_LINES, 0, 24);
  }
  if (showMap_ && light_.depthMap) {
    const int s = frameSize_.y / 3;
    glViewport(8, 8, s, s);  // bottom left: the Settings window covers the right side
    glDisable(GL_DEPTH_TEST);
    i.inset->use();
    i.inset->set("u_perspective", light_.light.type != LightType::Directional ? 1 : 0);
    i.inset->set("u_near", light_.light.nearPlane);
    i.inset->set("u_far", light_.light.farPlane);
    glBindTextureUnit(0, light_.depthMap);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
  }
  if (i.showHeatmap && i.heatmap.id()) {  // red: acne, blue: light leaking (see ground_truth.hpp)
    glViewport(0, 0, frameSize_.x, frameSize_.y);
    glDisable(GL_DEPTH_TEST);
    glEnablei(GL_BLEND, 0);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    i.overlay->use();
    glBindTextureUnit(0, i.heatmap.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisablei(GL_BLEND, 0);
    glEnable(GL_DEPTH_TEST);
  }
  for (GLuint b : {1u, 2u}) glColorMaski(b, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  if (i.imgui) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, i.fbo.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);  // (measure() and writeOutputs() point it elsewhere)
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, frameSize_.x, frameSize_.y, 0, 0, frameSize_.x, frameSize_.y, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, frameSize_.x, frameSize_.y);
    drawShell();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    // In a window, --screenshot captures the last frame as the user sees it, UI included.
    const bool lastFrame = i.opt.frames > 0 && i.frameIndex == i.opt.frames - 1 && !i.opt.screenshot.empty();
    if (i.screenshotRequested || lastFrame) {
      i.screenshotRequested = false;
      std::vector<uint8_t> px(size_t(frameSize_.x) * frameSize_.y * 4);
      glReadPixels(0, 0, frameSize_.x, frameSize_.y, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
      char stamp[32];
      std::time_t t = std::time(nullptr);
      std::strftime(stamp, sizeof stamp, "%Y%m%d_%H%M%S", std::localtime(&t));
      i.lastScreenshot = lastFrame ? i.opt.screenshot : "screenshots/lab" + number_ + "_" + stamp + ".png";
      writePng(i.lastScreenshot, frameSize_.x, frameSize_.y, px);
      std::printf("wrote %s\n", fs::absolute(i.lastScreenshot).string().c_str());
    }
    i.ctx->endFrame();
  }
}

void Lab::drawScene(bool programsOk) {
  bindFrameTarget();
  const float sky[4] = {0.55f, 0.65f, 0.78f, 1}, lit = 1, none[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, sky);
  glClearBufferfv(GL_COLOR, 1, &lit);
  glClearBufferfv(GL_COLOR, 2, none);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  if (programsOk) render();
}

void Lab::drawShell() {
  auto& i = *impl_;
  if (i.hidePanels) {
    ImGui::SetNextWindowPos(ImVec2(8, 8));
    ImGui::Begin("##panels hidden", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted("H: show the panels");
    ImGui::End();
    return;
  }
  const ImVec4 red(1, 0.4f, 0.4f, 1), green(0.5f, 1, 0.5f, 1), yellow(1, 0.85f, 0.3f, 1), grey(0.7f, 0.7f, 0.7f, 1);
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::Begin(("Lab " + number_ + ": " + title_).c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextColored(grey, "%s | %.1f fps | %dx%d", Context::renderer().c_str(), ImGui::GetIO().Framerate, frameSize_.x,
                     frameSize_.y);
  ImGui::Separator();
  ImGui::Text("Exercises (run ./workbook check %s to grade them)", number_.c_str());
  for (const auto& e : exercises_) {
    const char* label = "not run yet";
    ImVec4 c = grey;
    switch (e.state) {
      case ExerciseState::Implemented:
        label = "done", c = green;
        break;
      case ExerciseState::NotImplemented:
        label = "not implemented", c = yellow;
        break;
      case ExerciseState::Failed:
        label = "error", c = red;
        break;
      case ExerciseState::Unknown:
        break;
    }
    ImGui::TextColored(c, "%s  %-16s %s", e.id.c_str(), label, e.title.c_str());
    if (!e.message.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.message.c_str());
    if (e.state == ExerciseState::Failed) {  // the line that names file:line, if there is one
      std::string first = e.message.substr(0, e.message.find('\n'));
      if (auto at = e.message.find(": error"); at != std::string::npos) {
        const size_t begin = e.message.rfind('\n', at) + 1;
        first = e.message.substr(begin, e.message.find('\n', at) - begin);
      }
      ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40);
      ImGui::TextColored(red, "      %s", first.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  if (!i.passes.empty()) {
    ImGui::Separator();
    ImGui::Text("GPU time per pass");
    for (const auto& [name, s] : i.passes) ImGui::Text("  %-12s %7.3f ms", name.c_str(), s.last);
  }
  ImGui::Separator();
  if (ImGui::Button("Measure against exact visibility")) measure();
  if (!i.measured.empty()) {
    ImGui::SameLine();
    ImGui::Checkbox("heatmap", &i.showHeatmap);
    ImGui::TextUnformatted(i.measured.c_str());
  }
  for (const auto& p : programs_)
    if (!p.error().empty()) {
      ImGui::Separator();
      ImGui::TextColored(red, "Shader error (the last good version is still running):");
      ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40);
      ImGui::TextUnformatted(p.error().c_str());
      ImGui::PopTextWrapPos();
    }
  for (const auto& w : warnings_) ImGui::TextColored(yellow, "warning: %s", w.c_str());
  if (!i.lastScreenshot.empty()) ImGui::TextColored(grey, "saved %s", i.lastScreenshot.c_str());
  ImGui::TextColored(grey, "drag: orbit | wheel: zoom | 1-9: bookmarks | H: hide panels | F12: screenshot");
  ImGui::End();

  ImGui::SetNextWindowPos(ImVec2(float(frameSize_.x) - 8, 8), ImGuiCond_FirstUseEver, ImVec2(1, 0));
  ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("Settings", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::PushItemWidth(150);
  const int oldBookmark = bookmark_;
  settings.ui();
  if (ImGui::CollapsingHeader("compare (split screen)")) {
    // Any setting with named choices can be compared: value A on the left, B on the right.
    std::vector<const Setting*> choices;
    for (const auto& s : settings.all())
      if (s.kind == Setting::Kind::Choice) choices.push_back(&s);
    ImGui::Checkbox("split screen", &i.compareOn);
    if (i.compareKey.empty() && !choices.empty()) {
      i.compareKey = choices.back()->name;
      i.compareA = choices.back()->choices.front(), i.compareB = choices.back()->choices.back();
    }
    auto combo = [](const char* label, std::string& current, const std::vector<std::string>& options) {
      if (!ImGui::BeginCombo(label, current.c_str())) return;
      for (const auto& o : options)
        if (ImGui::Selectable(o.c_str(), o == current)) current = o;
      ImGui::EndCombo();
    };
    std::vector<std::string> names;
    for (const auto* c : choices) names.push_back(c->name);
    const std::string oldKey = i.compareKey;
    combo("setting", i.compareKey, names);
    for (const auto* c : choices)
      if (c->name == i.compareKey) {
        if (i.compareKey != oldKey) i.compareA = c->choices.front(), i.compareB = c->choices.back();
        combo("left (A)", i.compareA, c->choices);
        combo("right (B)", i.compareB, c->choices);
      }
  }
  if (bookmark_ != oldBookmark && bookmark_ < int(scene.cameras.size())) camera.pose = scene.cameras[bookmark_];
  lightIndex = std::min(lightIndex, int(scene.lights.size()) - 1);
  ui();
  ImGui::PopItemWidth();
  ImGui::End();
}

int Lab::sweep() {
  // Each combination: one warm-up frame, then --frames timed frames (GPU ms per pass and wall ms per
  // frame are their means); with --metrics, the last frame is also measured against exact visibility.
  auto& i = *impl_;
  const int timed = std::max(1, i.opt.frames);
  std::ofstream csv;
  if (!i.sweepCsv.empty()) {
    csv.open(i.sweepCsv);
    if (!csv) throw UsageError("cannot write --sweep-csv file '" + i.sweepCsv + "'");
  }
  auto row = [&](const std::vector<std::string>& cells) {
    std::string line = "|";
    for (const auto& c : cells) line += " " + c + " |";
    std::printf("%s\n", line.c_str());
    for (size_t c = 0; c < cells.size(); ++c) csv << (c ? "," : "") << cells[c];
    if (csv.is_open()) csv << "\n";
  };
  size_t total = 1;
  for (const auto& sw : i.sweeps) total *= sw.second.size();
  std::vector<std::string> passNames;
  for (size_t n = 0; n < total; ++n) {
    std::vector<std::string> cells;
    size_t k = n;
    for (auto it = i.sweeps.rbegin(); it != i.sweeps.rend(); ++it) {  // the last key varies fastest
      settings.assign(it->first + "=" + it->second[k % it->second.size()]);
      cells.insert(cells.begin(), it->second[k % it->second.size()]);
      k /= it->second.size();
    }
    std::fprintf(stderr, "\rsweep %zu/%zu ", n + 1, total);
    frame(1.0f / 60);  // warm-up: allocations, first use of a program
    glFinish();
    i.collect(true, false);
    for (auto& [name, st] : i.passes) st = PassStats{};
    const auto t0 = std::chrono::steady_clock::now();
    for (int f = 0; f < timed; ++f) {
      frame(1.0f / 60);
      glFinish();
      i.collect(true, true);
    }
    const double wall =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / timed;
    if (n == 0) {  // the header, once the passes are known
      for (const auto& p : i.passes) passNames.push_back(p.first);
      std::vector<std::string> header;
      for (const auto& sw : i.sweeps) header.push_back(sw.first);
      if (i.opt.metrics)
        header.insert(header.end(),
                      {"acne_%", "leak_%", "contact_gap_texels", "shadow_light_%", "pcf_diff_%", "pcf_lighter_%"});
      for (const auto& p : passNames) header.push_back(p + "_gpu_ms");
      header.emplace_back("frame_ms");
      row(header);
      std::string rule = "|";
      for (size_t c = 0; c < header.size(); ++c) rule += "---|";
      std::printf("%s\n", rule.c_str());
    }
    if (i.opt.metrics) {
      measure(false);
      cells.push_back(strf("%.2f", 100 * i.lastMetrics.acneRate()));
      cells.push_back(strf("%.2f", 100 * i.lastMetrics.leakRate()));
      cells.push_back(i.lastGap < 0 ? "n/a" : strf("%.1f", i.lastGap));
      cells.push_back(strf("%.2f", 100 * i.lastMetrics.meanShadowLight()));
      const bool ref = i.lastReference.pixels > 0;
      cells.push_back(ref ? strf("%.2f", 100 * i.lastReference.meanAbs()) : "n/a");
      cells.push_back(ref ? strf("%.2f", 100 * i.lastReference.lighterRate()) : "n/a");
    }
    for (const auto& p : passNames) {
      const PassStats& st = i.stats(p);
      cells.push_back(st.count ? strf("%.3f", st.sum / st.count) : "-");
    }
    cells.push_back(strf("%.2f", wall));
    row(cells);
  }
  std::fprintf(stderr, "\r%*s\r", 24, "");
  if (csv.is_open()) std::printf("wrote %s\n", fs::absolute(i.sweepCsv).string().c_str());
  return 0;
}

void Lab::measure(bool report) {
  auto& i = *impl_;
  const int w = frameSize_.x, h = frameSize_.y;
  const auto t0 = std::chrono::steady_clock::now();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, i.fbo.id());
  FloatImage rendered{w, h, std::vector<float>(size_t(w) * size_t(h))};
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, w, h, GL_RED, GL_FLOAT, rendered.pixels.data());
  std::vector<glm::vec4> positions(size_t(w) * size_t(h));
  glReadBuffer(GL_COLOR_ATTACHMENT2);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, positions.data());
  if (!i.rays || i.raysCutoff != alphaCutoff_)
    i.rays = std::make_unique<RayScene>(scene, alphaCutoff_), i.raysCutoff = alphaCutoff_;
  const Light& light = light_.depthMap ? light_.light : scene.lights[size_t(lightIndex)];
  const FloatImage exact = exactVisibility(*i.rays, light, w, h, positions);
  const VisibilityMetrics m = compareVisibility(rendered, exact, positions);
  double gap = -1;  // the contact gap needs texels of one size: orthographic maps only
  if (light_.depthMap && light.type == LightType::Directional && light_.mapSize > 0)
    gap = contactGapTexels(rendered, exact, positions, *i.rays, light, scene.boundsMin.y,
                           texelWorldSize(light_.viewProj, light_.mapSize));
  // Against PCF over the footprint each side filtered with (orthographic maps only); in split
  // screen the left side's reference needs the map it was drawn with, so its size must match.
  const bool split = i.compareOn && !i.compareKey.empty();
  std::vector<float> reference[2];
  auto referenceFor = [&](int side) -> const std::vector<float>* {
    const LightView& s = split ? i.sideLight[side] : light_;
    if (!light_.depthMap || light.type != LightType::Directional || s.mapSize != light_.mapSize) return nullptr;
    if (reference[side].empty())
      reference[side] =
          i.pcf.render(i.position.id(), w, h, light_.depthMap, light_.mapSize, light_.viewProj, s.kernel, s.gaussian);
    return &reference[side];
  };
  auto describe = [](const LightView& s) {
    return std::to_string(s.kernel) + "x" + std::to_string(s.kernel) + (s.kernel > 1 && s.gaussian ? " Gaussian" : "");
  };
  std::string pcfText = "against PCF: n/a (directional lights only)";
  i.lastReference = {};
  if (const auto* ref = referenceFor(split ? 1 : 0)) {
    i.lastReference = compareWithReference(rendered, *ref, 0, w);
    pcfText = strf(
        "against PCF over the same footprint (%s): |difference| %.2f%%,\n  lighter by > 0.1 on "
        "%.2f%%, darker on %.2f%% of light-facing pixels",
        describe(split ? i.sideLight[1] : light_).c_str(), 100 * i.lastReference.meanAbs(),
        100 * i.lastReference.lighterRate(), 100 * i.lastReference.darkerRate());
    if (split) pcfText.insert(pcfText.find(':'), ", whole frame");
  }
  std::string halves;  // in split screen, each half measured on its own
  if (split) {
    for (int side = 0; side < 2; ++side) {
      FloatImage r{w / 2, h, {}}, e{w / 2, h, {}};
      std::vector<glm::vec4> pos;
      for (int y = 0; y < h; ++y)
        for (int x = side * (w - w / 2); x < side * (w - w / 2) + w / 2; ++x) {
          const size_t k = size_t(y) * size_t(w) + size_t(x);
          r.pixels.push_back(rendered.pixels[k]), e.pixels.push_back(exact.pixels[k]), pos.push_back(positions[k]);
        }
      const VisibilityMetrics hm = compareVisibility(r, e, pos);
      halves += strf("\n%s %s=%s: acne %.2f%%, leak %.2f%%, light in shadows %.2f%%", side ? "right" : "left ",
                     i.compareKey.c_str(), (side ? i.compareB : i.compareA).c_str(), 100 * hm.acneRate(),
                     100 * hm.leakRate(), 100 * hm.meanShadowLight());
      if (const auto* ref = referenceFor(side)) {
        const ReferenceDifference d =
            compareWithReference(rendered, *ref, side * (w - w / 2), side * (w - w / 2) + w / 2);
        halves += strf("\n       against PCF %s: |difference| %.2f%%, lighter %.2f%%",
                       describe(i.sideLight[side]).c_str(), 100 * d.meanAbs(), 100 * d.lighterRate());
      } else {
        halves += "\n       against PCF: n/a";
      }
    }
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  char text[400];
  std::snprintf(
      text, sizeof text,
      "acne rate %.2f%% (%ld of %ld lit pixels drawn shadowed)\nlight leak %.2f%% (%ld of %ld shadowed pixels "
      "drawn lit)\ncontact gap %s texels\nlight in shadows %.2f%% (mean visibility where the light is blocked)\n"
      "(exact visibility by ray casting, %.0f ms)",
      100 * m.acneRate(), m.acnePixels, m.litPixels, 100 * m.leakRate(), m.leakPixels, m.shadowedPixels,
      gap < 0 ? "n/a" : std::to_string(gap).substr(0, std::to_string(gap).find('.') + 2).c_str(),
      100 * m.meanShadowLight(), ms);
  i.measured = text + ("\n" + pcfText) + halves;
  i.lastMetrics = m;
  i.lastGap = gap;
  if (!report) return;
  const std::vector<uint8_t> heat = artifactHeatmap(rendered, exact, positions);
  if (i.imgui) {
    i.heatmap = makeTexture2D(GL_RGBA8, w, h);
    glTextureSubImage2D(i.heatmap.id(), 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, heat.data());
    i.showHeatmap = true;
  }
  std::printf("%s\n", i.measured.c_str());
  if (!i.opt.heatmap.empty()) {
    writePng(i.opt.heatmap, w, h, heat);
    std::printf("wrote %s\n", fs::absolute(i.opt.heatmap).string().c_str());
  }
}

void Lab::writeOutputs() {
  auto& i = *impl_;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, i.fbo.id());
  const int w = frameSize_.x, h = frameSize_.y;
  if (!i.opt.screenshot.empty() && !i.imgui) {  // (a window writes its own, with the UI)
    std::vector<uint8_t> px(size_t(w) * h * 4);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    writePng(i.opt.screenshot, w, h, px);
    std::printf("wrote %s\n", fs::absolute(i.opt.screenshot).string().c_str());
  }
  if (!i.opt.visibility.empty()) {
    FloatImage img{w, h, std::vector<float>(size_t(w) * h)};
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glReadPixels(0, 0, w, h, GL_RED, GL_FLOAT, img.pixels.data());
    writePfm(i.opt.visibility, img);
    std::printf("wrote %s\n", fs::absolute(i.opt.visibility).string().c_str());
  }
  if (!i.opt.bench.empty()) {
    std::ofstream csv(i.opt.bench);
    if (!csv) throw UsageError("cannot write --bench file '" + i.opt.bench + "'");
    const double frameMs = i.wallCount ? i.wallSum / i.wallCount : 0;
    csv << "lab,renderer,size,pass,gpu_ms_mean,gpu_ms_min,gpu_ms_max,frames\n";
    std::printf("lab %s on %s, %dx%d, %d frames measured after %d warm-up\n", number_.c_str(),
                Context::renderer().c_str(), w, h, i.wallCount, i.warmup);
    std::printf("  %-14s %10s %10s %10s\n", "pass", "mean ms", "min ms", "max ms");
    for (const auto& [name, s] : i.passes) {
      const double mean = s.count ? s.sum / s.count : 0;
      csv << "lab" << number_ << ",\"" << Context::renderer() << "\"," << w << "x" << h << "," << name << "," << mean
          << "," << s.min << "," << s.max << "," << s.count << "\n";
      std::printf("  %-14s %10.3f %10.3f %10.3f\n", name.c_str(), mean, s.min, s.max);
    }
    csv << "lab" << number_ << ",\"" << Context::renderer() << "\"," << w << "x" << h << ",frame_wall," << frameMs
        << ",,," << i.wallCount << "\n";
    std::printf("  %-14s %10.3f   => %.1f fps\nwrote %s\n", "frame (wall)", frameMs, frameMs > 0 ? 1000 / frameMs : 0.0,
                fs::absolute(i.opt.bench).string().c_str());
  }
}

}  // namespace wb
