#include "report/csv_table.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "report/reference_data.hpp"

namespace {

using rbcsim::report::CsvTable;

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
          rbcsim::report::read_csv_file("/nonexistent/dir/stretch.csv");
        } catch (const rbcsim::InputError& error) {
          EXPECT_STREQ(error.what(), "/nonexistent/dir/stretch.csv: no such file");
          throw;
        }
      },
      rbcsim::InputError);
}

// The embedded Mills et al. (2004) data: 13 forces from 0 to about 193 pN, the cell stretching
// along the pull and narrowing across it, every error bar positive.
TEST(Mills2004Reference, IsEmbeddedWithItsErrorBars) {
  const auto& mills = rbcsim::report::mills2004_stretch();
  ASSERT_EQ(mills.force_pN.size(), 13u);
  EXPECT_EQ(mills.force_pN.front(), 0.0);
  EXPECT_NEAR(mills.force_pN.back(), 193, 1);
  for (const auto* column :
       {&mills.axial_um, &mills.axial_error_um, &mills.transverse_um, &mills.transverse_error_um}) {
    EXPECT_EQ(column->size(), 13u);
  }
  EXPECT_TRUE(std::is_sorted(mills.force_pN.begin(), mills.force_pN.end()));
  EXPECT_GT(mills.axial_um.back(), mills.axial_um.front());
  EXPECT_LT(mills.transverse_um.back(), mills.transverse_um.front());
  for (std::size_t i = 0; i < 13; ++i) {
    EXPECT_GT(mills.axial_error_um[i], 0) << i;
    EXPECT_GT(mills.transverse_error_um[i], 0) << i;
  }
}

}  // namespace
