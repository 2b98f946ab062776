#include "io/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/atomic_file.hpp"

namespace rbcsim::io {
namespace {

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  for (std::size_t start = 0;;) {
    const auto comma = line.find(',', start);
    fields.emplace_back(trimmed(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace

CsvTable CsvTable::parse(std::string_view text, std::string_view source) {
  CsvTable table;
  table.source_ = source;
  std::size_t line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const auto end = std::min(text.find('\n', start), text.size());
    const auto line = trimmed(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    auto fields = split_fields(line);
    if (table.header_.empty()) {
      table.header_ = std::move(fields);
      continue;
    }
    if (fields.size() != table.header_.size()) {
      throw InputError(table.source_, "line " + std::to_string(line_number) + ": " +
                                          std::to_string(fields.size()) + " fields, the header has " +
                                          std::to_string(table.header_.size()));
    }
    table.rows_.push_back(std::move(fields));
    table.row_lines_.push_back(line_number);
  }
  if (table.header_.empty()) throw InputError(table.source_, "no header row");
  return table;
}

bool CsvTable::has_column(std::string_view name) const {
  return std::find(header_.begin(), header_.end(), name) != header_.end();
}

std::vector<double> CsvTable::numbers(std::string_view column) const {
  const auto found = std::find(header_.begin(), header_.end(), column);
  if (found == header_.end()) throw InputError(source_, "no column " + in_quotes(column));
  const auto index = static_cast<std::size_t>(found - header_.begin());
  std::vector<double> values;
  values.reserve(rows_.size());
  for (std::size_t row = 0; row < rows_.size(); ++row) {
    const auto& field = rows_[row][index];
    double value = 0.0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size()) {
      throw InputError(source_, "line " + std::to_string(row_lines_[row]) + ", column " +
                                    in_quotes(column) + ": " + in_quotes(field) +
                                    " is not a number");
    }
    values.push_back(value);
  }
  return values;
}

CsvTable read_csv_file(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path.string(), "cannot read the file");
  std::stringstream text;
  text << stream.rdbuf();
  return CsvTable::parse(text.str(), path.string());
}

void write_csv_file(const std::filesystem::path& path, std::span<const std::string> columns,
                    std::span<const std::vector<double>> rows) {
  for (const auto& row : rows) {
    if (row.size() != columns.size()) {
      throw std::invalid_argument("CSV row of " + std::to_string(row.size()) + " values for " +
                                  std::to_string(columns.size()) + " columns");
    }
  }
  write_file_atomically(path, [&](std::ostream& out) {
    for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
    out << '\n';
    for (const auto& row : rows) {
      for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << format_number(row[i]);
      out << '\n';
    }
  });
}

}  // namespace rbcsim::io
