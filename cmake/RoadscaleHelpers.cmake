# Compiler flags shared by every roadscale target.
function(roadscale_set_compile_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(ROADSCALE_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(ROADSCALE_FUZZ)
    # Coverage feedback for libFuzzer in everything the fuzz targets call.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()

# roadscale_add_test(NAME SOURCES a_test.cc b_test.cc [LABELS slow data] [PREFIX module.]
#                    [READS_IMAGES])
# One GoogleTest executable per module. Each suite becomes one CTest test (its name preceded by
# PREFIX when given, so that `ctest -R module` selects a module's tests) that runs the suite's
# tests in one process: a process that loads OpenCV's image and video readers loads 263 shared
# libraries, 0.2 s on a 2-core machine (0.6 s with the sanitizers), for tests that mostly take
# milliseconds. READS_IMAGES links those readers, for tests that call cv::imread or cv::imwrite
# themselves; the library reaches them through its codecs plugin (io/codecs_plugin.h). A
# program labelled slow gives each test its own CTest test instead, so that its long tests run
# side by side. Without ROADSCALE_BUILD_SLOW_TESTS an executable labelled slow is
# not built (the sanitizer build of CI runs `ctest -LE slow`, which would never run it).
function(roadscale_add_test name)
  cmake_parse_arguments(ARG "READS_IMAGES" "PREFIX" "SOURCES;LABELS" ${ARGN})
  if("slow" IN_LIST ARG_LABELS AND NOT ROADSCALE_BUILD_SLOW_TESTS)
    return()
  endif()
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE roadscale roadscale_testing roadscale_test_main GTest::gtest)
  if(ARG_READS_IMAGES)
    target_link_libraries(${name} PRIVATE roadscale_opencv_codecs)
  endif()
  roadscale_set_compile_options(${name})
  if("slow" IN_LIST ARG_LABELS)
    gtest_discover_tests(${name}
      TEST_PREFIX "${ARG_PREFIX}"
      PROPERTIES LABELS "${ARG_LABELS}" SKIP_RETURN_CODE 77
      DISCOVERY_TIMEOUT 60)
    return()
  endif()
  set(suites_file "${CMAKE_CURRENT_BINARY_DIR}/${name}_suites.cmake")
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/${name}_suites_include.cmake")
  file(WRITE "${include_file}"
    "if(EXISTS [==[${suites_file}]==])\n"
    "  include([==[${suites_file}]==])\n"
    "else()\n"
    "  add_test(${name}_NOT_BUILT ${name}_NOT_BUILT)\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
  string(REPLACE ";" "," labels "${ARG_LABELS}")
  add_custom_command(TARGET ${name} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -D TEST_EXECUTABLE=$<TARGET_FILE:${name}> -D CTEST_FILE=${suites_file}
            -D TEST_PREFIX=${ARG_PREFIX} -D TEST_LABELS=${labels}
            -D WORKING_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR}
            -P ${PROJECT_SOURCE_DIR}/cmake/DiscoverTestSuites.cmake
    BYPRODUCTS ${suites_file}
    VERBATIM)
endfunction()
