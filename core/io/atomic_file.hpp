// Every output file of rbcsim is written through here: the content goes to a temporary file in
// the same directory, is flushed, and is renamed over the target only when complete. A run that
// is killed therefore never leaves a half-written result behind (docs/architecture.md).
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace rbcsim::io {

// Calls write(stream) on a temporary file and renames it to `path` on success. If write throws,
// or the stream fails, the temporary file is removed, `path` is untouched and the error propagates.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

void write_text_atomically(const std::filesystem::path& path, std::string_view text);

// Whether this process writes output files (default: yes). In a run across processes every
// process holds the same results and only rank 0 writes them (cli/main.cpp): on the others the two
// functions above return without writing.
void set_process_writes_files(bool writes);
bool process_writes_files();

}  // namespace rbcsim::io
