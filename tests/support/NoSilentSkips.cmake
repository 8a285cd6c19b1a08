# Runs a suite whose cases need the default head with the head out of reach (an empty cache
# folder): without CI=true its cases skip and it passes; with CI=true they fail, naming the
# cause (tests/support/DefaultHeadSkip.h). Arguments: -DSUITE=<path to the suite executable>
# -DWORK=<scratch folder>.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
foreach(ci false true)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env CI=${ci} XDG_CACHE_HOME=${WORK} QT_QPA_PLATFORM=offscreen
            "${SUITE}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(ci STREQUAL "false")
    if(NOT rc EQUAL 0 OR NOT out MATCHES "SKIP")
      message(FATAL_ERROR "without CI=true the suite should skip and pass (exit ${rc}):\n${out}${err}")
    endif()
  else()
    if(rc EQUAL 0 OR NOT out MATCHES "CI=true makes that a failure")
      message(FATAL_ERROR "with CI=true the suite should fail, naming the cause (exit ${rc}):\n${out}${err}")
    endif()
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
