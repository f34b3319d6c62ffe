#include "common/platform/context.hpp"

#include "common/base/error.hpp"
#include "common/platform/gl.hpp"

#if WB_HAVE_EGL
#include <glad/egl.h>
#endif
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>

namespace wb {
namespace {

std::mutex g_errorMutex;
std::vector<std::string> g_glErrors;

// KHR_debug: errors are collected (tests fail on them, debug builds stop on them); performance and
// portability warnings are printed once so students see them without drowning in them.
void APIENTRY onGlDebug(GLenum source, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                        const void*) {
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;  // Program reports these with file:line
  if (type == GL_DEBUG_TYPE_ERROR) {
    std::lock_guard<std::mutex> lock(g_errorMutex);
    g_glErrors.emplace_back(message);
  } else if (severity == GL_DEBUG_SEVERITY_HIGH) {
    std::fprintf(stderr, "GL: %s\n", message);
  }
}

// Core in 4.3, KHR_debug before: macOS's 4.1 has neither, and then GL errors go unreported. Mesa
// cannot turn the extension off, so WB_GL_NO_KHR_DEBUG=1 takes it as missing, to run that path here.
bool hasDebugOutput() {
  const char* off = std::getenv("WB_GL_NO_KHR_DEBUG");
  return GLAD_GL_KHR_debug && !(off && std::string(off) == "1");  // (glad sets it where the context lists it)
}

void installDebugOutput() {
  if (!hasDebugOutput()) {
    static std::once_flag said;
    std::call_once(said, [] {
      std::fprintf(stderr, "GL: no KHR_debug here (as on macOS): OpenGL errors are not reported as they happen\n");
    });
    return;
  }
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);       // the callback runs inside the failing call
  glDebugMessageCallback(onGlDebug, nullptr);  // gl41-optional
}

// The workbook's OpenGL: 4.1 core, macOS's ceiling (the loader, third_party/glad, has nothing newer).
constexpr int kGlMajor = 4, kGlMinor = 1;

void requireGl41(const char* how) {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < kGlMajor * 10 + kGlMinor)
    throw ContextError(std::string(how) + " gave OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                       ", but the workbook needs 4.1 core. On Linux, install Mesa (sudo apt-get install "
                       "libgl1-mesa-dri libegl-mesa0); elsewhere, update the graphics driver.");
}

#if WB_HAVE_EGL

class EglContext final : public Context {
 public:
  explicit EglContext(bool debug) {
    // glad's EGL loader runs twice: once for the client entry points, once for the display's.
    if (!gladLoaderLoadEGL(EGL_NO_DISPLAY))
      throw ContextError("cannot load libEGL. Install it with: sudo apt-get install libegl1 libegl-mesa0");
    // Before eglInitialize only client entry points are known; check the pointers, not versions.
    if (glad_eglGetPlatformDisplay)
      display_ = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    else if (glad_eglGetPlatformDisplayEXT)
      display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY) display_ = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor))
      throw ContextError(
          "no EGL display (surfaceless Mesa). Install it with: "
          "sudo apt-get install libegl-mesa0 libgl1-mesa-dri");
    gladLoaderLoadEGL(display_);
    eglBindAPI(EGL_OPENGL_API);
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                              kGlMajor,
                              EGL_CONTEXT_MINOR_VERSION,
                              kGlMinor,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_CONTEXT_OPENGL_DEBUG,
                              debug ? EGL_TRUE : EGL_FALSE,
                              EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context_ == EGL_NO_CONTEXT || !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw ContextError(
          "EGL could not create a surfaceless OpenGL 4.1 core context "
          "(EGL error 0x" +
          hex(eglGetError()) + "). Mesa 20 or newer provides one.");
    if (!gladLoaderLoadGL()) throw ContextError("cannot load OpenGL entry points through EGL");
    requireGl41("EGL");
  }
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  bool headless() const override { return true; }

 private:
  static std::string hex(EGLint v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04x", static_cast<unsigned>(v));
    return buf;
  }
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};
#endif

std::string g_glfwError;

// A GLFW window; `hidden` for headless rendering where there is no EGL (macOS, Windows): the
// window is never shown, and the lab draws into its own framebuffer as it does with EGL.
class GlfwContext final : public Context {
 public:
  GlfwContext(const ContextOptions& o, bool hidden) : hidden_(hidden) {
    glfwSetErrorCallback([](int, const char* msg) { g_glfwError = msg; });
#if !defined(__APPLE__) && !defined(_WIN32)
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland))
      throw ContextError(
          "no display found (DISPLAY and WAYLAND_DISPLAY are not set). "
          "Add --headless to render to a file instead, e.g. --headless --screenshot out.png");
#endif
    if (!glfwInit())
      throw ContextError("cannot open the display (" + g_glfwError + "). Add --headless to render to a file instead.");
    // GLFW's hints for a core profile on macOS (glfw.org/docs/latest/window_guide.html): 3.2 or
    // later, core, forward compatible (macOS refuses a core context without it). Retina: the
    // framebuffer has the display's pixels, and every viewport uses glfwGetFramebufferSize.
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, kGlMajor);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, kGlMinor);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_COCOA_RETINA_FRAMEBUFFER, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, o.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, hidden ? GLFW_FALSE : GLFW_TRUE);
    GLFWmonitor* monitor = o.fullscreen && !hidden ? glfwGetPrimaryMonitor() : nullptr;
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    // (hidden: a small window, whatever the size asked, as headless draws into framebuffer objects; the
    // tests ask for 0 x 0, which GLFW refuses)
    window_ = mode ? glfwCreateWindow(mode->width, mode->height, o.title.c_str(), monitor, nullptr)
                   : glfwCreateWindow(hidden ? 64 : o.width, hidden ? 64 : o.height, o.title.c_str(), nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw ContextError(
          "cannot create an OpenGL 4.1 core window (" + g_glfwError +
          (hidden ? "). Update the graphics driver." : "). Add --headless to use Mesa's software renderer instead."));
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(hidden ? 0 : 1);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)))
      throw ContextError("cannot load OpenGL entry points through GLFW");
    requireGl41("the window system");
  }
  ~GlfwContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  bool headless() const override { return hidden_; }
  GLFWwindow* window() const override { return hidden_ ? nullptr : window_; }
  bool shouldClose() const override { return !hidden_ && glfwWindowShouldClose(window_); }
  void endFrame() override {
    if (hidden_) return;
    glfwSwapBuffers(window_);
    glfwPollEvents();
  }
  void setFullscreen(bool on, glm::ivec2 size) override {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (hidden_ || !mode) return;
    if (on)
      glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
    else
      glfwSetWindowMonitor(window_, nullptr, 40, 40, size.x, size.y, GLFW_DONT_CARE);
  }
  float contentScale() const override {
    float x = 1, y = 1;
    if (!hidden_) glfwGetWindowContentScale(window_, &x, &y);
    return y > 0 ? y : 1.0f;
  }
  glm::ivec2 framebufferSize() const override {
    if (hidden_) return {0, 0};
    glm::ivec2 s;
    glfwGetFramebufferSize(window_, &s.x, &s.y);
    return s;
  }
  glm::ivec2 windowSize() const override {
    if (hidden_) return {0, 0};
    glm::ivec2 s;
    glfwGetWindowSize(window_, &s.x, &s.y);
    return s;
  }

 private:
  GLFWwindow* window_ = nullptr;
  bool hidden_ = false;
};

}  // namespace

std::unique_ptr<Context> Context::create(const ContextOptions& options) {
  std::unique_ptr<Context> ctx;
#if WB_HAVE_EGL
  if (options.headless)
    ctx = std::make_unique<EglContext>(options.debug);
  else
    ctx = std::make_unique<GlfwContext>(options, false);
#else
  ctx = std::make_unique<GlfwContext>(options, options.headless);
#endif
  if (options.debug) installDebugOutput();
  return ctx;
}

std::string Context::version() {
  const GLubyte* v = glGetString(GL_VERSION);
  return v ? reinterpret_cast<const char*>(v) : "unknown";
}

std::string Context::renderer() {
  const GLubyte* r = glGetString(GL_RENDERER);
  return r ? reinterpret_cast<const char*>(r) : "unknown";
}

std::vector<std::string> takeGlErrors() {
  std::lock_guard<std::mutex> lock(g_errorMutex);
  return std::exchange(g_glErrors, {});
}

}  // namespace wb
