#include "config/embedded_share.hpp"

#include <algorithm>

namespace rbcsim::config {

std::optional<std::string_view> find_embedded_share_file(std::string_view relative_path) {
  const auto files = embedded_share_files();
  const auto file = std::find_if(
      files.begin(), files.end(),
      [relative_path](const EmbeddedFile& f) { return f.relative_path == relative_path; });
  if (file == files.end()) return std::nullopt;
  return file->content;
}

}  // namespace rbcsim::config
