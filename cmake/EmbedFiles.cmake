# rbcsim_embed_files(OUTPUT <file.cpp> BASE_DIR <dir> FILES <relative paths...> HEADER <include>
#                    NAMESPACE <ns> FUNCTION <name> COMMENT <text>)
# Generates OUTPUT at build time with cmake/embed_files.cmake: the FILES (below BASE_DIR) as
# string literals behind `std::span<const rbcsim::EmbeddedFile> NAMESPACE::FUNCTION()`, declared
# in HEADER. Rebuilt when any of the files changes.
function(rbcsim_embed_files)
  cmake_parse_arguments(EMBED "" "OUTPUT;BASE_DIR;HEADER;NAMESPACE;FUNCTION;COMMENT" "FILES" ${ARGN})
  list(TRANSFORM EMBED_FILES PREPEND ${EMBED_BASE_DIR}/ OUTPUT_VARIABLE inputs)
  string(REPLACE ";" "|" listed "${EMBED_FILES}")
  add_custom_command(
    OUTPUT ${EMBED_OUTPUT}
    COMMAND ${CMAKE_COMMAND} -DBASE_DIR=${EMBED_BASE_DIR} "-DFILES=${listed}"
            -DOUTPUT=${EMBED_OUTPUT} -DHEADER=${EMBED_HEADER} -DNAMESPACE=${EMBED_NAMESPACE}
            -DFUNCTION=${EMBED_FUNCTION} -P ${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake
    DEPENDS ${inputs} ${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake
    COMMENT "${EMBED_COMMENT}"
    VERBATIM)
endfunction()
