# PRISM_SANITIZE=address,undefined or thread: applied to everything built.
set(PRISM_SANITIZE "" CACHE STRING "Sanitizers to build with (address,undefined | thread)")
if(PRISM_SANITIZE)
  add_compile_options(-fsanitize=${PRISM_SANITIZE} -fno-sanitize-recover=all
    -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${PRISM_SANITIZE})
endif()
