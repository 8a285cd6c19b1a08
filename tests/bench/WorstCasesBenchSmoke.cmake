# Smoke test of `lacrima-bench worst-cases --json`: the benchmark runs, prints one JSON object,
# and reports each timing as a finite number of milliseconds >= 0, and the rig's event-loop
# figures for the head it rigged (without a head it skips, or fails under CI=true). Speed is not checked here: figures are
# read, never asserted.
#   cmake -DBENCH=<path to lacrima-bench> -P WorstCasesBenchSmoke.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../support/MissingData.cmake)
execute_process(COMMAND "${BENCH}" worst-cases --runs 1 --json
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "lacrima-bench worst-cases exited with ${status}: ${err}")
endif()
foreach(figure bake_ten_minutes_ms long_line_parse_ms long_line_read_file_ms)
  string(JSON median ERROR_VARIABLE parseError GET "${out}" ${figure} median)
  if(parseError OR NOT median MATCHES "^[0-9.eE+-]+$" OR median LESS 0)
    message(FATAL_ERROR "${figure}: expected a median in milliseconds: ${parseError}\n${out}")
  endif()
endforeach()
string(JSON skipped ERROR_VARIABLE notSkipped GET "${out}" rig_stall skipped)
if(NOT notSkipped)
  lacrima_missing_data("lacrima-bench worst-cases rigged no head (${skipped})")
  return()
endif()
string(JSON rigMs GET "${out}" rig_stall rig_ms)
string(JSON ticks GET "${out}" rig_stall ticks)
string(JSON stall GET "${out}" rig_stall longest_stall_ms)
if(NOT rigMs GREATER 0 OR ticks LESS 0 OR stall LESS 0 OR stall GREATER rigMs)
  message(FATAL_ERROR "implausible rig figures: ${rigMs} ms, ${ticks} ticks, stall ${stall} ms")
endif()
message(STATUS "lacrima-bench worst-cases: rig ${rigMs} ms, ${ticks} ticks, stall ${stall} ms")
