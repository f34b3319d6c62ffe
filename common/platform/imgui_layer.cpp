#include "common/platform/imgui_layer.hpp"

#include "common/platform/font.hpp"
#include "common/platform/imgui_backends.hpp"

namespace wb {
namespace {
constexpr float kBasePixels = 16.0f, kBakePixels = 32.0f;
}  // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x03BB, 0x03C3, 0x2013, 0x2026, 0x2190, 0x2192, 0x2248, 0x2265, 0};
  const std::filesystem::path ttf = findFontFile();
  if (!ttf.empty() && ImGui::GetIO().Fonts->AddFontFromFileTTF(ttf.string().c_str(), kBakePixels, nullptr, ranges))
    bakedPixels_ = kBakePixels;
  base_ = ImGui::GetStyle();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 410 core");
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::setScale(float scale) {
  if (scale == scale_) return;
  scale_ = scale;
  ImGui::GetIO().FontGlobalScale = kBasePixels * scale / bakedPixels_;
  ImGui::GetStyle() = base_;
  ImGui::GetStyle().ScaleAllSizes(scale);
}

}  // namespace wb
