# The installed tree (bin/prt, lib/libprt_trace.so and its other builds) runs wherever it is
# moved: the executable finds the trace library relative to itself.
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DSCENE=... -P install_tree_test.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/first"
                RESULT_VARIABLE code OUTPUT_QUIET)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${code})")
endif()
file(RENAME "${WORK_DIR}/first" "${WORK_DIR}/moved")
execute_process(COMMAND "${WORK_DIR}/moved/bin/prt" --version
                RESULT_VARIABLE code OUTPUT_VARIABLE version ERROR_VARIABLE version)
if(NOT code EQUAL 0 OR NOT version MATCHES "trace kernels: ")
  message(FATAL_ERROR "the moved prt does not run (${code}): ${version}")
endif()
execute_process(COMMAND "${WORK_DIR}/moved/bin/prt" render "${SCENE}" --width 16 --height 12
                        --quiet -o "${WORK_DIR}/image.png"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT code EQUAL 0 OR NOT EXISTS "${WORK_DIR}/image.png")
  message(FATAL_ERROR "the moved prt does not render (${code}): ${out}")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
