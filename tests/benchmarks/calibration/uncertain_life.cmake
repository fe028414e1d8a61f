# mpirun -np 2 wearlink life params/nine_bar_life.prm --ensemble 64 with both bushings'
# wear coefficients uncertain (lognormal about the assumed 4.6e-14 m³/(N m), σ_log 0.3),
# timed. cmake -DWEARLINK=... -DMPIRUN=... -DSOURCE_DIR=... -DOUTPUT_DIR=... -P uncertain_life.cmake
file(REMOVE_RECURSE "${OUTPUT_DIR}")
string(ASCII 59 semicolon) # one argument: a quoted ';' would stay escaped
set(inputs "Joint A/Clearance/archard/Bushing wear coefficient: lognormal(4.6e-14, 0.3)${semicolon}")
string(APPEND inputs " Joint B/Clearance/archard/Bushing wear coefficient: lognormal(4.6e-14, 0.3)")
string(TIMESTAMP start "%s" UTC)
execute_process(COMMAND ${MPIRUN} -np 2 ${WEARLINK} life ${SOURCE_DIR}/params/nine_bar_life.prm --ensemble 64
                        --quiet --output ${OUTPUT_DIR} --set "Uncertainty/Inputs=${inputs}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(TIMESTAMP stop "%s" UTC)
math(EXPR seconds "${stop} - ${start}")
message("${out}")
message("life params/nine_bar_life.prm, 64 members with uncertain inputs, on 2 MPI ranks: ${seconds} s wall; "
        "target < 1800 s on 2 cores (measured with whatever else runs on the machine)")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the life ensemble failed with status ${status}: ${err}")
endif()
foreach(f summary.json ensemble.csv life_cdf.png)
  if(NOT EXISTS ${OUTPUT_DIR}/${f})
    message(FATAL_ERROR "${f} was not written")
  endif()
endforeach()
