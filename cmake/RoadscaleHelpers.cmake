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

# roadscale_add_test(NAME SOURCES a_test.cc b_test.cc [LABELS slow data] [PREFIX module.])
# One GoogleTest executable per module; each TEST becomes its own CTest case, its name
# preceded by PREFIX when given (so that `ctest -R module` selects a module's tests).
# Without ROADSCALE_BUILD_SLOW_TESTS an executable labelled slow is not built (the sanitizer
# build of CI runs `ctest -LE slow`, which would never run it).
function(roadscale_add_test name)
  cmake_parse_arguments(ARG "" "PREFIX" "SOURCES;LABELS" ${ARGN})
  if("slow" IN_LIST ARG_LABELS AND NOT ROADSCALE_BUILD_SLOW_TESTS)
    return()
  endif()
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE roadscale roadscale_testing GTest::gtest GTest::gtest_main)
  roadscale_set_compile_options(${name})
  gtest_discover_tests(${name}
    TEST_PREFIX "${ARG_PREFIX}"
    PROPERTIES LABELS "${ARG_LABELS}"
    DISCOVERY_TIMEOUT 60)
endfunction()
