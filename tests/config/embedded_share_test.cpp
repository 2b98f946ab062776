#include "config/embedded_share.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "config/config_sources.hpp"
#include "config/option_table.hpp"

namespace {

using rbcsim::config::find_embedded_share_file;

std::string read_source_file(const std::string& relative_path) {
  std::ifstream stream(std::string(RBCSIM_SOURCE_DIR) + "/" + relative_path, std::ios::binary);
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

TEST(EmbeddedShare, EveryMorphologyHasAValidOverlay) {
  for (const auto& morphology : rbcsim::config::option_table().find("morphology")->choices) {
    const auto relative_path = "config/" + morphology + ".json";
    const auto text = find_embedded_share_file(relative_path);
    ASSERT_TRUE(text) << relative_path << " is not embedded";
    EXPECT_NO_THROW(rbcsim::config::parse_config_text(*text, relative_path)) << relative_path;
  }
}

TEST(EmbeddedShare, EmbeddedCopiesMatchTheSourceTree) {
  const auto files = rbcsim::config::embedded_share_files();
  EXPECT_FALSE(files.empty());
  for (const auto& file : files) {
    EXPECT_EQ(file.content, read_source_file("share/" + std::string(file.relative_path)))
        << file.relative_path << ": rebuild to embed the current share/";
  }
  EXPECT_EQ(find_embedded_share_file("config/no-such-morphology.json"), std::nullopt);
}

}  // namespace
