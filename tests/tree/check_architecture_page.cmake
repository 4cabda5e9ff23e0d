# The architecture page check: manual/architecture.md names every header of the four layers,
# and every header it names exists.
#
#   cmake -DROOT=<source tree> [-DPAGE=<page>] -P tests/tree/check_architecture_page.cmake
#
# The rule (stated above the page's file tables): a header is named by its path relative to
# its layer folder, between backticks: core/engine/animator.h is written `engine/animator.h`,
# analysis/runs/run_driver.h `runs/run_driver.h`, gui/models/scene_model.h
# `models/scene_model.h` - exactly as it is included.
# Fails when a header under core/, analysis/, session/ or gui/ is not named, and when the page names, in
# that form, a header that does not exist (a backticked "<folder>/<name>.h" whose folder is a
# folder of a layer, or a full path such as `core/flow/camera.h`).
# PAGE defaults to ROOT/manual/architecture.md; ROOT to the tree this script sits in.

cmake_minimum_required(VERSION 3.18)

if(NOT DEFINED ROOT)
  get_filename_component(ROOT "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
if(NOT DEFINED PAGE)
  set(PAGE "${ROOT}/manual/architecture.md")
endif()
if(NOT EXISTS "${PAGE}")
  message(FATAL_ERROR "architecture_page: ${PAGE} does not exist")
endif()
file(READ "${PAGE}" page)

set(problems "")
set(header_count 0)
set(layer_folders "")
set(headers "")
foreach(layer core analysis session gui)
  file(GLOB_RECURSE layer_headers RELATIVE "${ROOT}/${layer}" "${ROOT}/${layer}/*.h")
  list(SORT layer_headers)
  foreach(header IN LISTS layer_headers)
    math(EXPR header_count "${header_count} + 1")
    list(APPEND headers "${header}")
    string(FIND "${page}" "`${header}`" position)
    if(position EQUAL -1)
      list(APPEND problems "${layer}/${header} is not named on the page (write `${header}`)")
    endif()
  endforeach()
  file(GLOB children LIST_DIRECTORIES true RELATIVE "${ROOT}/${layer}" "${ROOT}/${layer}/*")
  foreach(child IN LISTS children)
    if(IS_DIRECTORY "${ROOT}/${layer}/${child}")
      list(APPEND layer_folders "${child}")
    endif()
  endforeach()
endforeach()

# Backticked header names whose first folder is a layer's folder (`flow/camera.h`) or a
# layer (`core/flow/camera.h`) must exist.
string(REGEX MATCHALL "`[A-Za-z0-9_]+/[A-Za-z0-9_/]*[A-Za-z0-9_]\\.h`" named "${page}")
list(REMOVE_DUPLICATES named)
foreach(token IN LISTS named)
  string(REGEX REPLACE "^`(.*)`$" "\\1" header "${token}")
  string(REGEX REPLACE "/.*" "" folder "${header}")
  list(FIND layer_folders "${folder}" known_folder)
  list(FIND headers "${header}" known_header)
  if(known_folder GREATER -1 AND known_header EQUAL -1)
    list(APPEND problems "`${header}` is named on the page but no layer has that header")
  elseif(folder MATCHES "^(core|analysis|gui)$" AND NOT EXISTS "${ROOT}/${header}")
    list(APPEND problems "`${header}` is named on the page but does not exist")
  endif()
endforeach()

list(LENGTH problems problem_count)
if(problem_count GREATER 0)
  string(REPLACE ";" "\n  " listing "${problems}")
  message(FATAL_ERROR "architecture_page: ${PAGE} is out of date:\n  ${listing}")
endif()
message(STATUS "architecture_page: all ${header_count} headers named, none stale")
