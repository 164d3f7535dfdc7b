# prism-render --mpi-partition: SCENE rendered whole in one process (prism)
# and split over RANKS processes (prism_mpi, mode PRISM_MPI_MODE from the
# test's environment), each holding its share of the surfaces. Every
# process must say it built a share; the depth channels must be identical
# (visibility is global in every mode). With -DCOLOR_RMSE= the colors must
# also agree to that RMSE (0.01 is a PSNR of 40 dB; for modes that shade
# across processes); without it they must differ (composite mode shades
# each process's share alone: light bouncing between shares is missing,
# which shows the scene really was split).
#   -DRENDER= -DIMAGE_DIFF= -DMPIRUN=<;-list> -DRANKS= -DSCENE= -DWORK_DIR=
#   [-DCOLOR_RMSE=]
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(common ${SCENE} --size 64x64 --spp 4 --renderer pathtracer)

execute_process(COMMAND ${RENDER} ${common} -o ${WORK_DIR}/single.pfm
    --depth ${WORK_DIR}/single-depth.pfm
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the single-process render failed (${result})")
endif()

execute_process(COMMAND ${MPIRUN} -np ${RANKS} ${RENDER} --library prism_mpi
    --mpi-partition ${common} -o ${WORK_DIR}/split.pfm
    --depth ${WORK_DIR}/split-depth.pfm
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the render under mpirun failed (${result}):\n${output}${errors}")
endif()
string(REGEX MATCHALL "of ${RANKS} builds its share" shares "${output}${errors}")
list(LENGTH shares sharers)
if(NOT sharers EQUAL RANKS)
  message(FATAL_ERROR "${sharers} of ${RANKS} processes built a share:\n${output}${errors}")
endif()

execute_process(COMMAND ${IMAGE_DIFF} ${WORK_DIR}/single-depth.pfm
    ${WORK_DIR}/split-depth.pfm --tolerance-rmse 0
  RESULT_VARIABLE result OUTPUT_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the depth channels differ:\n${output}")
endif()
if(DEFINED COLOR_RMSE)
  execute_process(COMMAND ${IMAGE_DIFF} ${WORK_DIR}/single.pfm
      ${WORK_DIR}/split.pfm --tolerance-rmse ${COLOR_RMSE}
    RESULT_VARIABLE result OUTPUT_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the colors differ:\n${output}")
  endif()
else()
  execute_process(COMMAND ${IMAGE_DIFF} ${WORK_DIR}/single.pfm
      ${WORK_DIR}/split.pfm --tolerance-rmse 0.01
    RESULT_VARIABLE result OUTPUT_VARIABLE output)
  if(result EQUAL 0)
    message(FATAL_ERROR "the split scene shades like the whole one:\n${output}")
  endif()
endif()
