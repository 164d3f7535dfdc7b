# Runs FUZZER once over every file in CORPUS (libFuzzer runs file arguments
# once each and exits non-zero on the first crash, leak or timeout).
file(GLOB inputs LIST_DIRECTORIES false "${CORPUS}/*")
list(LENGTH inputs count)
if(count EQUAL 0)
  message(FATAL_ERROR "no inputs in ${CORPUS}")
endif()
execute_process(COMMAND ${FUZZER} -timeout=60 ${inputs}
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (${result}) on the corpus")
endif()
message(STATUS "${count} inputs replayed")
