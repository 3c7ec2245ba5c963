# cmake -DOUT=file.cpp -DSOURCES="a.cl|b.cl" -P embed.cmake
string(REPLACE "|" ";" SOURCES "${SOURCES}")
set(body "// Generated from stdlib/*.cl by embed.cmake. Do not edit.\n#include \"sdfc/stdlib_files.hpp\"\nnamespace sdfc {\nconst std::vector<StdlibFile>& stdlib_files() {\n  static const std::vector<StdlibFile> files = {\n")
foreach(src IN LISTS SOURCES)
  get_filename_component(name ${src} NAME)
  file(READ ${src} text)

  string(APPEND body "    {\"${name}\", R\"sdfc_cl(${text})sdfc_cl\"},\n")
endforeach()
string(APPEND body "  };\n  return files;\n}\n}  // namespace sdfc\n")
file(WRITE ${OUT}.new "${body}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.new ${OUT})
