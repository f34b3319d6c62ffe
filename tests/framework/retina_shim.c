/* A Retina display on Linux, for retina_test.sh (LD_PRELOAD): GLFW reports the window's size and
 * the cursor in points, half the framebuffer's pixels, and a content scale of 2, as macOS does.
 * With WB_RETINA_SHIM_BROKEN=1 the framebuffer's size is halved too: what code that took the
 * window's size for the framebuffer's would see, so the test shows that it can fail. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdlib.h>

typedef struct GLFWwindow GLFWwindow;

void glfwGetWindowSize(GLFWwindow* window, int* width, int* height) {
  void (*real)(GLFWwindow*, int*, int*) = (void (*)(GLFWwindow*, int*, int*))dlsym(RTLD_NEXT, "glfwGetWindowSize");
  int w = 0, h = 0;
  real(window, &w, &h);
  if (width) *width = w / 2;
  if (height) *height = h / 2;
}

void glfwGetFramebufferSize(GLFWwindow* window, int* width, int* height) {
  void (*real)(GLFWwindow*, int*, int*) = (void (*)(GLFWwindow*, int*, int*))dlsym(RTLD_NEXT, "glfwGetFramebufferSize");
  const char* broken = getenv("WB_RETINA_SHIM_BROKEN");
  const int by = broken && broken[0] == '1' ? 2 : 1;
  int w = 0, h = 0;
  real(window, &w, &h);
  if (width) *width = w / by;
  if (height) *height = h / by;
}

void glfwGetCursorPos(GLFWwindow* window, double* x, double* y) {
  void (*real)(GLFWwindow*, double*, double*) =
      (void (*)(GLFWwindow*, double*, double*))dlsym(RTLD_NEXT, "glfwGetCursorPos");
  double px = 0, py = 0;
  real(window, &px, &py);
  if (x) *x = px / 2;
  if (y) *y = py / 2;
}

void glfwGetWindowContentScale(GLFWwindow* window, float* x, float* y) {
  (void)window;
  if (x) *x = 2.0f;
  if (y) *y = 2.0f;
}
