// Reading a whole input file as text, with the diagnostics every reader of rbcsim gives: the
// file's path and what is wrong with it.
#pragma once

#include <filesystem>
#include <string>

namespace rbcsim::io {

// Throws InputError(path, "no such file" | "is a directory" | "cannot open the file for
// reading").
std::string read_text_file(const std::filesystem::path& file);

}  // namespace rbcsim::io
