# Writes a C++ source that holds files (of share/, of meshes/) as string literals, so that the
# rbcsim binary runs anywhere with its defaults (docs/architecture.md, "Embedded defaults").
# Run as: cmake -DBASE_DIR=<dir> -DFILES=<a|b|...> -DOUTPUT=<file.cpp> -DHEADER=<include>
#               -DNAMESPACE=<ns> -DFUNCTION=<name> -P embed_files.cmake
# FILES are paths relative to BASE_DIR separated by '|'. Each file becomes a char array with one
# '\x..' element per byte, so any content (quotes, backslashes, non-ASCII) survives unchanged, and
# no string literal exceeds the 65536 characters compilers must support (clang's
# -Woverlength-strings; a level-4 mesh is 256 kB). The source defines
# `std::span<const rbcsim::EmbeddedFile> NAMESPACE::FUNCTION()`, declared in HEADER.
string(REPLACE "|" ";" relative_paths "${FILES}")
set(arrays "")
set(entries "")
set(index 0)
foreach(relative_path IN LISTS relative_paths)
  file(READ "${BASE_DIR}/${relative_path}" bytes HEX)
  string(LENGTH "${bytes}" hex_length)
  math(EXPR size "${hex_length} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," escaped "${bytes}")
  string(APPEND arrays "constexpr char kFile${index}[${size} + 1] = {${escaped}'\\0'};\n")
  string(APPEND entries "    {\"${relative_path}\", {kFile${index}, ${size}}},\n")
  math(EXPR index "${index} + 1")
endforeach()
list(LENGTH relative_paths count)
file(WRITE "${OUTPUT}"
"// Generated at build time by cmake/embed_files.cmake from ${BASE_DIR}: do not edit.
#include \"${HEADER}\"

#include <array>

namespace ${NAMESPACE} {
namespace {

${arrays}
constexpr std::array<rbcsim::EmbeddedFile, ${count}> kEmbeddedFiles{{
${entries}}};

}  // namespace

std::span<const rbcsim::EmbeddedFile> ${FUNCTION}() { return kEmbeddedFiles; }

}  // namespace ${NAMESPACE}
")
