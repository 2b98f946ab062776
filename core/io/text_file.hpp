// Reading a whole input file as text, with the diagnostics every reader of rbcsim gives: the
// file's path and what is wrong with it.
#pragma once

#include <filesystem>
#include <string>

namespace rbcsim::io {

// Throws InputError(path, "no such file" | "is a directory" | "is not a regular file") unless
// `file` is a regular file (or a link to one). A device or a pipe is refused: the readers need
// its size, and /dev/null would otherwise read as an empty input.
void require_regular_file(const std::filesystem::path& file);

// require_regular_file, then the contents; InputError(path, "cannot open the file for reading")
// if it cannot be opened.
std::string read_text_file(const std::filesystem::path& file);

}  // namespace rbcsim::io
