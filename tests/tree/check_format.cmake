# The tree is formatted: clang-format 14 with the project's .clang-format changes nothing.
#
#   cmake -DROOT=<source tree> [-DCLANG_FORMAT=<program>] -P tests/tree/check_format.cmake
#
# Runs `clang-format-14 --dry-run --Werror` over every C++ file (.h, .cpp) of core/,
# analysis/, session/, gui/, tests/, bench/, fuzz/, web/ and python/. The fixture trees under tests/tree/fixtures/
# whose names start with "misformatted" are left out: they are wrong on purpose, for the
# control that shows this check rejects them. The style is ROOT/.clang-format, or the one
# of the tree this script sits in when ROOT has none (the fixture trees).
# A missing clang-format-14 is a failure, not a skip: tools/install-deps.sh installs it.
# Exits with an error naming every file that would change; prints "format: N files, all
# formatted" otherwise. ROOT defaults to the tree this script sits in.

cmake_minimum_required(VERSION 3.18)

get_filename_component(own_tree "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
if(NOT DEFINED ROOT)
  set(ROOT "${own_tree}")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)

if(NOT CLANG_FORMAT)
  find_program(CLANG_FORMAT NAMES clang-format-14)
endif()
if(NOT CLANG_FORMAT OR NOT EXISTS "${CLANG_FORMAT}")
  message(FATAL_ERROR
    "format: clang-format-14 is not installed (looked for: ${CLANG_FORMAT}; Debian package "
    "clang-format-14, which tools/install-deps.sh installs), so the formatting of the tree "
    "cannot be checked")
endif()
execute_process(COMMAND "${CLANG_FORMAT}" --version OUTPUT_VARIABLE version
                RESULT_VARIABLE version_result)
if(NOT version_result EQUAL 0 OR NOT version MATCHES "version 14\\.")
  message(FATAL_ERROR "format: ${CLANG_FORMAT} is not clang-format 14: ${version}")
endif()

set(style "${ROOT}/.clang-format")
if(NOT EXISTS "${style}")
  set(style "${own_tree}/.clang-format")
endif()

set(files "")
foreach(folder IN ITEMS core analysis session gui tests bench fuzz web python)
  file(GLOB_RECURSE found RELATIVE "${ROOT}" "${ROOT}/${folder}/*.h" "${ROOT}/${folder}/*.cpp")
  list(APPEND files ${found})
endforeach()
list(FILTER files EXCLUDE REGEX "^tests/tree/fixtures/misformatted")
list(SORT files)
list(LENGTH files file_count)
if(file_count EQUAL 0)
  message(FATAL_ERROR "format: no C++ files under ${ROOT}")
endif()

execute_process(
  COMMAND "${CLANG_FORMAT}" "--style=file:${style}" --dry-run --Werror --ferror-limit=1 ${files}
  WORKING_DIRECTORY "${ROOT}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  string(REGEX MATCHALL "[^\n:]+:[0-9]+:[0-9]+: error: code should be clang-formatted" hits
         "${errors}")
  set(bad "")
  foreach(hit IN LISTS hits)
    string(REGEX REPLACE ":[0-9]+:[0-9]+: error: .*$" "" file "${hit}")
    list(APPEND bad "${file}")
  endforeach()
  list(REMOVE_DUPLICATES bad)
  list(LENGTH bad bad_count)
  if(bad_count EQUAL 0)
    message(FATAL_ERROR "format: ${CLANG_FORMAT} failed (exit ${result}):\n${errors}")
  endif()
  string(REPLACE ";" "\n  " listing "${bad}")
  string(REPLACE ";" " " arguments "${bad}")
  message(FATAL_ERROR
    "format: ${bad_count} of ${file_count} files differ from clang-format 14 with ${style}:\n"
    "  ${listing}\nFormat them with: clang-format-14 -i ${arguments}")
endif()
message(STATUS "format: ${file_count} files, all formatted")
