/// @file imgui_backends.hpp
/// Dear ImGui's GLFW and OpenGL 3 backends, wherever the package puts them: in backends/ beside
/// imgui.h (Debian's and Ubuntu's libimgui-dev, a source checkout), or beside imgui.h itself (vcpkg).
#pragma once
#if __has_include(<backends/imgui_impl_glfw.h>)
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#else
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#endif
