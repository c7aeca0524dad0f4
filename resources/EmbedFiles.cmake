# Generates a C++ source that holds resource files as string literals (run with cmake -P).
# Inputs: OUTPUT (the .cpp to write), BASE (resources/ directory), FILES (paths relative to BASE).
set(body "// Generated from resources/ by EmbedFiles.cmake; do not edit.\n#include \"common/EmbeddedFiles.h\"\n\nnamespace pl {\n\nnamespace {\nconst EmbeddedFile kFiles[] = {\n")
string(REPLACE "," ";" file_list "${FILES}")
foreach(relative IN LISTS file_list)
  file(READ "${BASE}/${relative}" content)
  string(APPEND body "    {\"${relative}\", R\"plembed(${content})plembed\"},\n")
endforeach()
string(APPEND body "};\n} // namespace\n\nstd::span<const EmbeddedFile> embeddedFiles() { return kFiles; }\n\n} // namespace pl\n")
file(WRITE "${OUTPUT}.tmp" "${body}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
