# Fails, naming each file, when clang-format (with the project's .clang-format) would change a
# C++ source of the project.
#   cmake -DSOURCE_DIR=... -DCLANG_FORMAT=... -DWORK_DIR=... -P FormatCheck.cmake
set(files "")
foreach(part common rigging player editor tests)
  file(GLOB_RECURSE found RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${part}/*.cpp"
       "${SOURCE_DIR}/${part}/*.h")
  list(APPEND files ${found})
endforeach()
list(LENGTH files count)
if(count EQUAL 0)
  message(FATAL_ERROR "No C++ sources found under ${SOURCE_DIR}")
endif()

# One clang-format process formats copies of every file in place: starting it once per file cost
# a minute of the test command, almost all of it loading the program. The formatted copy is then
# compared with the file rather than asking for --dry-run --Werror: clang-format 14 reports its
# own rewrite of "// namespace a::inline b" comments as a violation even when the rewrite leaves
# the text as it is.
file(REMOVE_RECURSE "${WORK_DIR}")
foreach(file IN LISTS files)
  get_filename_component(folder "${file}" DIRECTORY)
  file(COPY "${SOURCE_DIR}/${file}" DESTINATION "${WORK_DIR}/${folder}")
endforeach()
execute_process(COMMAND "${CLANG_FORMAT}" "--style=file:${SOURCE_DIR}/.clang-format" -i ${files}
                WORKING_DIRECTORY "${WORK_DIR}"
                RESULT_VARIABLE rc ERROR_VARIABLE errors)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "clang-format failed (${rc}):\n${errors}")
endif()

set(unformatted "")
foreach(file IN LISTS files)
  file(READ "${SOURCE_DIR}/${file}" original)
  file(READ "${WORK_DIR}/${file}" formatted)
  if(NOT formatted STREQUAL original)
    list(APPEND unformatted "${file}")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
if(unformatted)
  list(LENGTH unformatted bad)
  list(JOIN unformatted "\n  " text)
  message(FATAL_ERROR "${bad} of ${count} files are not formatted (clang-format -i FILE fixes each):\n  ${text}")
endif()
message(STATUS "All ${count} C++ sources are formatted")
