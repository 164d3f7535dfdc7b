# `format` rewrites our sources with clang-format; the test style::ClangFormat
# fails when any of them is not formatted.
find_program(CLANG_FORMAT clang-format)
if(CLANG_FORMAT)
  file(GLOB_RECURSE PRISM_FORMATTED_SOURCES CONFIGURE_DEPENDS
    ${PROJECT_SOURCE_DIR}/include/*.h ${PROJECT_SOURCE_DIR}/include/*.hpp
    ${PROJECT_SOURCE_DIR}/src/*.h ${PROJECT_SOURCE_DIR}/src/*.cpp
    ${PROJECT_SOURCE_DIR}/tests/*.h ${PROJECT_SOURCE_DIR}/tests/*.cpp
    ${PROJECT_SOURCE_DIR}/tests/*.c ${PROJECT_SOURCE_DIR}/tools/*.cpp
    ${PROJECT_SOURCE_DIR}/tools/*.h ${PROJECT_SOURCE_DIR}/bench/*.cpp
    ${PROJECT_SOURCE_DIR}/scenes/*.h ${PROJECT_SOURCE_DIR}/scenes/*.cpp
    ${PROJECT_SOURCE_DIR}/python/*.h ${PROJECT_SOURCE_DIR}/python/*.cpp)
  add_custom_target(format
    COMMAND ${CLANG_FORMAT} -i ${PRISM_FORMATTED_SOURCES}
    COMMENT "clang-format on ${PROJECT_NAME} sources")
  if(PRISM_BUILD_TESTS)
    add_test(NAME style::ClangFormat
      COMMAND ${CLANG_FORMAT} --dry-run -Werror ${PRISM_FORMATTED_SOURCES})
    set_tests_properties(style::ClangFormat PROPERTIES LABELS style)
  endif()
endif()
