# Script mode helper for EmbedText.cmake: writes one embedded text file.
file(READ ${INPUT} content)
file(WRITE ${OUTPUT}
  "// Generated from ${INPUT}; edit that file instead.\n"
  "namespace ${NAMESPACE} {\n"
  "extern const char ${SYMBOL}[];\n"
  "const char ${SYMBOL}[] = R\"GLSL_EMBED(${content})GLSL_EMBED\";\n"
  "}\n")
