# prism-render, an MPI-unaware program, renders SCENE once in one process
# (prism) and once under mpirun (prism_mpi in the mode PRISM_MPI_MODE from
# the test's environment); the two images must be identical, and only rank
# 0 may write (the others' images are partial and would race for the file).
#   -DRENDER= -DIMAGE_DIFF= -DMPIRUN=<;-list> -DRANKS= -DSCENE= -DWORK_DIR=
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(common ${SCENE} --size 64x64 --spp 4 --renderer pathtracer)

execute_process(COMMAND ${RENDER} ${common} -o ${WORK_DIR}/single.pfm
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the single-process render failed (${result})")
endif()

execute_process(COMMAND ${MPIRUN} -np ${RANKS} ${RENDER} --library prism_mpi
    ${common} -o ${WORK_DIR}/mpi.pfm
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the render under mpirun failed (${result}):\n${output}${errors}")
endif()
string(REGEX MATCHALL "wrote [^\n]*mpi.pfm" writes "${output}")
list(LENGTH writes writers)
if(NOT writers EQUAL 1)
  message(FATAL_ERROR "${writers} processes wrote the image, not 1:\n${output}")
endif()

execute_process(COMMAND ${IMAGE_DIFF} ${WORK_DIR}/single.pfm
    ${WORK_DIR}/mpi.pfm --tolerance-rmse 0
  RESULT_VARIABLE result OUTPUT_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the images differ:\n${output}")
endif()
