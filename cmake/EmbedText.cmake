# embed_text_files(<target> <namespace> <files...>)
# Turns each text file (a shader) into a C++ source defining
#   extern const char <namespace>::<stem>_<ext>[];   e.g. engine::shaders::lit_frag
# so shaders live as real .vert/.frag files (readable, diffable) and ship inside the binary.
function(embed_text_files target namespace)
  foreach(file ${ARGN})
    get_filename_component(name ${file} NAME)
    string(MAKE_C_IDENTIFIER ${name} symbol)
    set(output ${CMAKE_CURRENT_BINARY_DIR}/embedded/${name}.cpp)
    add_custom_command(
      OUTPUT ${output}
      COMMAND ${CMAKE_COMMAND} -DINPUT=${file} -DOUTPUT=${output} -DSYMBOL=${symbol}
              -DNAMESPACE=${namespace} -P ${PROJECT_SOURCE_DIR}/cmake/EmbedTextFile.cmake
      DEPENDS ${file} ${PROJECT_SOURCE_DIR}/cmake/EmbedTextFile.cmake
      COMMENT "Embedding ${name}")
    target_sources(${target} PRIVATE ${output})
  endforeach()
endfunction()
