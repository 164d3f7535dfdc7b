# prism-mpi-example: SCENE built whole in one process (prism) and split
# over RANKS processes (prism_mpi, the example's default mode for the
# scene); rank 0's image must match to RMSE 0.01 (PSNR 40 dB) and only one
# process may write it.
#   -DEXAMPLE= -DIMAGE_DIFF= -DMPIRUN=<;-list> -DRANKS= -DSCENE= -DWORK_DIR=
#   [-DOPTIONS=<;-list>: more options for both runs, overriding the
#   defaults]
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(common --scene ${SCENE} --size 96x96 --spp 4 ${OPTIONS})

execute_process(COMMAND ${EXAMPLE} --library prism ${common}
    -o ${WORK_DIR}/whole.pfm
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the whole scene failed (${result}):\n${output}${errors}")
endif()

execute_process(COMMAND ${MPIRUN} -np ${RANKS} ${EXAMPLE} ${common}
    -o ${WORK_DIR}/split.pfm
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the split scene failed (${result}):\n${output}${errors}")
endif()
string(REGEX MATCHALL "wrote [^\n]*split.pfm [^\n]*${RANKS} processes" writes
  "${output}")
list(LENGTH writes writers)
if(NOT writers EQUAL 1)
  message(FATAL_ERROR "${writers} processes wrote the image, not 1:\n${output}")
endif()

execute_process(COMMAND ${IMAGE_DIFF} ${WORK_DIR}/whole.pfm
    ${WORK_DIR}/split.pfm --tolerance-rmse 0.01
  RESULT_VARIABLE result OUTPUT_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the images differ:\n${output}")
endif()
message(STATUS "${output}")
