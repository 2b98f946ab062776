#include "config/embedded_share.hpp"

namespace rbcsim::config {

std::optional<std::string_view> find_embedded_share_file(std::string_view relative_path) {
  return find_embedded_file(embedded_share_files(), relative_path);
}

}  // namespace rbcsim::config
