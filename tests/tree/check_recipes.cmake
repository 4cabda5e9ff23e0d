# The recipes check: the "## Four recipes" section of manual/architecture.md names only
# files, functions and tests that exist.
#
#   cmake -DROOT=<source tree> -P tests/tree/check_recipes.cmake
#
# In that section (up to the next "## " heading), every backticked token is checked:
#   - a path ending in .h, .cpp, .md, .cmake or .json must be a file at ROOT/<path>, or at
#     ROOT/<layer>/<path> for a layer (core, analysis, session, gui), as headers are named;
#   - a function, `name()` or `Class::name()`, must be defined or declared as "name(" in a
#     .h or .cpp of core/, analysis/, session/ or gui/;
#   - a test, `Suite.Name`, must be a GoogleTest "Suite, Name)" in tests/.
# Fails listing every name that does not exist; prints "recipes: N names, all exist".

cmake_minimum_required(VERSION 3.18)

if(NOT DEFINED ROOT)
  get_filename_component(ROOT "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
set(page "${ROOT}/manual/architecture.md")
if(NOT EXISTS "${page}")
  message(FATAL_ERROR "recipes: ${page} does not exist")
endif()
file(READ "${page}" text)
string(FIND "${text}" "\n## Four recipes" start)
if(start EQUAL -1)
  message(FATAL_ERROR "recipes: ${page} has no \"## Four recipes\" section")
endif()
string(SUBSTRING "${text}" ${start} -1 section)
string(SUBSTRING "${section}" 1 -1 rest)
string(FIND "${rest}" "\n## " end)
if(NOT end EQUAL -1)
  string(SUBSTRING "${rest}" 0 ${end} section)
endif()

# Every source text of the layers and of the tests, read once.
set(sources "")
foreach(folder core analysis session gui)
  file(GLOB_RECURSE found "${ROOT}/${folder}/*.h" "${ROOT}/${folder}/*.cpp")
  list(APPEND sources ${found})
endforeach()
set(code "")
foreach(file IN LISTS sources)
  file(READ "${file}" content)
  string(APPEND code "${content}")
endforeach()
file(GLOB_RECURSE test_files "${ROOT}/tests/*.cpp")
set(tests "")
foreach(file IN LISTS test_files)
  file(READ "${file}" content)
  string(APPEND tests "${content}")
endforeach()

string(REGEX MATCHALL "`[^`\n]+`" tokens "${section}")
set(problems "")
set(count 0)
foreach(token IN LISTS tokens)
  string(REGEX REPLACE "^`(.*)`$" "\\1" name "${token}")
  if(name MATCHES "^[A-Za-z0-9_./-]+\\.(h|cpp|md|cmake|json)$")
    math(EXPR count "${count} + 1")
    set(found FALSE)
    foreach(prefix "" core/ analysis/ session/ gui/)
      if(EXISTS "${ROOT}/${prefix}${name}")
        set(found TRUE)
      endif()
    endforeach()
    if(NOT found)
      list(APPEND problems "`${name}` is not a file of the tree")
    endif()
  elseif(name MATCHES "^([A-Za-z_][A-Za-z0-9_]*::)?([a-z_][A-Za-z0-9_]*)\\(\\)$")
    math(EXPR count "${count} + 1")
    string(FIND "${code}" "${CMAKE_MATCH_2}(" position)
    if(position EQUAL -1)
      list(APPEND problems "`${name}` is not a function of core, analysis, session or gui")
    endif()
  elseif(name MATCHES "^([A-Z][A-Za-z0-9]+)\\.([A-Z][A-Za-z0-9_]+)$")
    math(EXPR count "${count} + 1")
    string(FIND "${tests}" "${CMAKE_MATCH_1}, ${CMAKE_MATCH_2})" position)
    if(position EQUAL -1)
      list(APPEND problems "`${name}` is not a test of tests/")
    endif()
  endif()
endforeach()

list(LENGTH problems problem_count)
if(problem_count GREATER 0)
  string(REPLACE ";" "\n  " listing "${problems}")
  message(FATAL_ERROR "recipes: ${problem_count} name(s) of the recipes do not exist:\n  ${listing}")
endif()
message(STATUS "recipes: ${count} names, all exist")
