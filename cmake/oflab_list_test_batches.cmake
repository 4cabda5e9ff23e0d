# Included by the ctest file of oflab_gtest_batches (OflabTestBatches.cmake) when ctest reads
# the tests: lists a test program's tests and writes the ctest file of their batches to
# OUTPUT. Variables: EXECUTABLE, OUTPUT, LABELS, TIMEOUT (seconds per test), FILTER (a
# --gtest_filter for the listing, may be empty), BATCH (tests per batch), SKIP (a regular
# expression of full test names to leave out, may be empty).
set(list_args --gtest_list_tests)
if(FILTER)
  list(APPEND list_args "--gtest_filter=${FILTER}")
endif()
execute_process(COMMAND "${EXECUTABLE}" ${list_args} OUTPUT_VARIABLE listing
                RESULT_VARIABLE result TIMEOUT 60)
if(NOT result EQUAL 0)
  file(REMOVE "${OUTPUT}")
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${result}):\n${listing}")
endif()

set(script "")
set(suite "")
set(batch "")
set(batch_size 0)
set(suite_batches 0)
set(suites "")
# One ctest test per batch: the names of its tests as one --gtest_filter.
macro(flush_batch)
  if(batch_size GREATER 0)
    math(EXPR suite_batches "${suite_batches} + 1")
    set(test_name "${suite}")
    if(suite_batches GREATER 1)
      set(test_name "${suite}.${suite_batches}")
    endif()
    math(EXPR timeout "${TIMEOUT} * ${batch_size}")
    string(APPEND script "add_test([==[${test_name}]==] [==[${EXECUTABLE}]==] "
                         "[==[--gtest_filter=${batch}]==])\n"
                         "set_tests_properties([==[${test_name}]==] PROPERTIES "
                         "LABELS [==[${LABELS}]==] TIMEOUT ${timeout} COST ${batch_size})\n")
    set(batch "")
    set(batch_size 0)
  endif()
endmacro()

string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  if(line MATCHES "^([^ #][^ ]*)\\.( .*)?$")  # "Suite." (a parameterised one "Prefix/Suite.")
    flush_batch()
    set(suite "${CMAKE_MATCH_1}")
    set(suite_batches 0)
  elseif(line MATCHES "^  ([^ ]+)" AND NOT suite STREQUAL "")  # "  Test  # GetParam() = ..."
    set(full "${suite}.${CMAKE_MATCH_1}")
    if(NOT SKIP STREQUAL "" AND full MATCHES "${SKIP}")
      continue()
    endif()
    if(batch_size EQUAL 0)
      set(batch "${full}")
    else()
      string(APPEND batch ":${full}")
    endif()
    math(EXPR batch_size "${batch_size} + 1")
    if(batch_size EQUAL BATCH)
      flush_batch()
    endif()
  endif()
endforeach()
flush_batch()
file(WRITE "${OUTPUT}.tmp" "${script}")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
