/// @file context.hpp
/// An OpenGL 4.1 core context: a GLFW window, or a headless one: EGL surfaceless on Linux (Mesa
/// llvmpipe), a hidden GLFW window on macOS and Windows. Both sit behind one interface so labs and tests never care
/// which one they got.
#pragma once
#include <glm/vec2.hpp>

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace wb {

/// How to create a context.
struct ContextOptions {
  bool headless = false;    ///< no window: EGL surfaceless (Linux) or a hidden window (macOS, Windows)
  int width = 960;          ///< window width in pixels (ignored when headless)
  int height = 540;         ///< window height in pixels (ignored when headless)
  std::string title;        ///< window title
  bool debug = true;        ///< request a debug context and install the KHR_debug callback
  bool fullscreen = false;  ///< the window fills the primary monitor (ignored when headless)
};

/// A current GL context; destroying it releases the window or EGL display.
class Context {
 public:
  /// Creates the context and makes it current; throws wb::ContextError with a hint on failure.
  static std::unique_ptr<Context> create(const ContextOptions& options);
  virtual ~Context() = default;
  /// True for a headless context (EGL surfaceless, or a hidden window).
  virtual bool headless() const = 0;
  /// The GLFW window, or nullptr when headless.
  virtual GLFWwindow* window() const { return nullptr; }
  /// True once the user closed the window (never for headless).
  virtual bool shouldClose() const { return false; }
  /// Presents the frame and polls events (no-op when headless).
  virtual void endFrame() {}
  /// The default framebuffer's size in pixels ({0,0} when headless).
  virtual glm::ivec2 framebufferSize() const { return {0, 0}; }
  /// The window's size in the window system's units (points on a Mac: half the framebuffer's pixels
  /// on a Retina display); {0, 0} headless. Only for the ratio of the two: everything drawn or read
  /// back uses framebufferSize().
  virtual glm::ivec2 windowSize() const { return {0, 0}; }
  /// Switches the window between the primary monitor (at its resolution) and a window of `size`.
  virtual void setFullscreen(bool, glm::ivec2) {}
  /// The monitor's content scale (2 on a Retina display, 1.5 at 150% on Windows); 1 when headless.
  virtual float contentScale() const { return 1.0f; }
  /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  static std::string renderer();
  /// GL_VERSION, e.g. "4.1 (Core Profile) Mesa 22.3.6".
  static std::string version();
};

/// GL errors reported through KHR_debug since the last call, oldest first; clears the list.
std::vector<std::string> takeGlErrors();

}  // namespace wb
