# The glad 2 loader for OpenGL 4.1 core (+ EGL 1.5 where there is EGL), committed in third_party/glad
# (tools/platforms/glad.sh makes it; ctest framework.glad_matches_generator checks it). Nothing is generated or
# downloaded at build time, so Ubuntu 22.04 and vcpkg, whose glad is 0.1, build it as Debian does.
set(WB_GLAD_DIR ${PROJECT_SOURCE_DIR}/third_party/glad)
set(WB_GLAD_SOURCES ${WB_GLAD_DIR}/src/gl.c)
if(WB_HAVE_EGL)
  list(APPEND WB_GLAD_SOURCES ${WB_GLAD_DIR}/src/egl.c)
endif()
wb_framework_library(glad ${WB_GLAD_SOURCES})
target_include_directories(glad SYSTEM ${WB_FRAMEWORK_SCOPE} ${WB_GLAD_DIR}/include)
target_link_libraries(glad ${WB_FRAMEWORK_SCOPE} ${CMAKE_DL_LIBS})
set_target_properties(glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
