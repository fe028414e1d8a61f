# mpirun -np 2 wearlink calibrate params/nine_bar_wear.prm from one mass loss per surface
# (four coefficients), with a 4-member ensemble, timed.
# cmake -DWEARLINK=... -DMPIRUN=... -DSOURCE_DIR=... -DOUTPUT_DIR=... -P calibrate_nine_bar_wear.cmake
file(REMOVE_RECURSE "${OUTPUT_DIR}")
string(TIMESTAMP start "%s" UTC)
execute_process(COMMAND ${MPIRUN} -np 2 ${WEARLINK} calibrate ${SOURCE_DIR}/params/nine_bar_wear.prm
                        --measurements ${SOURCE_DIR}/tests/benchmarks/calibration/nine_bar_wear_measurements.prm
                        --ensemble 4 --output ${OUTPUT_DIR}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(TIMESTAMP stop "%s" UTC)
math(EXPR seconds "${stop} - ${start}")
message("${err}${out}")
message("calibrate params/nine_bar_wear.prm (4 coefficients, ensemble of 4) on 2 MPI ranks: ${seconds} s wall; "
        "target < 300 s on 2 cores (measured with whatever else runs on the machine)")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the calibration failed with status ${status}")
endif()
foreach(f calibration.json calibrated.prm)
  if(NOT EXISTS ${OUTPUT_DIR}/${f})
    message(FATAL_ERROR "${f} was not written")
  endif()
endforeach()
