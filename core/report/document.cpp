#include "report/document.hpp"

#include <algorithm>
#include <charconv>

#include "report/markup.hpp"

namespace rbcsim::report {
namespace {

// Inline, so the page needs nothing but itself. No '<' or '&' in it: the page is also XML.
constexpr std::string_view kStyleSheet = R"(
body { font-family: system-ui, "Segoe UI", Roboto, "DejaVu Sans", sans-serif; color: #1a1a1a;
  line-height: 1.45; max-width: 1320px; margin: 0 auto; padding: 0 1.5rem 3rem; }
h1 { margin-bottom: 0.2rem; }
.subtitle { color: #555555; margin-top: 0; }
nav ul { list-style: none; padding: 0; display: flex; flex-wrap: wrap; gap: 0.4rem 1.2rem; }
section { margin-top: 2rem; border-top: 1px solid #dddddd; }
.table-wrap { overflow-x: auto; }
table { border-collapse: collapse; margin: 0.8rem 0 1.2rem; font-size: 0.88rem; }
caption { caption-side: top; text-align: left; font-weight: 600; padding-bottom: 0.3rem; }
th, td { border: 1px solid #cccccc; padding: 0.2rem 0.55rem; text-align: left; vertical-align: top; }
th { background: #f1f3f5; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
td.prose { min-width: 24em; }
tbody tr:nth-child(even) { background: #fafafa; }
.figures { display: flex; flex-wrap: wrap; gap: 0.5rem 2rem; align-items: flex-start; }
figure { flex: 0 1 620px; margin: 1rem 0; }
figcaption { color: #444444; font-size: 0.88rem; }
svg.plot { width: 100%; height: auto; background: #ffffff; }
details { margin: 0.3rem 0; }
summary { cursor: pointer; }
@media print {
  @page { size: landscape; }
  body { max-width: none; padding: 0; }
  .table-wrap { overflow-x: visible; }
  table { font-size: 0.56rem; }
  th, td { padding: 0.1rem 0.2rem; }
  td.prose { min-width: 10em; }
}
)";

bool is_numeric_cell(std::string_view cell) {
  double value = 0;
  const auto result = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  return !cell.empty() && result.ec == std::errc() && result.ptr == cell.data() + cell.size();
}

// A column is right-aligned when every cell that is not "—" is a number.
bool is_numeric_column(const Table& table, std::size_t column) {
  bool any_number = false;
  for (const auto& row : table.rows) {
    if (row[column] == "—") continue;
    if (!is_numeric_cell(row[column])) return false;
    any_number = true;
  }
  return any_number;
}

// Numbers align right; a sentence (a stop reason, say) gets a minimum width, so that a wide
// table squeezing its column does not stretch the row to a dozen lines.
std::string_view cell_tag(std::string_view cell, bool numeric_column) {
  constexpr std::size_t kProseCharacters = 40;
  if (numeric_column) return "<td class=\"num\">";
  return cell.size() > kProseCharacters ? "<td class=\"prose\">" : "<td>";
}

// A header is often a JSON key ("max_triangle_area_deviation"); a line-break opportunity after
// each underscore lets its column be as narrow as its longest word, not its whole key.
std::string breakable_key(std::string_view header) {
  std::string html;
  for (const char c : escape_xml(header)) {
    html += c;
    if (c == '_') html += "<wbr/>";
  }
  return html;
}

std::string html_table(const Table& table) {
  std::string html = "<div class=\"table-wrap\"><table>\n";
  if (!table.caption.empty())
    html += concat("<caption>", escape_xml(table.caption), "</caption>\n");
  html += "<thead><tr>";
  for (const auto& header : table.headers) html += concat("<th>", breakable_key(header), "</th>");
  html += "</tr></thead>\n<tbody>\n";
  std::vector<bool> numeric;
  for (std::size_t column = 0; column < table.headers.size(); ++column) {
    numeric.push_back(is_numeric_column(table, column));
  }
  for (const auto& row : table.rows) {
    html += "<tr>";
    for (std::size_t column = 0; column < row.size(); ++column) {
      html += concat(cell_tag(row[column], numeric[column]), escape_xml(row[column]), "</td>");
    }
    html += "</tr>\n";
  }
  return html + "</tbody>\n</table></div>\n";
}

struct HtmlBlock {
  std::string operator()(const Paragraph& paragraph) const {
    return concat("<p>", escape_xml(paragraph.text), "</p>\n");
  }
  std::string operator()(const Table& table) const { return html_table(table); }
  std::string operator()(const Figure& figure) const {
    return concat("<figure>\n", figure.svg, "<figcaption>", escape_xml(figure.caption),
                  "</figcaption>\n</figure>\n");
  }
  std::string operator()(const Details& details) const {
    return concat("<details><summary>", escape_xml(details.summary), "</summary>\n",
                  html_table(details.table), "</details>\n");
  }
};

// The blocks in order, each run of consecutive figures in one flex row (side by side when the
// window is wide enough).
std::string html_blocks(const std::vector<Block>& blocks) {
  std::string html;
  bool in_figure_row = false;
  for (const auto& block : blocks) {
    const bool is_figure = std::holds_alternative<Figure>(block);
    if (is_figure != in_figure_row) html += is_figure ? "<div class=\"figures\">\n" : "</div>\n";
    in_figure_row = is_figure;
    html += std::visit(HtmlBlock{}, block);
  }
  if (in_figure_row) html += "</div>\n";
  return html;
}

std::string markdown_row(const std::vector<std::string>& cells) {
  std::string line = "|";
  for (const auto& cell : cells) line += concat(" ", escape_markdown(cell), " |");
  return line + "\n";
}

std::string markdown_table(const Table& table) {
  std::string markdown;
  if (!table.caption.empty()) markdown += concat("**", escape_markdown(table.caption), "**\n\n");
  markdown += markdown_row(table.headers) + "|";
  for (std::size_t column = 0; column < table.headers.size(); ++column) {
    markdown += is_numeric_column(table, column) ? " ---: |" : " --- |";
  }
  markdown += "\n";
  for (const auto& row : table.rows) markdown += markdown_row(row);
  return markdown + "\n";
}

struct MarkdownBlock {
  std::string operator()(const Paragraph& paragraph) const {
    return concat(escape_markdown(paragraph.text), "\n\n");
  }
  std::string operator()(const Table& table) const { return markdown_table(table); }
  std::string operator()(const Figure&) const { return ""; }
  std::string operator()(const Details&) const { return ""; }
};

}  // namespace

Table table_of_objects(std::string caption, std::string label_header,
                       const std::vector<LabelledObject>& objects) {
  std::vector<std::string> keys;
  for (const auto& labelled : objects) {
    for (const auto& [key, value] : labelled.object.items()) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  Table table{std::move(caption), {std::move(label_header)}, {}};
  for (const auto& key : keys) table.headers.push_back(key_title(key));
  for (const auto& labelled : objects) {
    std::vector<std::string> row{labelled.label};
    for (const auto& key : keys) {
      const auto member = labelled.object.find(key);
      row.push_back(member == labelled.object.end() ? "—" : format_cell(*member));
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

std::string render_html(const std::string& title, const std::string& subtitle,
                        const std::vector<Section>& sections) {
  std::string html = concat(
      "<!DOCTYPE html>\n"
      "<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\" xml:lang=\"en\">\n<head>\n"
      "<meta charset=\"utf-8\"/>\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n<title>",
      escape_xml(title), "</title>\n<style>", kStyleSheet,
      "</style>\n</head>\n<body>\n<header>\n<h1>", escape_xml(title),
      "</h1>\n<p class=\"subtitle\">", escape_xml(subtitle), "</p>\n<nav><ul>\n");
  for (const auto& section : sections) {
    html += concat("<li><a href=\"#", escape_xml(section.id), "\">", escape_xml(section.title),
                   "</a></li>\n");
  }
  html += "</ul></nav>\n</header>\n<main>\n";
  for (const auto& section : sections) {
    html += concat("<section id=\"", escape_xml(section.id), "\">\n<h2>", escape_xml(section.title),
                   "</h2>\n");
    html += html_blocks(section.blocks);
    html += "</section>\n";
  }
  return html + "</main>\n</body>\n</html>\n";
}

std::string render_markdown(const std::string& title, const std::string& subtitle,
                            const std::vector<Section>& sections) {
  std::string markdown =
      concat("# ", escape_markdown(title), "\n\n", escape_markdown(subtitle), "\n\n");
  for (const auto& section : sections) {
    markdown += concat("## ", escape_markdown(section.title), "\n\n");
    for (const auto& block : section.blocks) markdown += std::visit(MarkdownBlock{}, block);
  }
  return markdown;
}

}  // namespace rbcsim::report
