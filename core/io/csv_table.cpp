#include "io/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"

namespace rbcsim::io {
namespace {

// The fields of one line. A quoted field runs to its closing quote; "" inside it is a quote.
std::vector<std::string> split_fields(std::string_view line, const std::string& source,
                                      std::size_t line_number) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') {
        fields.back() += c;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) {
    throw InputError(source, "line " + std::to_string(line_number) + ": unterminated quote");
  }
  return fields;
}

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// Accepts what std::from_chars reads in full ("1.5", "-2e-19", "nan", "inf") and the JSON words
// true/false, which some writers use for flags such as `converged`.
bool parse_number(std::string_view text, double& value) {
  text = trim(text);
  if (text == "true" || text == "false") {
    value = text == "true" ? 1.0 : 0.0;
    return true;
  }
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && result.ec == std::errc() && result.ptr == text.data() + text.size();
}

}  // namespace

CsvTable CsvTable::parse(std::string_view text, std::string source) {
  CsvTable table;
  table.source_ = std::move(source);
  std::size_t line_number = 0;
  while (!text.empty()) {
    const auto end = text.find('\n');
    const auto line = trim(text.substr(0, end));
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    auto fields = split_fields(line, table.source_, line_number);
    for (auto& field : fields) field = std::string(trim(field));
    if (table.column_names_.empty()) {
      table.column_names_ = std::move(fields);
      continue;
    }
    if (fields.size() != table.column_names_.size()) {
      throw InputError(table.source_, "line " + std::to_string(line_number) + " has " +
                                          std::to_string(fields.size()) + " fields, the header " +
                                          std::to_string(table.column_names_.size()));
    }
    table.rows_.push_back({line_number, std::move(fields)});
  }
  if (table.column_names_.empty()) throw InputError(table.source_, "no header row");
  return table;
}

bool CsvTable::has_column(std::string_view name) const {
  return std::find(column_names_.begin(), column_names_.end(), name) != column_names_.end();
}

std::size_t CsvTable::column_index(std::string_view column_name) const {
  const auto column = std::find(column_names_.begin(), column_names_.end(), column_name);
  if (column == column_names_.end()) {
    throw InputError(source_, "no column " + in_quotes(column_name));
  }
  return static_cast<std::size_t>(column - column_names_.begin());
}

std::vector<std::string> CsvTable::strings(std::string_view column_name) const {
  const auto index = column_index(column_name);
  std::vector<std::string> values;
  values.reserve(rows_.size());
  for (const auto& row : rows_) values.push_back(row.fields[index]);
  return values;
}

std::vector<double> CsvTable::numbers(std::string_view column_name) const {
  const auto index = column_index(column_name);
  std::vector<double> values;
  values.reserve(rows_.size());
  for (const auto& row : rows_) {
    double value = 0;
    if (!parse_number(row.fields[index], value)) {
      throw InputError(source_, "line " + std::to_string(row.line) + ", column " +
                                    in_quotes(column_name) + ": " + in_quotes(row.fields[index]) +
                                    " is not a number");
    }
    values.push_back(value);
  }
  return values;
}

CsvTable read_csv_file(const std::filesystem::path& file) {
  return CsvTable::parse(read_text_file(file), file.string());
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
