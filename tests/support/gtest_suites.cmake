# Registers one CTest test per GoogleTest suite of a test executable (the unit tests'
# registration; wearlink_add_gtest(... PER_SUITE), tests/CMakeLists.txt). Run after the
# executable is built:
#   cmake -DEXE=path -DOUT=file.cmake -DLABEL=label -DTIMEOUT=seconds -DWORKDIR=dir -P gtest_suites.cmake
# It lists the executable's tests (--gtest_list_tests) and writes OUT, which CTest
# includes: per suite `add_test(Suite EXE --gtest_filter=Suite.*)` with LABEL and a
# timeout of TIMEOUT per test of the suite. Why per suite: a test process starts in
# ~0.27 s here (the dynamic loader resolving deal.II's symbols, doc/performance.md), which
# is most of what a unit test costs; one process per suite instead of per test saves
# that ~150 times over. A failing suite's output names the failing test.
foreach(_var EXE OUT LABEL TIMEOUT WORKDIR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "gtest_suites.cmake: -D${_var}=... is required")
  endif()
endforeach()
execute_process(COMMAND "${EXE}" --gtest_list_tests
                OUTPUT_VARIABLE _listing ERROR_VARIABLE _errors RESULT_VARIABLE _status TIMEOUT 60)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "${EXE} --gtest_list_tests failed (${_status}):\n${_listing}${_errors}")
endif()
string(REPLACE "\n" ";" _lines "${_listing}")
set(_suites "")
set(_suite "")
foreach(_line IN LISTS _lines)
  if(_line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    set(_suite "${CMAKE_MATCH_1}")
    list(APPEND _suites "${_suite}")
    set(_count_${_suite} 0)
  elseif(_line MATCHES "^  [^ ]" AND NOT _suite STREQUAL "")
    math(EXPR _count_${_suite} "${_count_${_suite}} + 1")
  endif()
endforeach()
if(_suites STREQUAL "")
  message(FATAL_ERROR "${EXE} lists no test suite:\n${_listing}")
endif()
set(_content "# Written by tests/support/gtest_suites.cmake from ${EXE} --gtest_list_tests\n")
foreach(_suite IN LISTS _suites)
  math(EXPR _timeout "${TIMEOUT} * ${_count_${_suite}}")
  string(APPEND _content
         "add_test([==[${_suite}]==] [==[${EXE}]==] [==[--gtest_filter=${_suite}.*]==])\n"
         "set_tests_properties([==[${_suite}]==] PROPERTIES LABELS [==[${LABEL}]==] TIMEOUT ${_timeout} "
         "WORKING_DIRECTORY [==[${WORKDIR}]==])\n")
endforeach()
file(WRITE "${OUT}" "${_content}")
