# Writes a C++ file defining cgtmo::operators::kBuiltinDorfText from the text file IN.
file(READ ${IN} content)
set(delim "cgtmo_dorf")
file(WRITE ${OUT} "// Generated from ${IN} by cmake/embed_text.cmake. Do not edit.\n"
  "namespace cgtmo::operators {\n"
  "extern const char* const kBuiltinDorfText;\n"
  "const char* const kBuiltinDorfText = R\"${delim}(${content})${delim}\";\n"
  "}\n")
