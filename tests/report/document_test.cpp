#include "report/document.hpp"

#include <gtest/gtest.h>

#include "support/xml_document.hpp"

namespace {

using rbcsim::report::render_html;
using rbcsim::report::Section;
using rbcsim::report::Table;
using rbcsim::testing::parse_xml;
using rbcsim::testing::XmlDocument;

// One section holding one table, rendered and parsed.
XmlDocument page_with(const Table& table) {
  const Section section{"s", "Section", {table}, {}};
  const auto page = parse_xml(render_html("Title", "Subtitle", {section}));
  EXPECT_EQ(page.error, "") << "the page is not well-formed XML";
  return page;
}

TEST(HtmlTable, HeadersBreakAfterEachUnderscore) {
  const auto page = page_with({"", {"max_triangle_area_deviation", "length (µm)"}, {{"1", "2"}}});
  const auto headers = page.find("th");
  ASSERT_EQ(headers.size(), 2u);
  // The key reads whole; a line may break after each of its three underscores, nowhere else.
  EXPECT_EQ(page.elements[headers[0]].text, "max_triangle_area_deviation");
  EXPECT_EQ(page.find("wbr", "", static_cast<long>(headers[0])).size(), 3u);
  EXPECT_EQ(page.find("wbr", "", static_cast<long>(headers[1])).size(), 0u);
}

TEST(HtmlTable, NumbersAlignRightAndSentencesKeepAWidth) {
  const std::string sentence = "steady: the mean length and breadth changed by less than 0.002";
  const auto page = page_with(
      {"", {"rate", "steady", "stop_reason"}, {{"0", "yes", sentence}, {"1000", "—", "stopped"}}});
  const auto cells = page.find("td");
  ASSERT_EQ(cells.size(), 6u);
  // A column of numbers (and "—") is numeric; a text column is not, whatever its cells' length.
  EXPECT_TRUE(page.elements[cells[0]].has_class("num"));
  EXPECT_TRUE(page.elements[cells[3]].has_class("num"));
  EXPECT_FALSE(page.elements[cells[1]].has_class("num"));
  // Only the sentence longer than 40 characters gets the minimum width of prose.
  EXPECT_TRUE(page.elements[cells[2]].has_class("prose"));
  EXPECT_EQ(page.elements[cells[2]].text, sentence);
  EXPECT_FALSE(page.elements[cells[5]].has_class("prose"));
  EXPECT_FALSE(page.elements[cells[1]].has_class("prose"));
}

}  // namespace
