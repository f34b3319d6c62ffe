# cmake -P FillFromStubs.cmake: the student edition's build of one lab (fill_NN, before its exercise
# files compile) gives a file written before one of its exercises was added (a new edition of the
# labs mid-term) that exercise's stub, from the stubs as handed out, as ./workbook check and the
# grader do: wb_check --fill-missing (common/exercise/exercise_chunks.hpp), one line each. Where
# there is no ./workbook (a Windows laptop: cmake --build build --target check_NN) this is what does it.
#   -DWB_CHECK=path/to/wb_check -DSTUBS=tests/stubs/NN_name -DLAB_DIR=labs/NN_name -DLAB=NN_name
file(GLOB_RECURSE stubs RELATIVE ${STUBS} ${STUBS}/exercise*)
list(SORT stubs)
foreach(rel IN LISTS stubs)
  if(EXISTS ${LAB_DIR}/${rel})
    execute_process(COMMAND ${WB_CHECK} --fill-missing ${LAB_DIR}/${rel} ${STUBS}/${rel} labs/${LAB}/${rel}
                            tests/stubs/${LAB}/${rel} check)
  endif()
endforeach()
