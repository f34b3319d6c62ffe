# glad2 loader for GL 4.5 core + EGL 1.5, generated at configure time by Debian's python3-glad.
# The generated files live in the build tree only; nothing is committed and nothing is downloaded.
find_program(WB_SYSTEM_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT WB_SYSTEM_PYTHON3)
  find_program(WB_SYSTEM_PYTHON3 python3 REQUIRED)
endif()
set(WB_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
if(NOT EXISTS ${WB_GLAD_DIR}/src/gl.c OR NOT EXISTS ${WB_GLAD_DIR}/src/egl.c)
  message(STATUS "Generating the glad loader with ${WB_SYSTEM_PYTHON3} -m glad")
  execute_process(
    COMMAND ${WB_SYSTEM_PYTHON3} -m glad --quiet --api gl:core=4.5,egl=1.5 --out-path ${WB_GLAD_DIR}
            --reproducible c --loader
    RESULT_VARIABLE glad_result OUTPUT_QUIET ERROR_VARIABLE glad_error)
  if(NOT glad_result EQUAL 0)
    # glad 1 (Ubuntu 22.04's python3-glad 0.1.30) has --api too, but no `c` command: it fails here.
    message(FATAL_ERROR "Generating glad failed: ${glad_error}\n"
                        "This needs glad 2, run with ${WB_SYSTEM_PYTHON3}: Debian 12 and Ubuntu 24.04 ship it "
                        "as python3-glad (sudo apt-get install python3-glad). Ubuntu 22.04's python3-glad is "
                        "glad 1; there, install glad 2 with: sudo ${WB_SYSTEM_PYTHON3} -m pip install glad2 "
                        "(tools/gradescope/setup.sh does).")
  endif()
endif()
wb_framework_library(glad ${WB_GLAD_DIR}/src/gl.c ${WB_GLAD_DIR}/src/egl.c)
target_include_directories(glad SYSTEM ${WB_FRAMEWORK_SCOPE} ${WB_GLAD_DIR}/include)
target_link_libraries(glad ${WB_FRAMEWORK_SCOPE} ${CMAKE_DL_LIBS})
set_target_properties(glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
