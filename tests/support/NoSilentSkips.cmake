# Runs suites with their data out of reach: the default head (an empty cache folder) and the
# reference material ../shared ($LACRIMA_SHARED_DIR pointing at an empty folder). Without
# CI=true their cases skip and the suite passes; with CI=true they fail, naming what is missing
# (tests/support/MissingData.h). Arguments: -DWORK=<scratch folder> and, as lists of equal
# length, -DSUITES=<suite executables> -DCAUSES=<what each suite's message must name>.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/cache" "${WORK}/shared")
foreach(suite cause IN ZIP_LISTS SUITES CAUSES)
  foreach(ci false true)
    execute_process(
      COMMAND ${CMAKE_COMMAND} -E env CI=${ci} XDG_CACHE_HOME=${WORK}/cache LACRIMA_CACHE_DIR=
              LACRIMA_SHARED_DIR=${WORK}/shared QT_QPA_PLATFORM=offscreen "${suite}"
      RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(ci STREQUAL "false")
      if(NOT rc EQUAL 0 OR NOT out MATCHES "SKIP" OR NOT out MATCHES "${cause}")
        message(FATAL_ERROR "without CI=true ${suite} should skip, naming '${cause}', and pass "
                            "(exit ${rc}):\n${out}${err}")
      endif()
    elseif(rc EQUAL 0 OR NOT out MATCHES "FAIL!.*${cause}, and CI=true makes that a failure")
      message(FATAL_ERROR "with CI=true ${suite} should fail, naming '${cause}' "
                          "(exit ${rc}):\n${out}${err}")
    endif()
  endforeach()
endforeach()
file(REMOVE_RECURSE "${WORK}")
