# The tree follows .clang-format (doc/contributing.md §9; clang-format 14 as Debian 12
# ships it): every C++ file under src/ and tests/ must be unchanged by clang-format.
# Usage: cmake -DROOT=<source root> -DCLANG_FORMAT=<program> -P check_format.cmake
cmake_minimum_required(VERSION 3.16)
file(GLOB_RECURSE files "${ROOT}/src/*.h" "${ROOT}/src/*.cc" "${ROOT}/tests/*.h" "${ROOT}/tests/*.cc")
list(FILTER files EXCLUDE REGEX "/fixture_")
set(unformatted "")
foreach(f IN LISTS files)
  execute_process(COMMAND "${CLANG_FORMAT}" --style=file --dry-run --Werror "${f}"
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT rc EQUAL 0)
    file(RELATIVE_PATH rel "${ROOT}" "${f}")
    string(APPEND unformatted "  ${rel}\n")
  endif()
endforeach()
list(LENGTH files n)
if(unformatted)
  message(FATAL_ERROR "Not formatted as .clang-format says (fix: clang-format -i <file>):\n${unformatted}")
endif()
message(STATUS "check_format: ${n} files follow .clang-format")
