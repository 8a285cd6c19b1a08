# Smoke test of `lacrima-bench proposal --json`: the benchmark runs, prints one JSON object, and
# what it reports is sane (38 proposed points in each orientation and method, finite errors, the
# same vertices in both orientations). Without the heads it skips, or fails under CI=true.
# Speed is not checked here: figures are read, never asserted.
#   cmake -DBENCH=<path to lacrima-bench> -P ProposalBenchSmoke.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../support/MissingData.cmake)
execute_process(COMMAND "${BENCH}" proposal --runs 1 --json
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "lacrima-bench proposal exited with ${status}: ${err}")
endif()
string(JSON skipped ERROR_VARIABLE noSkip GET "${out}" skipped)
if(NOT noSkip AND skipped)
  # Its note without its own "skipped: ", which is the skip marker here.
  string(REGEX REPLACE "^proposal: skipped: |\n$" "" why "${err}")
  lacrima_missing_data("lacrima-bench proposal had no head to run on (${why})")
  return()
endif()
string(JSON orientations ERROR_VARIABLE parseError LENGTH "${out}" orientations)
if(parseError)
  message(FATAL_ERROR "lacrima-bench proposal --json printed no JSON object: ${parseError}\n${out}")
endif()
if(NOT orientations EQUAL 2)
  message(FATAL_ERROR "expected 2 orientations, got ${orientations}")
endif()
foreach(o 0 1)
  foreach(m 0 1)
    string(JSON points GET "${out}" orientations ${o} methods ${m} all points)
    string(JSON mean GET "${out}" orientations ${o} methods ${m} all mean_es0)
    string(JSON worst GET "${out}" orientations ${o} methods ${m} all worst_es0)
    if(NOT points EQUAL 38 OR mean STREQUAL "null" OR worst STREQUAL "null"
       OR NOT mean GREATER 0 OR NOT worst GREATER_EQUAL mean)
      message(FATAL_ERROR "orientation ${o}, method ${m}: ${points} points, mean ${mean}, worst ${worst}")
    endif()
    string(JSON same GET "${out}" orientations ${o} methods ${m} same_vertices)
    if(NOT same)
      message(FATAL_ERROR "orientation ${o}, method ${m}: not the vertices of orientation 0")
    endif()
  endforeach()
endforeach()
string(JSON mean GET "${out}" orientations 0 methods 1 all mean_es0)
message(STATUS "lacrima-bench proposal: mean ${mean} ES0, the same vertices in both orientations")
