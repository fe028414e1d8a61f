# Run a command that must fail: non-zero exit, output matching EXPECT (a regex), and no
# files left in OUTPUT_DIR (no half-written outputs). With EXPECT_STATUS, exactly that
# exit status (2 for bad input).
#   cmake -DCOMMAND="a;b;c" -DEXPECT=regex -DOUTPUT_DIR=dir [-DEXPECT_STATUS=2] -P expect_failure.cmake
file(REMOVE_RECURSE "${OUTPUT_DIR}")
execute_process(COMMAND ${COMMAND}
                RESULT_VARIABLE status
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
set(all "${out}${err}")
message("${all}")
if(status EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit status, got 0")
endif()
if(NOT status MATCHES "^[0-9]+$")
  message(FATAL_ERROR "the program did not exit normally: ${status}")
endif()
if(status EQUAL 1)
  message(FATAL_ERROR "exit status 1 means an internal error, not a user-input error")
endif()
if(DEFINED EXPECT_STATUS AND NOT status EQUAL EXPECT_STATUS)
  message(FATAL_ERROR "expected the exit status ${EXPECT_STATUS}, got ${status}")
endif()
if(NOT all MATCHES "${EXPECT}")
  message(FATAL_ERROR "the message does not match the expected regex: ${EXPECT}")
endif()
if(EXISTS "${OUTPUT_DIR}")
  file(GLOB_RECURSE left "${OUTPUT_DIR}/*")
  if(left)
    message(FATAL_ERROR "files were left behind: ${left}")
  endif()
endif()
