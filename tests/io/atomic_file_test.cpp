#include "io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
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

// The processes other than rank 0 of a run across processes write nothing (cli/main.cpp).
TEST(AtomicFile, AProcessThatDoesNotWriteFilesLeavesTheDirectoryAlone) {
  const auto directory = fresh_directory("atomic_silent");
  rbcsim::io::set_process_writes_files(false);
  rbcsim::io::write_text_atomically(directory / "sub" / "result.json", "{}\n");
  const bool wrote = std::filesystem::exists(directory / "sub");
  rbcsim::io::set_process_writes_files(true);
  EXPECT_FALSE(wrote);
  EXPECT_TRUE(rbcsim::io::process_writes_files());
  rbcsim::io::write_text_atomically(directory / "result.json", "{}\n");
  EXPECT_EQ(read_all(directory / "result.json"), "{}\n");
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

// SIGKILL in the middle of a write (the process cannot clean up): the target keeps its old
// content, the half-written bytes are only in a temporary sibling (".result.json.tmp<random>")
// that no reader takes for the result. A plain write to the target would leave "half" there.
TEST(AtomicFile, KilledMidWriteLeavesOldFileAndOnlyAHiddenTemporary) {
  const auto directory = fresh_directory("atomic_killed");
  rbcsim::io::write_text_atomically(directory / "result.json", "old");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    rbcsim::io::write_file_atomically(directory / "result.json", [](std::ostream& out) {
      out << "half" << std::flush;
      std::raise(SIGKILL);
    });
    _exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  EXPECT_EQ(read_all(directory / "result.json"), "old");
  std::size_t temporaries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    const auto name = entry.path().filename().string();
    if (name == "result.json") continue;
    EXPECT_TRUE(name.starts_with(".result.json.tmp")) << name;
    EXPECT_EQ(read_all(entry.path()), "half");
    ++temporaries;
  }
  EXPECT_EQ(temporaries, 1u);
}

}  // namespace
