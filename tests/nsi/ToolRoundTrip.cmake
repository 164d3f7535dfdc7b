# nsi-render --write twice: a scene file written as a stream, that stream
# written again, and the two must be the same bytes (the reader made the
# same calls the first time as the second). Run as cmake -DTOOL=... -DSCENE=...
# -DWORKDIR=... -P ToolRoundTrip.cmake.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(COMMAND ${TOOL} --write ${WORKDIR}/first.nsi ${SCENE}
  RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0 OR NOT errors STREQUAL "")
  message(FATAL_ERROR "first write failed (${status}): ${errors}")
endif()
execute_process(COMMAND ${TOOL} --write ${WORKDIR}/second.nsi ${WORKDIR}/first.nsi
  RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0 OR NOT errors STREQUAL "")
  message(FATAL_ERROR "second write failed (${status}): ${errors}")
endif()
file(READ ${WORKDIR}/first.nsi first)
file(READ ${WORKDIR}/second.nsi second)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "the stream changed when read back and written again")
endif()
string(FIND "${first}" "Connect \"lamp_attr\" \"\" \"lamp_xf\" \"geometryattributes\"" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the written stream lacks the scene's last connection")
endif()
