# The layering check: every include in the tree points down the stack
# gui -> session -> analysis -> core.
#
#   cmake -DROOT=<source tree> -P tests/tree/check_layering.cmake
#
# Scans the C++ files (.h, .cpp) of core/, analysis/, session/, gui/ and of the code built with
# each layer (tests/core with core, tests/analysis and bench/ with analysis, tests/session,
# web/ (the browser page), fuzz/ (the readers' harnesses) and python/ (the Python module) with
# session, tests/gui with gui).
# A quoted include is resolved the way the compiler resolves it: the including file's own
# folder first, then the include roots its target sees (its test folder, its own layer, then
# the layers below), and finally the layers above, where finding it is a violation.
# Violations, each reported as "file:line: #include ...: reason":
#   - the include resolves to a header of a layer above the file's own;
#   - the include is written with a layer prefix ("core/...", "analysis/...", "gui/..."): each
#     library exposes only its own folder, so "flow/camera.h", never "core/flow/camera.h";
#   - the include names no file of the tree (system and third-party headers are <...>);
#   - core or session (or the code built with them) includes a Qt or VTK header (<Q...>,
#     <vtk...>), or analysis includes a Qt header (analysis links VTK but never Qt);
#   - a folder of core includes a later folder of core (flow < image < content <
#     engine = scene < scene_shifting; the engine and the scenes it plays are one rank).
# Exits with an error listing every violation; prints "layering: N files, no violations"
# otherwise. ROOT defaults to the tree this script sits in.

cmake_minimum_required(VERSION 3.18)

if(NOT DEFINED ROOT)
  get_filename_component(ROOT "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)

# The layers, lowest first; a file may include headers of its own layer and those below.
set(layers core analysis session gui)

# Appends "file:line: #include ...: reason" to `violations`; the reason is the remaining
# arguments, concatenated (no semicolons: `violations` is a list).
macro(add_violation file line include)
  string(CONCAT reason ${ARGN})
  list(APPEND violations "${file}:${line}: #include ${include}: ${reason}")
endmacro()

# Sets `out` to the 1-based line number of the first occurrence of `needle` in `text`.
function(line_of text needle out)
  string(FIND "${text}" "${needle}" position)
  string(SUBSTRING "${text}" 0 ${position} before)
  string(REGEX MATCHALL "\n" newlines "${before}")
  list(LENGTH newlines count)
  math(EXPR line "${count} + 1")
  set(${out} ${line} PARENT_SCOPE)
endfunction()

# Sets `out` to the layer that holds `include` for a file in `dir` of layer index `rank`
# with the extra include root `extra` ("" when none): "" when found below or at the file's
# own layer, the layer's name when found only above, "-" when found nowhere.
function(resolve_layer include dir rank extra out)
  if(EXISTS "${dir}/${include}" AND NOT IS_DIRECTORY "${dir}/${include}")
    set(${out} "" PARENT_SCOPE)
    return()
  endif()
  if(NOT extra STREQUAL "" AND EXISTS "${ROOT}/${extra}/${include}")
    set(${out} "" PARENT_SCOPE)
    return()
  endif()
  set(index 0)
  foreach(layer IN LISTS layers)
    if(EXISTS "${ROOT}/${layer}/${include}" AND NOT IS_DIRECTORY "${ROOT}/${layer}/${include}")
      if(index LESS_EQUAL rank)
        set(${out} "" PARENT_SCOPE)
      else()
        set(${out} "${layer}" PARENT_SCOPE)
      endif()
      return()
    endif()
    math(EXPR index "${index} + 1")
  endforeach()
  set(${out} "-" PARENT_SCOPE)
endfunction()

# Inside gui/, the folders in dependency order, lowest first: a file may include headers of
# its own folder and those before it. adapters (core data as Qt/VTK images, palettes, the flow
# renderer) < models (the window's state and its models) < views (widgets showing the models)
# < app (the window, the command line, the exports).
set(gui_folders adapters models views app)

# Appends a violation when `include` (from `file` in gui/`sub`) names a header of a gui folder
# later than `sub`, or when a view's file (gui/views/*_view.*) includes another view's header.
function(check_gui_include file line include sub)
  if(NOT include MATCHES "^([a-z_]+)/")
    return()
  endif()
  set(target "${CMAKE_MATCH_1}")
  list(FIND gui_folders "${sub}" own)
  list(FIND gui_folders "${target}" other)
  if(own GREATER_EQUAL 0 AND other GREATER own)
    add_violation("${file}" ${line} "\"${include}\""
      "gui/${sub} must not include gui/${target} (inside gui, dependencies point "
      "app -> views -> models -> adapters)")
  endif()
  get_filename_component(name "${file}" NAME_WE)
  get_filename_component(included "${include}" NAME_WE)
  if(sub STREQUAL "views" AND target STREQUAL "views" AND name MATCHES "_view$"
     AND included MATCHES "_view$" AND NOT name STREQUAL included)
    add_violation("${file}" ${line} "\"${include}\""
      "a view must not include another view's header (views read the window model, never "
      "each other)")
  endif()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

# Inside core/, the folders in dependency order, lowest first, as folder:rank: the flow of a
# plane, images and warps, what a layer shows, the engine and the scenes it plays (one rank:
# the engine's frame records name scene types, the scene engine runs the plane engine), and
# scene shifting.
set(core_folders flow:0 image:1 content:2 engine:3 scene:3 scene_shifting:4)

# Sets `out` to the rank of core folder `folder`, or -1.
function(core_rank folder out)
  set(${out} -1 PARENT_SCOPE)
  foreach(entry IN LISTS core_folders)
    if(entry MATCHES "^${folder}:([0-9]+)$")
      set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
    endif()
  endforeach()
endfunction()

# Appends a violation when `include` (from `file` in core/`sub`) names a header of a core
# folder later than `sub`.
function(check_core_include file line include sub)
  if(NOT include MATCHES "^([a-z_]+)/")
    return()
  endif()
  set(target "${CMAKE_MATCH_1}")
  core_rank("${sub}" own)
  core_rank("${target}" other)
  if(own GREATER_EQUAL 0 AND other GREATER own)
    add_violation("${file}" ${line} "\"${include}\""
      "core/${sub} must not include core/${target} (inside core, folders depend on earlier "
      "ones only: flow < image < content < engine = scene < scene_shifting)")
  endif()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

# Checks the files under `folder` (relative to ROOT), built with layer index `rank` and the
# extra include root `extra`; appends to `violations` and `file_count` in the caller's scope.
function(check_folder folder rank extra)
  if(NOT IS_DIRECTORY "${ROOT}/${folder}")
    return()
  endif()
  list(GET layers ${rank} own_layer)
  set(who "${folder}")
  if(NOT folder STREQUAL own_layer)
    set(who "${folder} (built with ${own_layer})")
  endif()
  file(GLOB_RECURSE files RELATIVE "${ROOT}" "${ROOT}/${folder}/*.h" "${ROOT}/${folder}/*.cpp")
  list(LENGTH files count)
  math(EXPR count "${file_count} + ${count}")
  set(file_count ${count} PARENT_SCOPE)
  foreach(file IN LISTS files)
    get_filename_component(dir "${ROOT}/${file}" DIRECTORY)
    file(STRINGS "${ROOT}/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    if(NOT includes)
      continue()
    endif()
    file(READ "${ROOT}/${file}" text)
    foreach(directive IN LISTS includes)
      string(STRIP "${directive}" directive)
      if(directive MATCHES "^#[ \t]*include[ \t]*\"([^\"]+)\"")
        set(include "${CMAKE_MATCH_1}")
        line_of("${text}" "${directive}" line)
        if(include MATCHES "^(core|analysis|session|gui)/")
          add_violation("${file}" ${line} "\"${include}\""
            "written with a layer prefix, but each library's include root is its own folder, so "
            "drop the '${CMAKE_MATCH_1}/'")
          continue()
        endif()
        resolve_layer("${include}" "${dir}" ${rank} "${extra}" found)
        if(found STREQUAL "-")
          add_violation("${file}" ${line} "\"${include}\""
            "names no file of the tree (write system and third-party headers as <...>)")
        elseif(NOT found STREQUAL "")
          add_violation("${file}" ${line} "\"${include}\""
            "resolves to ${found}/${include}, and ${who} must not include ${found} "
            "(dependencies point gui -> session -> analysis -> core)")
        elseif(file MATCHES "^gui/([a-z_]+)/")
          check_gui_include("${file}" ${line} "${include}" "${CMAKE_MATCH_1}")
        elseif(file MATCHES "^core/([a-z_]+)/")
          check_core_include("${file}" ${line} "${include}" "${CMAKE_MATCH_1}")
        endif()
      elseif(directive MATCHES "^#[ \t]*include[ \t]*<((Q|vtk)[^>]*)>")
        set(include "${CMAKE_MATCH_1}")
        set(library Qt)
        if(include MATCHES "^vtk")
          set(library VTK)
        endif()
        if(rank EQUAL 0 OR rank EQUAL 2 OR (rank EQUAL 1 AND library STREQUAL "Qt"))
          line_of("${text}" "${directive}" line)
          add_violation("${file}" ${line} "<${include}>"
            "${who} must not include ${library} headers")
        endif()
      endif()
    endforeach()
  endforeach()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

set(violations "")
set(file_count 0)
set(rank 0)
foreach(layer IN LISTS layers)
  check_folder("${layer}" ${rank} "")
  check_folder("tests/${layer}" ${rank} "tests/${layer}")
  math(EXPR rank "${rank} + 1")
endforeach()
check_folder(bench 1 bench)  # oflab-bench links analysis (the engine cases read shipped scripts)
check_folder(web 2 web)      # the browser page binds session (and core, analysis/formats)
check_folder(fuzz 2 fuzz)    # the readers' harnesses read through session's readers
check_folder(python 2 python)  # the Python module binds session (and analysis, core)

list(LENGTH violations violation_count)
if(violation_count GREATER 0)
  string(REPLACE ";" "\n  " listing "${violations}")
  message(FATAL_ERROR
    "layering: ${violation_count} include(s) break the layering rule "
    "(see manual/architecture.md#layers):\n  ${listing}")
endif()
message(STATUS "layering: ${file_count} files, no violations")
