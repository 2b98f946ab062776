// libFuzzer entry point: any bytes as an STL file through the whole import (size checks, assimp,
// welding, topology checks). Bad input must end in InputError; anything else (a crash, a sanitizer
// report, another exception) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "common/errors.hpp"
#include "mesh/import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // assimp reads files; one per process, so parallel fuzzing jobs do not share it, removed when
  // the fuzzer exits normally (a crash leaves it, beside libFuzzer's own copy of the input).
  static const auto file = [] {
    static const auto path = std::filesystem::temp_directory_path() /
                             ("rbcsim_fuzz_" + std::to_string(getpid()) + ".stl");
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    });
    return path;
  }();
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    rbcsim::mesh::import_mesh(file, {.center = true, .align = true});
  } catch (const rbcsim::InputError&) {
  }
  return 0;
}
