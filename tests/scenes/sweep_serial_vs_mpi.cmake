# The sweep over MPI ranks gives the same bifurcation diagram as the serial sweep.
#   cmake -DWEARLINK=... -DMPIRUN=... -DSOURCE_DIR=... -DOUTPUT_DIR=... -P sweep_serial_vs_mpi.cmake
#
# Scene: the four-bar with a clearance joint at A (params/four_bar.prm), 2 s = 10 crank
# revolutions, Poincaré points of A_ex_m after a 0.4 s transient (9 per member: 0.4, 0.6, ..., 2.0 s), swept
# over the radial clearance -1e-4 : 3e-4 in 5 values. Members 0 (-1e-4 m, outside the
# entry's pattern) and 1 (0 m, "a clearance joint needs a gap") are invalid and must be
# reported without sinking the sweep; members 2-4 run.
#
# Why the CSV files must be byte-identical: a member's computation depends only on the
# scene and its value (fresh scene, fresh ledger, deterministic integrator), never on
# the rank or on the members that ran before it in the same process; with 2 ranks the
# round-robin gives rank 1 members 1 and 3, which ran after 0 and 2 serially. Timings
# and ranks are only in sweep.json, not in the CSV files.
file(REMOVE_RECURSE "${OUTPUT_DIR}")
set(args sweep ${SOURCE_DIR}/params/four_bar.prm
    --parameter "Joint A/Clearance/Radial clearance" --values -1e-4:3e-4:5
    --set "Simulation/End time=2.0" --set "Analyses/Transient=0.4" --quiet)

execute_process(COMMAND ${WEARLINK} ${args} --output ${OUTPUT_DIR}/serial
                RESULT_VARIABLE status_serial OUTPUT_VARIABLE out_serial ERROR_VARIABLE err_serial)
message("serial:\n${out_serial}${err_serial}")
if(NOT status_serial EQUAL 0)
  message(FATAL_ERROR "the serial sweep failed with status ${status_serial}")
endif()

execute_process(COMMAND ${MPIRUN} -np 2 --oversubscribe ${WEARLINK} ${args} --output ${OUTPUT_DIR}/mpi
                RESULT_VARIABLE status_mpi OUTPUT_VARIABLE out_mpi ERROR_VARIABLE err_mpi)
message("mpirun -np 2:\n${out_mpi}${err_mpi}")
if(NOT status_mpi EQUAL 0)
  message(FATAL_ERROR "the MPI sweep failed with status ${status_mpi}")
endif()
if(NOT out_mpi MATCHES "2 MPI ranks")
  message(FATAL_ERROR "the MPI sweep did not run on 2 ranks")
endif()

foreach(f bifurcation.csv members.csv)
  foreach(run serial mpi)
    if(NOT EXISTS ${OUTPUT_DIR}/${run}/${f})
      message(FATAL_ERROR "${run}: ${f} was not written")
    endif()
  endforeach()
  file(SHA256 ${OUTPUT_DIR}/serial/${f} h_serial)
  file(SHA256 ${OUTPUT_DIR}/mpi/${f} h_mpi)
  if(NOT h_serial STREQUAL h_mpi)
    message(FATAL_ERROR "${f} differs between the serial and the 2-rank sweep")
  endif()
endforeach()

# Statuses: two invalid members reported, three that ran with 9 points each.
file(STRINGS ${OUTPUT_DIR}/serial/members.csv members ENCODING UTF-8)
list(GET members 1 m0)
list(GET members 2 m1)
list(GET members 3 m2)
list(GET members 5 m4)
if(NOT m0 MATCHES "^0,-0.0001,invalid,0,.*does not match" OR NOT m1 MATCHES "^1,0,invalid,0,.*needs a gap"
   OR NOT m2 MATCHES "^2,0.0001,ok,9," OR NOT m4 MATCHES "^4,0.0003,ok,9,")
  message(FATAL_ERROR "unexpected member statuses:\n${m0}\n${m1}\n${m2}\n${m4}")
endif()
file(STRINGS ${OUTPUT_DIR}/serial/bifurcation.csv points ENCODING UTF-8)
list(LENGTH points n_lines)
if(NOT n_lines EQUAL 28) # header + 3 members x 9 points
  message(FATAL_ERROR "bifurcation.csv has ${n_lines} lines, expected 28")
endif()
# Both ranks ran members, and only rank 0 wrote: no temporary files anywhere.
file(READ ${OUTPUT_DIR}/mpi/sweep.json summary)
if(NOT summary MATCHES "\"rank\": 1")
  message(FATAL_ERROR "no member ran on rank 1")
endif()
file(GLOB_RECURSE partial "${OUTPUT_DIR}/*.partial-*")
if(partial)
  message(FATAL_ERROR "temporary files left behind: ${partial}")
endif()
