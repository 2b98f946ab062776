#include "io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace {

std::filesystem::path fresh_directory(const std::string& name) {
  auto directory = std::filesystem::temp_directory_path() / ("rbcsim_test_" + name);
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(AtomicFile, WritesCompleteContent) {
  const auto directory = fresh_directory("atomic_ok");
  rbcsim::io::write_text_atomically(directory / "result.json", "{\"ok\": true}\n");
  EXPECT_EQ(read_all(directory / "result.json"), "{\"ok\": true}\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory), {}), 1);
}

TEST(AtomicFile, FailedWriteLeavesOldFileAndNoTemporary) {
  const auto directory = fresh_directory("atomic_fail");
  rbcsim::io::write_text_atomically(directory / "result.json", "old");
  EXPECT_THROW(rbcsim::io::write_file_atomically(directory / "result.json",
                                                 [](std::ostream& out) {
                                                   out << "half";
                                                   throw std::runtime_error("killed");
                                                 }),
               std::runtime_error);
  EXPECT_EQ(read_all(directory / "result.json"), "old");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory), {}), 1);
}

}  // namespace
