// The report as a document model, rendered twice: to one self-contained XHTML-compatible HTML
// page (tables, inline SVG figures, collapsible details) and to Markdown (paragraphs and tables:
// summary.md carries the headline numbers, not the figures).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

namespace rbcsim::report {

struct Paragraph {
  std::string text;
};

struct Table {
  std::string caption;
  std::vector<std::string> headers;
  std::vector<std::vector<std::string>> rows;  // each as long as headers
};

struct Figure {
  std::string svg;  // rendered by svg::render_*; trusted markup
  std::string caption;
};

// A table shown folded (HTML <details>), left out of Markdown: bulky per-run detail.
struct Details {
  std::string summary;
  Table table;
};

using Block = std::variant<Paragraph, Table, Figure, Details>;

struct Section {
  std::string id;  // HTML anchor
  std::string title;
  std::vector<Block> blocks;
  nlohmann::json summary;  // this section's part of summary.json
};

// A table whose rows are `objects` (a row label and a JSON object each) and whose columns are the
// union of their members in order of first appearance, titled by key_title ("wall_time (s)");
// a member a row lacks shows "—".
struct LabelledObject {
  std::string label;
  nlohmann::json object;
};
Table table_of_objects(std::string caption, std::string label_header,
                       const std::vector<LabelledObject>& objects);

std::string render_html(const std::string& title, const std::string& subtitle,
                        const std::vector<Section>& sections);
std::string render_markdown(const std::string& title, const std::string& subtitle,
                            const std::vector<Section>& sections);

}  // namespace rbcsim::report
