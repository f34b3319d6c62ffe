# The workbook's dependencies, found the same way on Debian/Ubuntu (apt), macOS (Homebrew) and
# Windows (vcpkg's manifest, vcpkg.json). Each library the framework links is one target:
# glfw, glm::glm, nlohmann_json::nlohmann_json, GTest::gtest, embree, wb_imgui, wb_stb.
find_package(glfw3 3.3 REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
# GoogleTest: the system's package, or its sources built here with this build's compiler and standard
# library (WB_GTEST_SOURCE_DIR, e.g. Debian's /usr/src/googletest): a build with libc++, the Mac's
# standard library, cannot link a GoogleTest built with libstdc++ (tools/platforms/mac_profile.sh).
set(WB_GTEST_SOURCE_DIR "" CACHE PATH "GoogleTest's sources, built here instead of the installed package")
if(WB_GTEST_SOURCE_DIR)
  set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
  set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
  add_subdirectory(${WB_GTEST_SOURCE_DIR} ${CMAKE_BINARY_DIR}/googletest EXCLUDE_FROM_ALL)
  get_target_property(gtest_includes gtest INTERFACE_INCLUDE_DIRECTORIES)  # (its headers' warnings are not ours)
  set_target_properties(gtest PROPERTIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${gtest_includes}")
  if(NOT TARGET GTest::gtest)  # (GoogleTest 1.11 and later name them so themselves)
    add_library(GTest::gtest ALIAS gtest)
    add_library(GTest::gtest_main ALIAS gtest_main)
  endif()
else()
  find_package(GTest REQUIRED)
endif()
# Embree 3 (Debian 12, Ubuntu 22.04) or 4 (Ubuntu 24.04, Homebrew, vcpkg): both export `embree`.
find_package(embree CONFIG REQUIRED)

# Dear ImGui with its GLFW and OpenGL 3 backends: vcpkg's port has a CMake package (imgui::imgui);
# Debian's and Ubuntu's libimgui-dev a pkg-config file; elsewhere, WB_IMGUI_DIR names a checkout
# of its sources (git clone https://github.com/ocornut/imgui), built here.
add_library(wb_imgui INTERFACE)
set(WB_IMGUI_DIR "" CACHE PATH "Dear ImGui's source folder, where no package provides it (macOS)")
find_package(imgui CONFIG QUIET)
if(WB_IMGUI_DIR)
  if(NOT EXISTS ${WB_IMGUI_DIR}/imgui.cpp OR NOT EXISTS ${WB_IMGUI_DIR}/backends/imgui_impl_glfw.cpp)
    message(FATAL_ERROR "WB_IMGUI_DIR=${WB_IMGUI_DIR} has no Dear ImGui sources (imgui.cpp, backends/). Get them "
                        "with: git clone --depth 1 https://github.com/ocornut/imgui ${WB_IMGUI_DIR}")
  endif()
  add_library(wb_imgui_sources STATIC
    ${WB_IMGUI_DIR}/imgui.cpp ${WB_IMGUI_DIR}/imgui_draw.cpp ${WB_IMGUI_DIR}/imgui_tables.cpp
    ${WB_IMGUI_DIR}/imgui_widgets.cpp ${WB_IMGUI_DIR}/backends/imgui_impl_glfw.cpp
    ${WB_IMGUI_DIR}/backends/imgui_impl_opengl3.cpp)
  target_include_directories(wb_imgui_sources SYSTEM PUBLIC ${WB_IMGUI_DIR} ${WB_IMGUI_DIR}/backends)
  target_link_libraries(wb_imgui_sources PUBLIC glfw)
  target_link_libraries(wb_imgui INTERFACE wb_imgui_sources)
elseif(TARGET imgui::imgui)
  target_link_libraries(wb_imgui INTERFACE imgui::imgui)
else()
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
  target_link_libraries(wb_imgui INTERFACE PkgConfig::IMGUI)
endif()

# stb's single-file headers: /usr/include/stb on Debian and Ubuntu, include/ in vcpkg, or a checkout
# in third_party/stb (macOS: Homebrew has no stb).
find_path(WB_STB_DIR stb_image.h HINTS ${PROJECT_SOURCE_DIR}/third_party/stb PATH_SUFFIXES stb REQUIRED)
add_library(wb_stb INTERFACE)
target_include_directories(wb_stb SYSTEM INTERFACE ${WB_STB_DIR})
