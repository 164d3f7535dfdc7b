# prism-mpi-example with bad options: each invocation exits with status 2,
# says what is wrong on stderr, and writes no image.
#   -DEXAMPLE= -DWORK_DIR=
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(cases
  "--scene|teapot|-o|out.png" "unknown scene 'teapot'"
  "--size|0x0|-o|out.png" "--size: expected WxH"
  "--size|wide|-o|out.png" "--size: expected WxH"
  "--spp|0|-o|out.png" "--spp: expected a positive number"
  "--frobnicate|1|-o|out.png" "unknown option --frobnicate"
  "-o" "expected a value after -o")
list(LENGTH cases length)
math(EXPR last "${length} - 1")
foreach(i RANGE 0 ${last} 2)
  math(EXPR j "${i} + 1")
  list(GET cases ${i} arguments)
  list(GET cases ${j} expected)
  string(REPLACE "|" ";" arguments "${arguments}")
  execute_process(COMMAND ${EXAMPLE} ${arguments}
    WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
  if(NOT result EQUAL 2)
    message(FATAL_ERROR
      "${arguments}: exit ${result}, expected 2:\n${output}${errors}")
  endif()
  string(FIND "${errors}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${arguments}: stderr lacks '${expected}':\n${errors}")
  endif()
  if(EXISTS ${WORK_DIR}/out.png)
    message(FATAL_ERROR "${arguments}: an image was written")
  endif()
endforeach()
