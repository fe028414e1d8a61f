# A sweep member that fails while running is reported and the others still run; a sweep
# in which every member fails exits with status 3; a bad --channel is an input error
# (status 2) before anything runs.
#   cmake -DWEARLINK=... -DSOURCE_DIR=... -DOUTPUT_DIR=... -P sweep_failed_member.cmake
#
# Swept: the crank speed of the four-bar (params/four_bar.prm), 0 and 300 rpm. At
# 0 rad/s the driver does not turn, so the member has no driving period for its Poincaré
# section: it fails at run time (status "failed", the message names the entry to set);
# the 300 rpm member runs (sections at 0.2, 0.4, ..., 1.0 s: 5 points).
file(REMOVE_RECURSE "${OUTPUT_DIR}")
execute_process(COMMAND ${WEARLINK} sweep ${SOURCE_DIR}/params/four_bar.prm
                        --parameter "Joint drive/Angular velocity" --values 0:31.41592653589793:2
                        --set "Analyses/Transient=0.2" --output ${OUTPUT_DIR}/mixed --quiet
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "a sweep with one failed member must still succeed (status ${status})")
endif()
file(STRINGS ${OUTPUT_DIR}/mixed/members.csv members ENCODING UTF-8)
list(GET members 1 m0)
list(GET members 2 m1)
if(NOT m0 MATCHES "^0,0,failed,0,.*no turning angle driver.*Driving period"
   OR NOT m1 MATCHES "^1,31.4159265359,ok,5,")
  message(FATAL_ERROR "unexpected member statuses:\n${m0}\n${m1}")
endif()
if(NOT out MATCHES "1 of 2 members ran")
  message(FATAL_ERROR "the summary line does not report the failed member")
endif()

execute_process(COMMAND ${WEARLINK} sweep ${SOURCE_DIR}/params/four_bar.prm
                        --parameter "Joint drive/Angular velocity" --values 0:0:1
                        --output ${OUTPUT_DIR}/all_failed --quiet
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 3)
  message(FATAL_ERROR "a sweep in which every member failed must exit with 3, got ${status}\n${out}${err}")
endif()

execute_process(COMMAND ${WEARLINK} sweep ${SOURCE_DIR}/params/four_bar.prm
                        --parameter "Joint A/Clearance/Radial clearance" --values 1e-4:2e-4:2
                        --channel A_x_m --output ${OUTPUT_DIR}/bad_channel --quiet
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "no channel 'A_x_m'.*A_ex_m")
  message(FATAL_ERROR "a bad --channel must be an input error listing the channels (status ${status})\n${out}${err}")
endif()
if(EXISTS ${OUTPUT_DIR}/bad_channel)
  message(FATAL_ERROR "a sweep with bad input wrote ${OUTPUT_DIR}/bad_channel")
endif()
