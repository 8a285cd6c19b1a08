# Fails, naming each file, when clang-format (with the project's .clang-format) would change a
# C++ source of the project.   cmake -DSOURCE_DIR=... -DCLANG_FORMAT=... -P FormatCheck.cmake
set(files "")
foreach(part common rigging player editor tests)
  file(GLOB_RECURSE found "${SOURCE_DIR}/${part}/*.cpp" "${SOURCE_DIR}/${part}/*.h")
  list(APPEND files ${found})
endforeach()
list(LENGTH files count)
if(count EQUAL 0)
  message(FATAL_ERROR "No C++ sources found under ${SOURCE_DIR}")
endif()

set(unformatted "")
foreach(file IN LISTS files)
  # The formatted text is compared with the file rather than asking for --dry-run --Werror:
  # clang-format 14 reports its own rewrite of "// namespace a::inline b" comments as a violation
  # even when the rewrite leaves the text as it is.
  execute_process(COMMAND "${CLANG_FORMAT}" --style=file "${file}"
                  WORKING_DIRECTORY "${SOURCE_DIR}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE formatted ERROR_QUIET)
  file(READ "${file}" original)
  if(NOT rc EQUAL 0 OR NOT formatted STREQUAL original)
    file(RELATIVE_PATH relative "${SOURCE_DIR}" "${file}")
    list(APPEND unformatted "${relative}")
  endif()
endforeach()
if(unformatted)
  list(LENGTH unformatted bad)
  list(JOIN unformatted "\n  " text)
  message(FATAL_ERROR "${bad} of ${count} files are not formatted (clang-format -i FILE fixes each):\n  ${text}")
endif()
message(STATUS "All ${count} C++ sources are formatted")
