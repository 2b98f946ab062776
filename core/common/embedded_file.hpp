// A file compiled into the binary at build time (cmake/embed_files.cmake), so that every command
// runs with its defaults from any directory: share/ (config overlays, reference data; config/
// embedded_share.hpp) and meshes/ (the shipped cell shapes; shapes/shipped_shapes.hpp).
#pragma once

#include <algorithm>
#include <optional>
#include <span>
#include <string_view>

namespace rbcsim {

struct EmbeddedFile {
  std::string_view relative_path;  // below the embedded folder, e.g. "config/discocyte.json"
  std::string_view content;
};

// The content of the file at `relative_path` in `files`, or nullopt.
inline std::optional<std::string_view> find_embedded_file(std::span<const EmbeddedFile> files,
                                                          std::string_view relative_path) {
  const auto file = std::find_if(files.begin(), files.end(), [relative_path](const auto& f) {
    return f.relative_path == relative_path;
  });
  if (file == files.end()) return std::nullopt;
  return file->content;
}

}  // namespace rbcsim
