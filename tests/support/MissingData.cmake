# The smoke tests' counterpart of MissingData.h: lacrima_missing_data(WHAT) when the data a
# benchmark needs is missing. Under CI=true that fails, naming it; otherwise it prints
# "skipped: WHAT" (the tests' SKIP_REGULAR_EXPRESSION) and the caller returns or moves on.
function(lacrima_missing_data what)
  if("$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "${what}, and CI=true makes that a failure, not a skip")
  endif()
  message(STATUS "skipped: ${what}")
endfunction()
