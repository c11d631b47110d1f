# One ctest test per GoogleTest suite instead of one per test: a process
# start (and, under ASan, the leak check at exit) costs 0.05 s in the release
# build and 0.18 s in the sanitizer build, and 641 tests one process each
# took 212 s of the sanitizer run (67 s of the release run) against 117 s
# (55 s) for the 154 suites. Each test of a suite still runs and fails on
# its own in the suite's process (--output-on-failure names it).
#
# aapat_gtest_suites(TARGET ENVIRONMENT ...) registers the suites the built
# binary lists, as gtest_discover_tests does for tests: after each build the
# binary writes its suite names (script mode of this file, below), and ctest
# reads them through an include file that stands in a failing test while the
# binary is not built yet.
if(CMAKE_SCRIPT_MODE_FILE)
  # Script mode: -DBINARY=... -DOUT=... writes `set(aapat_test_suites ...)`.
  execute_process(COMMAND ${BINARY} --gtest_list_tests OUTPUT_VARIABLE listing
    RESULT_VARIABLE status TIMEOUT 60)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${BINARY} --gtest_list_tests failed (${status})")
  endif()
  string(REPLACE "\n" ";" lines "${listing}")
  set(suites "")
  foreach(line IN LISTS lines)
    # A suite's line starts in the first column and ends its name with a
    # dot (a parameterized suite adds a comment after it).
    if(line MATCHES "^([A-Za-z0-9_/]+)\\.( .*)?$")
      list(APPEND suites ${CMAKE_MATCH_1})
    endif()
  endforeach()
  file(WRITE ${OUT}.new "set(aapat_test_suites ${suites})\n")
  file(RENAME ${OUT}.new ${OUT})
  return()
endif()

function(aapat_gtest_suites target)
  cmake_parse_arguments(ARG "" "" "ENVIRONMENT" ${ARGN})
  set(list_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_suites.cmake)
  set(include_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_suites_include.cmake)
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -DBINARY=$<TARGET_FILE:${target}> -DOUT=${list_file}
      -P ${CMAKE_SOURCE_DIR}/cmake/gtest_suites.cmake
    BYPRODUCTS ${list_file} VERBATIM)
  # The environment's items, joined by semicolons in one quoted argument: a
  # list-valued property, as gtest_discover_tests writes it.
  set(environment "${ARG_ENVIRONMENT}")
  file(GENERATE OUTPUT ${include_file} CONTENT "\
if(EXISTS \"${list_file}\")
  include(\"${list_file}\")
  foreach(suite IN LISTS aapat_test_suites)
    add_test(\"\${suite}.*\" \"$<TARGET_FILE:${target}>\" \"--gtest_filter=\${suite}.*\")
    set_tests_properties(\"\${suite}.*\" PROPERTIES ENVIRONMENT \"${environment}\")
  endforeach()
else()
  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)
endif()
")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include_file})
endfunction()
