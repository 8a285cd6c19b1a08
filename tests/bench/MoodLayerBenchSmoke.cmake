# Smoke test of `lacrima-bench mood-layer --json`: the benchmark runs, prints one JSON object, and
# what it reports is sane (a minute at 22 fps is 1,321 frames, the take holds memory, every time
# is positive). Speed is not checked here: figures are read, never asserted.
#   cmake -DBENCH=<path to lacrima-bench> -P MoodLayerBenchSmoke.cmake
execute_process(COMMAND "${BENCH}" mood-layer --minutes 1 --json
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "lacrima-bench mood-layer exited with ${status}: ${err}")
endif()
string(JSON frames ERROR_VARIABLE parseError GET "${out}" frames)
if(parseError)
  message(FATAL_ERROR "lacrima-bench mood-layer --json printed no JSON object: ${parseError}\n${out}")
endif()
if(NOT frames EQUAL 1321)
  message(FATAL_ERROR "a minute at 22 fps should be 1321 frames, got ${frames}")
endif()
string(JSON bytes GET "${out}" take_bytes)
if(NOT bytes GREATER 0)
  message(FATAL_ERROR "the take holds no memory: ${bytes}")
endif()
foreach(path "generate_ms;median" "bake_ms;median" "cache_hit_ns" "evaluate_ns")
  string(JSON value GET "${out}" ${path})
  if(NOT value GREATER 0)
    message(FATAL_ERROR "${path}: expected a positive time, got ${value}")
  endif()
endforeach()
