# Runs prism-render once and checks what came of it (cmake -P script; lists
# use "|" so they survive add_test):
#   TOOL            the prism-render executable
#   ARGS            its arguments
#   WORKDIR         where it runs (created; outputs land here)
#   EXPECT_EXIT     0, 1, 2 or nonzero
#   EXPECT_STDERR   regex stderr must match
#   REJECT_STDERR   regex stderr must not match
#   STDERR_LINES    how many lines stderr must have
#   EXPECT_STDOUT   regex stdout must match
#   EXISTS          files that must exist afterwards
#   ABSENT          files that must not exist afterwards (no partial output)
#   IMAGE_DIFF      the image-diff executable, with
#   COMPARE         output|reference pairs, compared within
#   DIFF_ARGS       extra image-diff arguments (e.g. --tolerance-rmse|1e-5)
#   UPDATABLE       when set and PRISM_UPDATE_REFERENCES=1 is in the
#                   environment, outputs replace their references instead
#   INTERRUPT_AFTER seconds after which the run gets SIGINT (Ctrl-C), by
#                   coreutils' timeout
#   FIRST_ARGS      arguments of an earlier run in the same folder (must
#                   succeed), e.g. to write a reference for CHECK
#   PYTHON, CHECK_SCRIPT, CHECK
#                   after the run, `PYTHON CHECK_SCRIPT CHECK...` (the
#                   image assertions of check_image.py) must succeed
# Every listed output is deleted first, so a stale file never passes.
cmake_minimum_required(VERSION 3.25)

function(split out text)
  if(text)
    string(REPLACE "|" ";" list "${text}")
  else()
    set(list "")
  endif()
  set(${out} "${list}" PARENT_SCOPE)
endfunction()

split(args "${ARGS}")
split(exists "${EXISTS}")
split(absent "${ABSENT}")
split(compare "${COMPARE}")
split(diffArgs "${DIFF_ARGS}")
split(firstArgs "${FIRST_ARGS}")
split(check "${CHECK}")

file(MAKE_DIRECTORY "${WORKDIR}")
set(outputs ${exists} ${absent})
list(LENGTH compare compareLength)
if(compareLength GREATER 0)
  math(EXPR last "${compareLength} - 1")
  foreach(i RANGE 0 ${last} 2)
    list(GET compare ${i} output)
    list(APPEND outputs "${output}")
  endforeach()
endif()
foreach(output IN LISTS outputs)
  file(REMOVE "${WORKDIR}/${output}")
endforeach()

if(firstArgs)
  execute_process(COMMAND "${TOOL}" ${firstArgs}
    WORKING_DIRECTORY "${WORKDIR}"
    RESULT_VARIABLE firstStatus
    OUTPUT_VARIABLE firstOut
    ERROR_VARIABLE firstErr
    TIMEOUT 300)
  message("$ prism-render ${firstArgs}\nexit status: ${firstStatus}\n"
    "stdout:\n${firstOut}\nstderr:\n${firstErr}")
  if(NOT firstStatus EQUAL 0)
    message(FATAL_ERROR "the first run failed")
  endif()
endif()

set(command "${TOOL}" ${args})
if(INTERRUPT_AFTER)
  # --foreground: the signal goes to the tool alone, once, as a terminal's
  # Ctrl-C does.
  set(command timeout --foreground --preserve-status -s INT ${INTERRUPT_AFTER}
    ${command})
endif()
execute_process(COMMAND ${command}
  WORKING_DIRECTORY "${WORKDIR}"
  RESULT_VARIABLE status
  OUTPUT_VARIABLE stdout
  ERROR_VARIABLE stderr
  TIMEOUT 300)
message("$ prism-render ${args}\nexit status: ${status}\n"
  "stdout:\n${stdout}\nstderr:\n${stderr}")


if(EXPECT_EXIT STREQUAL "nonzero")
  if(status EQUAL 0 OR NOT status MATCHES "^[0-9]+$")
    message(FATAL_ERROR "expected a non-zero exit status, got '${status}'")
  endif()
elseif(NOT status STREQUAL EXPECT_EXIT)
  message(FATAL_ERROR "expected exit status ${EXPECT_EXIT}, got '${status}'")
endif()
if(DEFINED EXPECT_STDERR AND NOT stderr MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_STDERR}'")
endif()
if(DEFINED STDERR_LINES)
  string(REGEX MATCHALL "\n" newlines "${stderr}")
  list(LENGTH newlines lines)
  if(NOT lines EQUAL STDERR_LINES)
    message(FATAL_ERROR "stderr has ${lines} lines, not ${STDERR_LINES}")
  endif()
endif()
if(DEFINED REJECT_STDERR AND stderr MATCHES "${REJECT_STDERR}")
  message(FATAL_ERROR "stderr matches '${REJECT_STDERR}', but must not")
endif()
if(DEFINED EXPECT_STDOUT AND NOT stdout MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout does not match '${EXPECT_STDOUT}'")
endif()
foreach(file IN LISTS exists)
  if(NOT EXISTS "${WORKDIR}/${file}")
    message(FATAL_ERROR "'${file}' was not written")
  endif()
endforeach()
foreach(file IN LISTS absent)
  if(EXISTS "${WORKDIR}/${file}")
    message(FATAL_ERROR "'${file}' was written, but must not be")
  endif()
endforeach()

if(compareLength GREATER 0)
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET compare ${i} output)
    list(GET compare ${j} reference)
    if(NOT EXISTS "${WORKDIR}/${output}")
      message(FATAL_ERROR "'${output}' was not written")
    endif()
    if(UPDATABLE AND "$ENV{PRISM_UPDATE_REFERENCES}" STREQUAL "1")
      file(COPY_FILE "${WORKDIR}/${output}" "${reference}")
      message("updated ${reference}")
      continue()
    endif()
    if(NOT EXISTS "${reference}")
      message(FATAL_ERROR "no reference '${reference}'; create it with "
        "PRISM_UPDATE_REFERENCES=1 ctest -L cli, then look at it")
    endif()
    get_filename_component(stem "${output}" NAME_WE)
    execute_process(COMMAND "${IMAGE_DIFF}" "${WORKDIR}/${output}"
        "${reference}" ${diffArgs} --diff "${WORKDIR}/${stem}.diff.png"
      RESULT_VARIABLE diffStatus
      OUTPUT_VARIABLE diffOut
      ERROR_VARIABLE diffErr)
    message("image-diff ${output} ${reference}:\n${diffOut}${diffErr}")
    if(NOT diffStatus EQUAL 0)
      message(FATAL_ERROR "'${output}' differs from '${reference}' "
        "(see ${WORKDIR}/${stem}.diff.png)")
    endif()
  endforeach()
endif()

if(check)
  execute_process(COMMAND "${PYTHON}" "${CHECK_SCRIPT}" ${check}
    WORKING_DIRECTORY "${WORKDIR}"
    RESULT_VARIABLE checkStatus
    OUTPUT_VARIABLE checkOut
    ERROR_VARIABLE checkErr)
  message("check_image.py ${check}:\n${checkOut}${checkErr}")
  if(NOT checkStatus EQUAL 0)
    message(FATAL_ERROR "the image assertions failed (see above)")
  endif()
endif()
