# Writes CTEST_FILE: one CTest test per suite of the GoogleTest program TEST_EXECUTABLE, named
# TEST_PREFIX + the suite, running the suite's tests in one process. Run at build time by
# roadscale_add_test (RoadscaleHelpers.cmake), after the program is linked.
#   cmake -D TEST_EXECUTABLE=... -D CTEST_FILE=... -D TEST_PREFIX=... -D TEST_LABELS=a,b
#         -D WORKING_DIRECTORY=... -P DiscoverTestSuites.cmake
execute_process(COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests
                WORKING_DIRECTORY "${WORKING_DIRECTORY}"
                OUTPUT_VARIABLE listing ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${status}): ${errors}")
endif()
string(REPLACE "," ";" labels "${TEST_LABELS}")
# A parameter printed after a test's name may hold ';', CMake's list separator.
string(REPLACE ";" "," listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(content "")
foreach(line IN LISTS lines)
  # A suite's line is its name and a dot (then perhaps "  # TypeParam = ..."); its tests'
  # lines are indented.
  if(line MATCHES "^([^ ]+)\\.")
    set(test "${TEST_PREFIX}${CMAKE_MATCH_1}")
    string(APPEND content
      "add_test([==[${test}]==] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${CMAKE_MATCH_1}.*]==])\n"
      "set_tests_properties([==[${test}]==] PROPERTIES WORKING_DIRECTORY [==[${WORKING_DIRECTORY}]==]"
      " SKIP_RETURN_CODE 77 LABELS [==[${labels}]==])\n")
  endif()
endforeach()
# A listing that yields no suite would leave the program's tests out of CTest unnoticed.
if(content STREQUAL "")
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests listed no suite: ${listing}")
endif()
file(WRITE "${CTEST_FILE}" "${content}")
