/// @file imgui_layer.hpp
/// Dear ImGui with its GLFW and OpenGL 3 backends for a lab's window: created in the canonical
/// order, shut down in reverse. The panels' text is DejaVu Sans (the frames' labels' font, common/
/// font.hpp), baked at 32 px and drawn at 16 px times the UI scale (ui.scale), with the symbols the
/// panels print (±, ×, µ, ≤, σ); ImGui's own font where no TTF is found.
#pragma once
#include <imgui.h>

struct GLFWwindow;

namespace wb {

/// The ImGui context and its backends for one window (LabHost owns one when it has a window).
class ImGuiLayer {
 public:
  /// Starts ImGui on `window` (its context current).
  explicit ImGuiLayer(GLFWwindow* window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;
  /// Text 16 px times `scale` tall, and the paddings and widgets scaled with it.
  void setScale(float scale);
  /// The scale last set (text 16 px times it tall, in ImGui's units).
  float scale() const { return scale_; }

 private:
  float bakedPixels_ = 13.0f;  // ImGui's own font when no TTF is found
  float scale_ = 0.0f;
  ImGuiStyle base_;
};

}  // namespace wb
