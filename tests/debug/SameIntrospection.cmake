# anari-info (INFO) lists the same devices, extensions, subtypes and
# parameters for the debug layer around prism as for prism itself.
# Run as cmake -DINFO=... -P.
execute_process(COMMAND ${INFO} prism OUTPUT_VARIABLE plain RESULT_VARIABLE a)
execute_process(COMMAND ${INFO} debug OUTPUT_VARIABLE layered RESULT_VARIABLE b)
if(NOT a EQUAL 0 OR NOT b EQUAL 0)
  message(FATAL_ERROR "anari-info failed")
endif()
# The first line names the library. (REGEX REPLACE would apply "^" again
# after each match, emptying the text.)
foreach(text plain layered)
  string(FIND "${${text}}" "\n" newline)
  math(EXPR newline "${newline} + 1")
  string(SUBSTRING "${${text}}" ${newline} -1 ${text})
endforeach()
if(NOT plain STREQUAL layered OR plain STREQUAL "")
  message(FATAL_ERROR "introspection differs through the layer")
endif()
message(STATUS "same introspection")
