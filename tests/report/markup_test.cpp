#include "report/markup.hpp"

#include <gtest/gtest.h>

namespace {

using rbcsim::format_significant;
using rbcsim::report::describe_key;
using rbcsim::report::escape_markdown;
using rbcsim::report::escape_xml;
using rbcsim::report::format_cell;

TEST(EscapeXml, ReplacesTheFiveMarkupCharacters) {
  EXPECT_EQ(escape_xml("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(escape_xml("plain text"), "plain text");
}

TEST(EscapeXml, KeepsValidUtf8AndReplacesWhatXmlCannotCarry) {
  EXPECT_EQ(escape_xml("µm ≤ 𝜏"), "µm ≤ 𝜏");
  EXPECT_EQ(escape_xml("tab\tnewline\n"), "tab\tnewline\n");
  const std::string replacement = "\xEF\xBF\xBD";
  EXPECT_EQ(escape_xml(std::string("a\x01z")), "a" + replacement + "z");  // control character
  EXPECT_EQ(escape_xml("a\xFFz"), "a" + replacement + "z");               // not UTF-8
  EXPECT_EQ(escape_xml("a\xC3"), "a" + replacement);                      // truncated sequence
  EXPECT_EQ(escape_xml("\xC0\xAF"), replacement + replacement);           // overlong '/'
  EXPECT_EQ(escape_xml("\xED\xA0\x80"), replacement + replacement + replacement);  // surrogate
  EXPECT_EQ(escape_xml("\xEF\xBF\xBE"), replacement);  // U+FFFE is not an XML character
}

TEST(EscapeMarkdown, KeepsATableCellOnOneLineWithoutMarkup) {
  EXPECT_EQ(escape_markdown("a|b"), "a\\|b");
  EXPECT_EQ(escape_markdown("two\nlines"), "two lines");
  EXPECT_EQ(escape_markdown("<b>*x*</b>"), "\\<b\\>\\*x\\*\\</b\\>");
  EXPECT_EQ(escape_markdown("k_link [kBT]"), "k\\_link \\[kBT\\]");
  EXPECT_EQ(escape_markdown("µm"), "µm");
}

TEST(FormatSignificant, FourSignificantDigitsInTheShorterNotation) {
  EXPECT_EQ(format_significant(29.85), "29.85");
  EXPECT_EQ(format_significant(29.8549), "29.85");
  EXPECT_EQ(format_significant(0.0012345), "0.001234");
  EXPECT_EQ(format_significant(2.0e-19), "2e-19");
  EXPECT_EQ(format_significant(2000), "2000");
  EXPECT_EQ(format_significant(1.0 / 3.0, 2), "0.33");
  EXPECT_EQ(format_significant(std::nan("")), "nan");
  EXPECT_EQ(format_significant(-INFINITY), "-inf");
}

TEST(FormatCell, EachJsonKind) {
  EXPECT_EQ(format_cell(nlohmann::json(nullptr)), "—");
  EXPECT_EQ(format_cell(true), "yes");
  EXPECT_EQ(format_cell(false), "no");
  EXPECT_EQ(format_cell(13), "13");
  EXPECT_EQ(format_cell(123456789), "123456789");  // integers exactly
  EXPECT_EQ(format_cell(0.123456), "0.1235");
  EXPECT_EQ(format_cell("text"), "text");
  EXPECT_EQ(format_cell(nlohmann::json::array({"link", "bend"})), "link, bend");
  EXPECT_EQ(format_cell(nlohmann::json{{"a", 1}}), "{\"a\":1}");
}

TEST(DescribeKey, ReadsTheUnitSuffix) {
  const std::vector<std::tuple<std::string, std::string, std::string>> cases{
      {"wall_time_s", "wall_time", "s"},
      {"E_s_uN_per_m", "E_s", "µN/m"},
      {"velocity_x_m_per_s", "velocity_x", "m/s"},
      {"kinematic_viscosity_m2_per_s", "kinematic_viscosity", "m²/s"},
      {"shear_rate_per_s", "shear_rate", "1/s"},
      {"k_link_kBT", "k_link", "kBT"},
      {"force_pN", "force", "pN"},
      {"axial_um", "axial", "µm"},
      {"area_um2", "area", "µm²"},
      {"inclination_deg", "inclination", "deg"},
      {"smoothness_rad", "smoothness", "rad"},
      {"tank_treading_hz", "tank_treading", "Hz"},
      {"bending_modulus_J", "bending_modulus", "J"},
      {"deformation_index", "deformation_index", ""},
      {"_s", "_s", ""},  // a suffix alone names nothing
  };
  for (const auto& [key, name, unit] : cases) {
    const auto label = describe_key(key);
    EXPECT_EQ(label.name, name) << key;
    EXPECT_EQ(label.unit, unit) << key;
  }
  EXPECT_EQ(rbcsim::report::key_title("wall_time_s"), "wall_time (s)");
  EXPECT_EQ(rbcsim::report::key_title("poisson_ratio"), "poisson_ratio");
}

}  // namespace
