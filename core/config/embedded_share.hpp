// Files of share/ compiled into the binary at build time (core/config/CMakeLists.txt runs
// cmake/embed_files.cmake), so every command runs with its defaults from any directory.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "common/embedded_file.hpp"

namespace rbcsim::config {

using rbcsim::EmbeddedFile;

std::span<const EmbeddedFile> embedded_share_files();

// The content of share/<relative_path> as it was when the binary was built, or nullopt.
std::optional<std::string_view> find_embedded_share_file(std::string_view relative_path);

}  // namespace rbcsim::config
