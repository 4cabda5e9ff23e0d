# The size check: the code stays in pieces a reader can hold (manual/architecture.md,
# "Conventions every file follows").
#
#   cmake -DROOT=<source tree> [-DMAX_LONG_FUNCTIONS=5] -P tests/tree/check_sizes.cmake
#
# Over the .cpp and .h files of core/, analysis/, session/, gui/, web/ and python/:
#   - no .cpp together with its .h is longer than 800 lines;
#   - at most MAX_LONG_FUNCTIONS functions are longer than 60 lines, as pmccabe counts them
#     (its fifth column; Debian's pmccabe, installed by tools/install-deps.sh: a missing
#     pmccabe is a failure, not a skip).
# Fails listing what is too long; prints "sizes: N files, M functions over 60 lines" else.

cmake_minimum_required(VERSION 3.18)

if(NOT DEFINED ROOT)
  get_filename_component(ROOT "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
if(NOT DEFINED MAX_LONG_FUNCTIONS)
  set(MAX_LONG_FUNCTIONS 5)
endif()

set(files "")
foreach(folder core analysis session gui web python)
  file(GLOB_RECURSE found "${ROOT}/${folder}/*.h" "${ROOT}/${folder}/*.cpp")
  list(APPEND files ${found})
endforeach()
list(SORT files)

set(problems "")
foreach(file IN LISTS files)
  if(NOT file MATCHES "\\.cpp$")
    continue()
  endif()
  file(STRINGS "${file}" lines)
  list(LENGTH lines count)
  string(REGEX REPLACE "\\.cpp$" ".h" header "${file}")
  if(EXISTS "${header}")
    file(STRINGS "${header}" header_lines)
    list(LENGTH header_lines header_count)
    math(EXPR count "${count} + ${header_count}")
  endif()
  if(count GREATER 800)
    file(RELATIVE_PATH name "${ROOT}" "${file}")
    list(APPEND problems "${name} with its header: ${count} lines (at most 800)")
  endif()
endforeach()

find_program(PMCCABE pmccabe)
if(NOT PMCCABE)
  message(FATAL_ERROR "sizes: pmccabe is missing (tools/install-deps.sh installs it)")
endif()
execute_process(COMMAND "${PMCCABE}" ${files} OUTPUT_VARIABLE table ERROR_QUIET
                WORKING_DIRECTORY "${ROOT}")
string(REPLACE "\n" ";" rows "${table}")
set(long "")
foreach(row IN LISTS rows)
  if(row MATCHES "^[0-9]+\t[0-9]+\t[0-9]+\t[0-9]+\t([0-9]+)\t(.*)$")
    if(CMAKE_MATCH_1 GREATER 60)
      string(REPLACE "${ROOT}/" "" where "${CMAKE_MATCH_2}")
      list(APPEND long "${where} (${CMAKE_MATCH_1} lines)")
    endif()
  endif()
endforeach()
list(LENGTH long long_count)
if(long_count GREATER MAX_LONG_FUNCTIONS)
  string(REPLACE ";" "\n    " listing "${long}")
  list(APPEND problems "${long_count} functions over 60 lines (at most ${MAX_LONG_FUNCTIONS}):\n    ${listing}")
endif()

list(LENGTH files file_count)
if(problems)
  string(REPLACE ";" "\n  " listing "${problems}")
  message(FATAL_ERROR "sizes: too long:\n  ${listing}")
endif()
message(STATUS "sizes: ${file_count} files, ${long_count} functions over 60 lines")
