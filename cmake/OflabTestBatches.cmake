# oflab_gtest_batches(<target> LABELS <labels> TIMEOUT <seconds> [FILTER <gtest filter>]):
# the GoogleTest program's tests as ctest tests, a batch of up to OFLAB_TEST_BATCH tests of one
# suite per ctest test (named <Suite>, or <Suite>.<n> when a suite has several batches), each
# batch one process running its tests by name (--gtest_filter). A test program linked
# against Qt and VTK takes about a quarter of a second of processor time only to start,
# so one process per test cost more than most tests; a batch pays it once.
#
# The tests are listed when ctest reads the tests (the program's --gtest_list_tests, with
# FILTER applied; again only after the program or this configuration changed), as
# gtest_discover_tests does in its PRE_TEST mode. Tests whose full name (Suite.Test, a
# parameterised one with its instance prefix and value suffix) matches the regular expression
# OFLAB_TEST_SKIP are left out (the sanitized tree's list, tools/run-tests.sh). A batch's
# timeout is TIMEOUT per test, and its COST its test count (ctest starts the larger first).
set(OFLAB_TEST_BATCH 8 CACHE STRING "Most GoogleTest tests run in one process by one ctest test")
set(OFLAB_TEST_SKIP "" CACHE STRING "Regular expression of GoogleTest full names not to run")

function(oflab_gtest_batches target)
  cmake_parse_arguments(PARSE_ARGV 1 BATCH "" "TIMEOUT;FILTER" "LABELS")
  set(listed "${CMAKE_CURRENT_BINARY_DIR}/${target}_batches.cmake")
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_include.cmake")
  file(GENERATE OUTPUT "${include_file}" CONTENT
"set(EXECUTABLE [==[$<TARGET_FILE:${target}>]==])
set(OUTPUT [==[${listed}]==])
if(NOT EXISTS \"\${EXECUTABLE}\")
  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)
  return()
endif()
if(NOT EXISTS \"\${OUTPUT}\" OR \"\${EXECUTABLE}\" IS_NEWER_THAN \"\${OUTPUT}\"
   OR \"\${CMAKE_CURRENT_LIST_FILE}\" IS_NEWER_THAN \"\${OUTPUT}\")
  set(LABELS [==[${BATCH_LABELS}]==])
  set(TIMEOUT ${BATCH_TIMEOUT})
  set(FILTER [==[${BATCH_FILTER}]==])
  set(BATCH ${OFLAB_TEST_BATCH})
  set(SKIP [==[${OFLAB_TEST_SKIP}]==])
  include([==[${PROJECT_SOURCE_DIR}/cmake/oflab_list_test_batches.cmake]==])
endif()
include(\"\${OUTPUT}\")
")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
endfunction()
