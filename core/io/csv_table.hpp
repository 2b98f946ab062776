// CSV files with a header row (the run directories' tables, the reference data of share/).
// Lines starting with '#' are comments (the reference files' provenance) and blank lines are
// skipped; fields are separated by commas without quoting (no field of ours holds a comma).
// Numbers are written in their shortest round-trip form, so a table reads back exactly.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::io {

class CsvTable {
 public:
  // Throws InputError(source, "line N: ...") for a missing header or a row whose field count
  // differs from the header's.
  static CsvTable parse(std::string_view text, std::string_view source);

  const std::vector<std::string>& header() const { return header_; }
  std::size_t row_count() const { return rows_.size(); }
  bool has_column(std::string_view name) const;
  // The column's fields as numbers. Throws InputError(source, ...) for a missing column or a
  // field that is not a number, naming the line.
  std::vector<double> numbers(std::string_view column) const;

 private:
  std::string source_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> row_lines_;  // the line number of each row, for diagnostics
};

// Reads a file; the path is the source of every diagnostic. Throws InputError if unreadable.
CsvTable read_csv_file(const std::filesystem::path& path);

// Writes a header row and rows of numbers, atomically (atomic_file.hpp). Each row must have one
// value per column (std::invalid_argument otherwise).
void write_csv_file(const std::filesystem::path& path, std::span<const std::string> columns,
                    std::span<const std::vector<double>> rows);

}  // namespace rbcsim::io
