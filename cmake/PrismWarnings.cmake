# Warnings as an INTERFACE target: link it to code we write, not to
# generated or third-party code.
add_library(prism_warnings INTERFACE)
target_compile_options(prism_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wno-unused-parameter>
  $<$<COMPILE_LANGUAGE:C>:-Wall -Wextra -Wpedantic>)
option(PRISM_WERROR "Treat warnings as errors" OFF)
if(PRISM_WERROR)
  target_compile_options(prism_warnings INTERFACE -Werror)
endif()
