# PRISM_SANITIZE=address,undefined or thread: applied to everything built.
set(PRISM_SANITIZE "" CACHE STRING "Sanitizers to build with (address,undefined | thread)")
if(PRISM_SANITIZE)
  add_compile_options(-fsanitize=${PRISM_SANITIZE} -fno-sanitize-recover=all
    -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${PRISM_SANITIZE})
endif()

# PRISM_BUILD_FUZZERS: everything built gets libFuzzer's coverage
# instrumentation, so the fuzz targets see the edges they reach in the device
# and the front-end; only the targets themselves link libFuzzer
# (-fsanitize=fuzzer, see tests/fuzz). Builds without fuzzers are unchanged.
if(PRISM_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "PRISM_BUILD_FUZZERS needs clang (CXX=clang++)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
