// The app's window side: the handout's picture, input (the mouse, bookmarks, presenter steps),
// the ImGui panels over the frame, the presenter's caption band, and window screenshots.
#include "common/platform/imgui_backends.hpp"
#include "common/shell/lab_host.hpp"

#include "common/base/variant.hpp"
#include "common/platform/context.hpp"
#include "common/platform/image.hpp"
#include "common/shell/lab.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <stb_image.h>

#include <ctime>

namespace fs = std::filesystem;

namespace wb {
void LabHost::loadPicture() {
  picture_ = Texture(), pictureSize_ = glm::ivec2(0);
  const fs::path file = stage_->board.picture();
  std::error_code ec;
  if (!imgui_ || file.empty() || !fs::is_regular_file(file, ec)) return;
  int w = 0, h = 0, n = 0;
  unsigned char* px = stbi_load(file.string().c_str(), &w, &h, &n, 4);
  if (!px) return;  // (a missing or broken picture only leaves the panel without it)
  picture_ = makeTexture2D(GL_RGBA8, w, h, GL_LINEAR);
  uploadTexture2D(picture_.id(), 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
  stbi_image_free(px);
  pictureSize_ = {w, h};
}

void LabHost::beginUiFrame() {
  applyUiScale();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  GLFWwindow* win = ctx_->window();
  const ImGuiIO& io = ImGui::GetIO();
  glm::dvec2 mouse;
  glfwGetCursorPos(win, &mouse.x, &mouse.y);
  if (!io.WantCaptureMouse) {  // never steal the mouse from a widget
    if (glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS && mouse != lastMouse_) {
      lab_->camera.orbit(float(mouse.x - lastMouse_.x), float(mouse.y - lastMouse_.y));
      panels_.showHeatmap = false;  // it was measured for the old view
    }
    lab_->camera.zoom(io.MouseWheel);
  }
  lastMouse_ = mouse;
  if (!io.WantCaptureKeyboard) handleKeys();
  const glm::ivec2 window = ctx_->framebufferSize();
  glm::ivec2 scene = window;
  if (step_ > 0) scene.y = window.y - Presenter::bandHeight(window, pixelsPerPoint());  // the caption's band
  viewSize_ = glm::max(scene, glm::ivec2(16));
  // render.scale: the scene is drawn smaller and stretched over the window; the panels stay sharp.
  frameSize_ = glm::max(glm::ivec2(glm::round(glm::vec2(viewSize_) * shared_.renderScale)), glm::ivec2(16));
}

void LabHost::handleKeys() {
  GLFWwindow* win = ctx_->window();
  auto pressed = [&](int key) {  // true once per press, so holding a key does not repeat
    const bool down = glfwGetKey(win, key) == GLFW_PRESS, was = keyDown_[key];
    keyDown_[key] = down;
    return down && !was;
  };
  for (int k = 0; k < 9; ++k)
    if (pressed(GLFW_KEY_1 + k)) shared_.goToBookmark(k + 1, lab_->scene, lab_->camera);  // (none: nothing)
  if (pressed(GLFW_KEY_F12) || pressed(GLFW_KEY_P)) screenshotRequested_ = true;
  if (pressed(GLFW_KEY_H)) shared_.uiPanels = !shared_.uiPanels;
  if (pressed(GLFW_KEY_F11)) fullscreen_ = !fullscreen_, ctx_->setFullscreen(fullscreen_, options_.size);
  stepKeys(pressed);
}

// The lab's demo.json (or --demo FILE): the presenter's steps for Page Down/Up and --demo-step. A
// window without a readable demo still runs (and says why); asking for one makes it an error.
void LabHost::startPresenter() {
  presenter_.reset(), step_ = 0;
  const bool named = !options_.demo.empty(), needed = named || options_.demoStep > 0;
  const fs::path demo = named ? fs::path(options_.demo) : fs::path(variant::kLabDir) / "demo.json";
  if (!fs::exists(demo)) {
    if (needed) throw UsageError("the demo " + demo.string() + " does not exist");
    return;
  }
  try {
    presenter_ = std::make_unique<Presenter>(demo, lab_->settings);
  } catch (const UsageError& e) {
    if (needed) throw;
    stage_->warn(e.what());
    return;
  }
  if (options_.demoStep > 0) showStep(options_.demoStep);
}

// Presenter mode: Page Down / Right the next step, Page Up / Left the one before, Escape leaves.
void LabHost::stepKeys(const std::function<bool(int)>& pressed) {
  // Every key is read (not ||'s short cut): pressed() keeps each key's last state, for its edges.
  const bool pageDown = pressed(GLFW_KEY_PAGE_DOWN), right = pressed(GLFW_KEY_RIGHT);
  const bool pageUp = pressed(GLFW_KEY_PAGE_UP), left = pressed(GLFW_KEY_LEFT);
  const bool next = pageDown || right, back = pageUp || left;
  const bool leave = pressed(GLFW_KEY_ESCAPE);
  if (!presenter_ || !(next || back || leave)) return;
  const int k = leave ? 0 : std::clamp(step_ + (next ? 1 : -1), 1, presenter_->count());
  try {
    showStep(k);
  } catch (const UsageError& e) {
    stage_->warn(e.what());
  }
}

void LabHost::presentWindow() {
  const glm::ivec2 size = target_.size(), window = ctx_->framebufferSize(), shown = glm::min(viewSize_, window);
  const int band = step_ > 0 ? std::max(0, window.y - shown.y) : 0;  // the presenter's caption, below
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_.framebuffer());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  {
    auto timer = timers_.scope("blit");  // (a window's extra passes are timed too: ./workbook bench NN --window)
    if (size == shown)
      glBlitFramebuffer(0, 0, size.x, size.y, 0, band, size.x, band + size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    else
      upscale(band, shown);
  }
  if (stretched() && panels_.compare.on && !panels_.compare.key.empty()) {  // the halves' labels, sharp
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, band, shown.x, shown.y);
    split_.drawLabels(panels_.compare, shown, pixelsPerPoint());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, window.x, window.y);
  Lab& lab = *lab_;
  const int bookmark = shared_.bookmark;
  auto labUi = [&] {  // the shared settings are applied before the lab's own widgets read them
    if (shared_.bookmark != bookmark) shared_.goToBookmark(shared_.bookmark, lab.scene, lab.camera);
    lab.lightIndex = std::min(lab.lightIndex, int(lab.scene.lights.size()) - 1);
    lab.ui();
  };
  panels_.hidePanels = !shared_.uiPanels;
  if (step_ == 0)  // presenting: the picture and its caption, no panels
    drawPanels({stage_->board, checks_.get(), timers_, stage_->programs, stage_->warnings, lab.settings, shown,
                picture_.id(), pictureSize_, labUi, symptoms_ ? &symptoms_->line() : nullptr},
               panels_);
  // The hunts' symptom, once the view has held still after a change (not while presenting).
  const bool due = symptoms_ && step_ == 0 && symptoms_->due(lab.settings, lab.shown().viewProj, frameSize_, reloads_);
  if (panels_.measureRequested)
    panels_.measureRequested = false, measureNow(true);
  else if (due)
    measureFrame();
  ImGui::Render();
  {
    auto timer = timers_.scope("panels");
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }
  if (step_ > 0) presenter_->drawBand(step_, measureStep_ ? "measuring..." : stepNumbers_, window, pixelsPerPoint());
  // In a window, --screenshot captures the last frame as the user sees it, UI included.
  const bool lastFrame = options_.frames > 0 && frameIndex_ == options_.frames - 1 && !options_.screenshot.empty();
  if (screenshotRequested_ || lastFrame) {
    screenshotRequested_ = false;
    char stamp[32];
    const std::time_t t = std::time(nullptr);
    std::strftime(stamp, sizeof stamp, "%Y%m%d_%H%M%S", std::localtime(&t));
    saveWindowScreenshot(lastFrame ? options_.screenshot
                                   : "screenshots/lab" + stage_->board.number() + "_" + stamp + ".png");
  }
  ctx_->endFrame();
}

// render.scale below 1: the frame is drawn over the window's scene area as a textured triangle,
// filtered linearly (a scaling glBlitFramebuffer costs llvmpipe 8.5 ms at 1080p, this about a third).
void LabHost::upscale(int band, glm::ivec2 shown) {
  if (!upscale_.ok())
    upscale_ = Program({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/upscale.frag"}});
  if (!emptyVao_.id()) {
    emptyVao_ = makeEmptyVertexArray();
    linear_ = makePlainSampler();  // (clamped; filtered linearly for the stretch)
    glSamplerParameteri(linear_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(linear_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, band, shown.x, shown.y);
  glDisable(GL_DEPTH_TEST);
  upscale_.use();
  upscale_.set("u_frame", 0);
  bindTexture(0, target_.attachment(0));
  glBindSampler(0, linear_.id());
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(0, 0);
  glEnable(GL_DEPTH_TEST);
}

void LabHost::saveWindowScreenshot(const std::string& path) {
  const glm::ivec2 size = ctx_->framebufferSize();  // the window as the user sees it
  std::vector<uint8_t> px(size_t(size.x) * size_t(size.y) * 4);
  glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  writePng(path, size.x, size.y, px);
  panels_.lastScreenshot = path;
  written_.emplace_back("screenshot", path);
  say("wrote " + fs::absolute(path).string());
}

}  // namespace wb
