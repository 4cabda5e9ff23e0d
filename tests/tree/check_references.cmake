# The tree stands alone: nothing in it points at a file that is not in the repository.
#
#   cmake -DROOT=<source tree> -P tests/tree/check_references.cmake
#
# Scans the C++ files (.h, .cpp), the CMake files (CMakeLists.txt, .cmake, .cmake.in), the
# shell scripts (.sh and the scripts of .ci/) and the Markdown pages of the tree. Build
# folders (build*, out*), .git and tests/tree/fixtures (trees of their own, each checked by
# its own test) and web/node_modules (the npm packages tools/build-web.sh installs there,
# ignored by git) are left out. Reported, each as "file:line: 'name' is not in the repository":
#   - a Markdown link [text](path) in a .md file whose relative path does not resolve from
#     the page's folder (web addresses and in-page anchors are not checked);
#   - the name of a Markdown page (a word ending in .md, in code, comments or prose) that
#     matches no .md file of the tree, except the names of files the programs write
#     (`generated` below);
#   - a path into the folders outside the tree that sources were once taken from (the
#     `outside_places` below, optionally after ../, and the absolute /work folder), unless
#     the path exists in the tree.
# Exits with an error listing every reference; prints "outside_references: N files, none
# outside" otherwise. ROOT defaults to the tree this script sits in.

cmake_minimum_required(VERSION 3.18)

if(NOT DEFINED ROOT)
  get_filename_component(ROOT "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)

# Page names the programs write at run time (analysis/report writes report.md).
set(generated report.md)
# Folders beside the tree that are not part of it.
set(outside_places shared reference seed)
list(JOIN outside_places "|" places)

# Every file of the tree below ROOT, relative to it, without build folders, .git, the
# fixture trees and the installed npm packages.
file(GLOB top RELATIVE "${ROOT}" "${ROOT}/*" "${ROOT}/.*")
set(all_files "")
foreach(entry IN LISTS top)
  if(entry MATCHES "^(build|out)" OR entry STREQUAL ".git")
    continue()
  endif()
  if(IS_DIRECTORY "${ROOT}/${entry}")
    file(GLOB_RECURSE below RELATIVE "${ROOT}" "${ROOT}/${entry}/*")
    list(FILTER below EXCLUDE REGEX "^(tests/tree/fixtures|web/node_modules)/")
    list(APPEND all_files ${below})
  else()
    list(APPEND all_files "${entry}")
  endif()
endforeach()

# The page names of the tree, and the files to scan.
set(page_names ${generated})
set(scanned "")
foreach(file IN LISTS all_files)
  get_filename_component(name "${file}" NAME)
  if(name MATCHES "\\.md$")
    list(APPEND page_names "${name}")
  endif()
  if(name MATCHES "\\.(h|cpp|cmake|cmake\\.in|sh|md)$" OR name STREQUAL "CMakeLists.txt"
     OR file MATCHES "^\\.ci/")
    list(APPEND scanned "${file}")
  endif()
endforeach()
list(REMOVE_DUPLICATES page_names)

# Characters that CMake lists treat specially, swapped for markers before a text is split
# into lines, and swapped back in reported names.
set(semicolon "@SEMI@")
set(backslash "@BSL@")
set(open_bracket "@LB@")
set(close_bracket "@RB@")
function(restore text out)
  string(REPLACE "${semicolon}" ";" text "${text}")
  string(REPLACE "${backslash}" "\\" text "${text}")
  string(REPLACE "${open_bracket}" "[" text "${text}")
  string(REPLACE "${close_bracket}" "]" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# Appends "file:line: 'name' is not in the repository" to `problems` in the caller's scope.
macro(add_problem file line name)
  restore("${name}" shown)
  list(APPEND problems "${file}:${line}: '${shown}' is not in the repository")
endmacro()

# Written with [/] so that this file does not match its own patterns.
set(path_rest "[^] \t`'\")>,:]*")
set(outside_path "(^|[^A-Za-z0-9_./-])((\\.\\.[/])*(${places})[/]${path_rest})")
set(work_path "(^|[^A-Za-z0-9_.-])([/]work[/]${path_rest})")
set(candidate "\\.md|(${places}|[/]work)[/]")
set(page_name "([A-Za-z0-9_./-]*[A-Za-z0-9_-]\\.md)([^A-Za-z0-9_]|$)")

set(problems "")
list(LENGTH scanned file_count)
foreach(file IN LISTS scanned)
  file(READ "${ROOT}/${file}" text)
  set(is_page FALSE)
  if(file MATCHES "\\.md$")
    set(is_page TRUE)
  endif()
  if(NOT text MATCHES "${candidate}" AND NOT (is_page AND text MATCHES "\\]\\("))
    continue()
  endif()
  get_filename_component(dir "${ROOT}/${file}" DIRECTORY)
  string(REPLACE ";" "${semicolon}" text "${text}")
  string(REPLACE "\\" "${backslash}" text "${text}")
  string(REPLACE "[" "${open_bracket}" text "${text}")
  string(REPLACE "]" "${close_bracket}" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(line 0)
  foreach(content IN LISTS lines)
    math(EXPR line "${line} + 1")
    if(NOT content MATCHES "${candidate}|${close_bracket}\\(")
      continue()
    endif()
    # Markdown links of a page: the target must resolve from the page's folder.
    if(is_page)
      string(REGEX MATCHALL "${close_bracket}\\(([^) \t]+)[) \t]" links "${content}")
      foreach(link IN LISTS links)
        string(REGEX REPLACE "^${close_bracket}\\(([^) \t]+).$" "\\1" target "${link}")
        if(target MATCHES "^[a-z]+:" OR target MATCHES "^#")
          continue()
        endif()
        string(REGEX REPLACE "#.*$" "" path "${target}")
        restore("${path}" path)
        if(NOT EXISTS "${dir}/${path}")
          add_problem("${file}" ${line} "${target}")
        endif()
      endforeach()
    endif()
    # Names of pages: each must be the name of some page of the tree.
    string(REGEX MATCHALL "${page_name}" mentions "${content}")
    foreach(mention IN LISTS mentions)
      string(REGEX REPLACE "${page_name}" "\\1" mention "${mention}")
      if(mention MATCHES "^//")
        continue()  # part of a web address
      endif()
      get_filename_component(name "${mention}" NAME)
      list(FIND page_names "${name}" found)
      if(found EQUAL -1)
        add_problem("${file}" ${line} "${mention}")
      endif()
    endforeach()
    # Paths into the places outside the tree.
    foreach(pattern IN ITEMS "${outside_path}" "${work_path}")
      string(REGEX MATCHALL "${pattern}" paths "${content}")
      foreach(path IN LISTS paths)
        string(REGEX REPLACE "${pattern}" "\\2" path "${path}")
        if(NOT EXISTS "${dir}/${path}" AND NOT EXISTS "${ROOT}/${path}")
          add_problem("${file}" ${line} "${path}")
        endif()
      endforeach()
    endforeach()
  endforeach()
endforeach()

list(REMOVE_DUPLICATES problems)
list(LENGTH problems problem_count)
if(problem_count GREATER 0)
  string(REPLACE ";" "\n  " listing "${problems}")
  message(FATAL_ERROR
    "outside_references: ${problem_count} reference(s) to files outside the repository "
    "(put what is cited into the tree, e.g. manual/, and cite that):\n  ${listing}")
endif()
message(STATUS "outside_references: ${file_count} files, none outside")
