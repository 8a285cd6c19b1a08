# Smoke test of `lacrima-bench tears --json`: the benchmark runs, prints one JSON object, and
# what it reports is sane (the commanded particles alive, every value finite, sub-steps taken,
# pair-list builds and stray sub-steps within them, the same state, surface and trail hashes for 1 and 3 threads).
# Speed is not checked here: figures are read, never asserted.
#   cmake -DBENCH=<path to lacrima-bench> -P TearsBenchSmoke.cmake
execute_process(COMMAND "${BENCH}" tears --particles 100 --frames 12 --json
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "lacrima-bench tears exited with ${status}: ${err}")
endif()
string(JSON alive ERROR_VARIABLE parseError GET "${out}" particles_alive)
if(parseError)
  message(FATAL_ERROR "lacrima-bench tears --json printed no JSON object: ${parseError}\n${out}")
endif()
string(JSON finite GET "${out}" all_finite)
string(JSON frames GET "${out}" frames)
string(JSON substeps GET "${out}" counters substeps)
string(JSON strays GET "${out}" counters stray_substeps)
string(JSON searches GET "${out}" counters neighbour_searches)
string(JSON surfaceRuns GET "${out}" counters surface_runs)
if(NOT alive EQUAL 100)
  message(FATAL_ERROR "expected 100 particles alive, got ${alive}")
endif()
if(NOT finite)
  message(FATAL_ERROR "the tear state went non-finite")
endif()
if(NOT frames EQUAL 12 OR NOT surfaceRuns EQUAL 12)
  message(FATAL_ERROR "expected 12 frames and 12 surface runs, got ${frames} and ${surfaceRuns}")
endif()
# Each sub-step either rebuilds the pair list or keeps it, with strays or without: the rebuilds
# and the sub-steps with strays together cannot outnumber the sub-steps.
math(EXPR accounted "${searches} + ${strays}")
if(NOT substeps GREATER_EQUAL 12 OR NOT searches GREATER 0 OR accounted GREATER substeps)
  message(FATAL_ERROR "implausible counters: ${substeps} sub-steps, ${searches} pair-list "
                      "builds, ${strays} stray sub-steps")
endif()
message(STATUS "lacrima-bench tears: ${alive} particles, ${substeps} sub-steps in ${frames} frames")

# --threads: the JSON names the count, and the particles, the surface and the trails hash the
# same for 1 and 3 threads (3,000 particles: past the sharing threshold).
foreach(threads 1 3)
  execute_process(COMMAND "${BENCH}" tears --particles 3000 --frames 12 --threads ${threads} --json
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "lacrima-bench tears --threads ${threads} exited with ${status}: ${err}")
  endif()
  string(JSON reported GET "${out}" threads)
  string(JSON hash${threads} GET "${out}" state_hash)
  string(JSON surface${threads} GET "${out}" surface_hash)
  string(JSON trail${threads} GET "${out}" trail_hash)
  if(NOT reported EQUAL threads)
    message(FATAL_ERROR "--threads ${threads} reported ${reported} threads")
  endif()
endforeach()
if(NOT hash1 STREQUAL hash3 OR NOT hash1 MATCHES "^[0-9a-f]+$")
  message(FATAL_ERROR "state hash differs between 1 and 3 threads: ${hash1} and ${hash3}")
endif()
if(NOT surface1 STREQUAL surface3 OR NOT trail1 STREQUAL trail3 OR NOT surface1 MATCHES "^[0-9a-f]+$"
   OR NOT trail1 MATCHES "^[0-9a-f]+$")
  message(FATAL_ERROR "surface or trail hash differs between 1 and 3 threads: surface "
                      "${surface1} and ${surface3}, trails ${trail1} and ${trail3}")
endif()
message(STATUS "lacrima-bench tears --threads 1 and 3: state hash ${hash1}, surface ${surface1}, "
               "trails ${trail1}")

# --quality maps a level as the apps do (playback::simulationOptions): Reference halves the
# viscous bound as well as the CFL and acceleration factors, which --substep-factor 0.5 does
# not. With a viscosity at which the viscous bound sets the sub-steps, Reference takes more.
foreach(run quality substep)
  if(run STREQUAL quality)
    set(choice --quality reference)
  else()
    set(choice --substep-factor 0.5)
  endif()
  execute_process(COMMAND "${BENCH}" tears --particles 100 --frames 12 --param viscosity=50
                          ${choice} --json
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "lacrima-bench tears ${choice} exited with ${status}: ${err}")
  endif()
  string(JSON level${run} GET "${out}" quality)
  string(JSON substeps${run} GET "${out}" counters substeps)
  string(JSON samples${run} LENGTH "${out}" population)
endforeach()
if(NOT levelquality STREQUAL "reference" OR NOT levelsubstep STREQUAL "balanced")
  message(FATAL_ERROR "--quality reported '${levelquality}', the default '${levelsubstep}'")
endif()
if(NOT substepsquality GREATER substepssubstep)
  message(FATAL_ERROR "--quality reference took ${substepsquality} sub-steps, no more than "
                      "--substep-factor 0.5 (${substepssubstep}): the viscous bound was not halved")
endif()
if(NOT samplesquality EQUAL 2)
  message(FATAL_ERROR "expected 2 population samples in 12 frames, got ${samplesquality}")
endif()
message(STATUS "--quality reference: ${substepsquality} sub-steps, --substep-factor 0.5: "
               "${substepssubstep}")
