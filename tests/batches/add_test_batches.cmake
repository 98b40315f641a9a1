# glossy_add_test_batches(TARGET MAX_TESTS n [SEPARATE suite...]): CTest tests that run a GoogleTest executable a suite at a time.
#
# Why not one CTest test per case (gtest_discover_tests): the executable links OpenImageIO, whose many
# dependencies (OpenVDB, GDAL, OpenCV, …) the dynamic loader binds at every start, a cost that a process per
# case pays a thousand times (docs/testing.md has the figures). A suite's cases run in one process
# instead, split into shards of at most MAX_TESTS cases (GoogleTest's own GTEST_TOTAL_SHARDS and
# GTEST_SHARD_INDEX) so that large parameterised families still spread over the cores. Each test is named after
# its suite (`Family/Chi2#3/17` for a shard); `--output-on-failure` shows which case failed. The suites named
# in SEPARATE, whose cases are long, keep a test per case, for the scheduler to spread them. The
# executable's main (batch_main.cpp) exits 77, CTest's skip, when a case of the batch skipped and none
# failed, so that absent data is never reported as passed.
#
# As gtest_discover_tests does, the list is read from the built executable after each link and included by
# CTest (write_test_batches.cmake).
function(glossy_add_test_batches target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "MAX_TESTS" "SEPARATE")
  set(ctest_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_batches.cmake")
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -D EXE=$<TARGET_FILE:${target}> -D OUT=${ctest_file} -D MAX_TESTS=${arg_MAX_TESTS}
            "-D SEPARATE=${arg_SEPARATE}"
            -D WORKING_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR}
            -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/write_test_batches.cmake
    BYPRODUCTS ${ctest_file}
    VERBATIM)
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${ctest_file})
endfunction()
