// CSV files of the run-directory contract (stretch.csv, shear.csv, capillary_timeseries.csv) and
// of share/reference: a header row with the unit in each column name, then one row per record.
// The experiment commands write them (write_csv_file), `rbcsim report` and the stretch
// comparison read them.
// Lines starting with '#' are provenance comments (share/reference keeps its sources there) and
// are skipped, as are blank lines. Fields may be double-quoted ("a, b", "say ""hi""").
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::io {

class CsvTable {
 public:
  // Throws InputError("SOURCE", "line N: ...") for a missing header or a row whose field count
  // differs from the header's.
  static CsvTable parse(std::string_view text, std::string source);

  const std::vector<std::string>& column_names() const { return column_names_; }
  bool has_column(std::string_view name) const;
  std::size_t row_count() const { return rows_.size(); }

  // The column as numbers. Throws InputError naming the source if the column is missing or a
  // cell is not a number (the message gives the line and the cell).
  std::vector<double> numbers(std::string_view column_name) const;
  // The column's fields as text (quotes removed). Throws InputError if the column is missing.
  std::vector<std::string> strings(std::string_view column_name) const;

 private:
  std::size_t column_index(std::string_view column_name) const;

  struct Row {
    std::size_t line;  // 1-based line in the source, for diagnostics
    std::vector<std::string> fields;
  };

  std::string source_;
  std::vector<std::string> column_names_;
  std::vector<Row> rows_;
};

// read_text_file + CsvTable::parse, the file being the source of every diagnostic.
CsvTable read_csv_file(const std::filesystem::path& file);

// A header row and rows of numbers in their shortest round-trip form (format_number), written
// atomically (atomic_file.hpp), so a table reads back exactly. Each row must have one value per
// column (std::invalid_argument otherwise).
void write_csv_file(const std::filesystem::path& path, std::span<const std::string> columns,
                    std::span<const std::vector<double>> rows);

}  // namespace rbcsim::io
