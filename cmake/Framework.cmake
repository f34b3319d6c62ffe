# The framework's static libraries (glad, wb_common, wb_testing) and the tests' main (an object, so
# that its tests are always linked in): compiled here, or linked from a folder where another build of
# this same source left them (WB_PREBUILT_FRAMEWORK). The grader's runner tree
# (tools/grading/workspace.py) takes them from the judge's build, so that preparing it compiles only
# the labs, not the framework a second time. They hold no solution: the labs' exercise files, tests
# and held-out tests are compiled in the lab targets, never in these.
set(WB_PREBUILT_FRAMEWORK "" CACHE PATH "A folder with libglad.a, libwb_common.a, libwb_testing.a and main.cpp.o built from this source")
if(WB_PREBUILT_FRAMEWORK)
  set(WB_FRAMEWORK_SCOPE INTERFACE)  # (an imported library has only usage requirements)
else()
  set(WB_FRAMEWORK_SCOPE PUBLIC)
endif()

# The prebuilt `file` of the framework target `name` (a STATIC or OBJECT library), imported.
function(_wb_import_prebuilt name kind file)
  if(NOT EXISTS ${WB_PREBUILT_FRAMEWORK}/${file})
    message(FATAL_ERROR "WB_PREBUILT_FRAMEWORK: ${WB_PREBUILT_FRAMEWORK}/${file} is missing; build the framework "
                        "there, or leave the option empty")
  endif()
  add_library(${name} ${kind} IMPORTED GLOBAL)
  set(property IMPORTED_LOCATION)
  if(kind STREQUAL "OBJECT")
    set(property IMPORTED_OBJECTS)
  endif()
  set_target_properties(${name} PROPERTIES ${property} ${WB_PREBUILT_FRAMEWORK}/${file})
endfunction()

function(wb_framework_library name)
  if(WB_PREBUILT_FRAMEWORK)
    _wb_import_prebuilt(${name} STATIC lib${name}.a)
  else()
    add_library(${name} STATIC ${ARGN})
  endif()
endfunction()

function(wb_framework_objects name source)
  if(WB_PREBUILT_FRAMEWORK)
    get_filename_component(object ${source} NAME)
    _wb_import_prebuilt(${name} OBJECT ${object}.o)
  else()
    add_library(${name} OBJECT ${source})
  endif()
endfunction()

function(wb_framework_warnings name)
  if(NOT WB_PREBUILT_FRAMEWORK)
    target_compile_options(${name} PRIVATE ${WB_WARNINGS})
  endif()
endfunction()
