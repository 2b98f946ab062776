#include "io/csv_table.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "support/scratch_directory.hpp"

namespace {

using rbcsim::io::CsvTable;

std::string parse_error(std::string_view text, const std::string& column = "") {
  try {
    const auto table = CsvTable::parse(text, "data.csv");
    if (!column.empty()) table.numbers(column);
  } catch (const rbcsim::InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(CsvTable, SkipsProvenanceCommentsAndBlankLines) {
  const auto table = CsvTable::parse(
      "# source: somewhere, 2004\n\nforce_pN, axial_um\r\n# a comment between rows\n0,7.7\n"
      "16.4,9.2\n\n",
      "data.csv");
  EXPECT_EQ(table.column_names(), (std::vector<std::string>{"force_pN", "axial_um"}));
  EXPECT_EQ(table.row_count(), 2u);
  EXPECT_EQ(table.numbers("force_pN"), (std::vector<double>{0, 16.4}));
  EXPECT_EQ(table.numbers("axial_um"), (std::vector<double>{7.7, 9.2}));
  EXPECT_TRUE(table.has_column("axial_um"));
  EXPECT_FALSE(table.has_column("transverse_um"));
}

TEST(CsvTable, ReadsQuotedFieldsAndFlags) {
  const auto table = CsvTable::parse(
      "name,value,converged\n\"a, \"\"quoted\"\" name\",+1e-19,true\nplain,-2.5,false\n", "x");
  EXPECT_EQ(table.numbers("value"), (std::vector<double>{1e-19, -2.5}));
  EXPECT_EQ(table.numbers("converged"), (std::vector<double>{1, 0}));
  EXPECT_EQ(table.strings("name"), (std::vector<std::string>{"a, \"quoted\" name", "plain"}));
}

TEST(CsvTable, NamesTheSourceLineAndColumnOfAProblem) {
  EXPECT_EQ(parse_error("# only a comment\n"), "data.csv: no header row");
  EXPECT_EQ(parse_error("a,b\n1,2\n3\n"), "data.csv: line 3 has 1 fields, the header 2");
  EXPECT_EQ(parse_error("a,b\n\"1,2\n"), "data.csv: line 2: unterminated quote");
  EXPECT_EQ(parse_error("a,b\n1,2\n3,x4\n", "b"),
            "data.csv: line 3, column \"b\": \"x4\" is not a number");
  EXPECT_EQ(parse_error("a,b\n1,\n", "b"), "data.csv: line 2, column \"b\": \"\" is not a number");
  EXPECT_EQ(parse_error("a,b\n1,2\n", "c"), "data.csv: no column \"c\"");
}

TEST(CsvTable, MissingFileIsNamed) {
  EXPECT_THROW(
      {
        try {
          rbcsim::io::read_csv_file("/nonexistent/dir/stretch.csv");
        } catch (const rbcsim::InputError& error) {
          EXPECT_STREQ(error.what(), "/nonexistent/dir/stretch.csv: no such file");
          throw;
        }
      },
      rbcsim::InputError);
}

// What write_csv_file writes reads back exactly: the header and every number to the last bit.
TEST(CsvTable, WrittenTablesReadBackExactly) {
  const rbcsim::testing::ScratchDirectory scratch;
  const std::vector<std::string> columns{"force_pN", "axial_um"};
  const std::vector<std::vector<double>> rows{{0.0, 7.82}, {15.987, 0.1 + 0.2}, {1e-300, -2.5}};
  rbcsim::io::write_csv_file(scratch.path() / "t.csv", columns, rows);
  const auto table = rbcsim::io::read_csv_file(scratch.path() / "t.csv");
  EXPECT_EQ(table.column_names(), columns);
  EXPECT_EQ(table.numbers("force_pN"), (std::vector<double>{0.0, 15.987, 1e-300}));
  EXPECT_EQ(table.numbers("axial_um"), (std::vector<double>{7.82, 0.1 + 0.2, -2.5}));
  EXPECT_THROW(rbcsim::io::write_csv_file(scratch.path() / "bad.csv", columns,
                                          std::vector<std::vector<double>>{{1.0}}),
               std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(scratch.path() / "bad.csv"));
}

}  // namespace
