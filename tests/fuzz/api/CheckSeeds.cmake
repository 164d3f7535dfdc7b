# Fails when the seeds in CORPUS differ from what WRITER writes now
# (regenerate: fuzz_api_seeds tests/fuzz/api/corpus).
file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}")
execute_process(COMMAND ${WRITER} "${SCRATCH}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${WRITER} failed")
endif()
file(GLOB written RELATIVE "${SCRATCH}" "${SCRATCH}/seed-*")
file(GLOB committed RELATIVE "${CORPUS}" "${CORPUS}/seed-*")
if(NOT written STREQUAL committed)
  message(FATAL_ERROR "seed files differ: regenerate with "
    "'fuzz_api_seeds tests/fuzz/api/corpus'")
endif()
foreach(name IN LISTS written)
  file(SHA256 "${SCRATCH}/${name}" a)
  file(SHA256 "${CORPUS}/${name}" b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "${name} differs from what the writer makes: "
      "regenerate with 'fuzz_api_seeds tests/fuzz/api/corpus'")
  endif()
endforeach()
