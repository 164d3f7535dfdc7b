# Renders ARGS with prism-render (RENDER) once as is and once wrapped in the
# debug layer (ANARI_DEBUG_LAYER=1): the layer must stay silent and the two
# images be the same bytes. Run as cmake -DRENDER=... -DARGS=... -DOUT=... -P.
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${RENDER} ${args} -o ${OUT}.plain.png
  RESULT_VARIABLE plainResult ERROR_VARIABLE plainErrors OUTPUT_QUIET)
execute_process(COMMAND ${CMAKE_COMMAND} -E env ANARI_DEBUG_LAYER=1
    ${RENDER} ${args} -o ${OUT}.layered.png
  RESULT_VARIABLE layeredResult ERROR_VARIABLE layeredErrors OUTPUT_QUIET)
if(NOT plainResult EQUAL 0 OR NOT layeredResult EQUAL 0)
  message(FATAL_ERROR "prism-render failed: ${plainErrors} / ${layeredErrors}")
endif()
if(NOT layeredErrors STREQUAL plainErrors)
  message(FATAL_ERROR "the layer reported:\n${layeredErrors}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
    ${OUT}.plain.png ${OUT}.layered.png RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "the image through the layer differs")
endif()
message(STATUS "same image, nothing reported")
