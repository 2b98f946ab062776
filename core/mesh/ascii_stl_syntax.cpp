#include "mesh/ascii_stl_syntax.hpp"

#include <cctype>
#include <cstdlib>

#include "common/errors.hpp"

namespace rbcsim::mesh {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// 'text', built by appending (GCC 12 warns falsely, -Wrestrict, about "'" + std::string(...)).
std::string quoted(std::string_view text) {
  std::string result(1, '\'');
  result.append(text);
  result.push_back('\'');
  return result;
}

// Keywords are lower case, as the format defines them and as assimp's reader matches them: a
// keyword it does not recognise ("vertEx") makes it throw half-way and leak (found by fuzzing).
bool is_keyword(std::string_view token, std::string_view keyword) { return token == keyword; }

// Whitespace-separated tokens with the line each starts on.
class Tokens {
 public:
  Tokens(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  // The next token, or an empty view at the end of the text.
  std::string_view next() {
    while (position_ < text_.size() && is_space(text_[position_])) {
      if (text_[position_++] == '\n') ++line_;
    }
    const auto start = position_;
    while (position_ < text_.size() && !is_space(text_[position_])) ++position_;
    return text_.substr(start, position_ - start);
  }

  void skip_line() {
    while (position_ < text_.size() && text_[position_] != '\n') ++position_;
  }

  void expect_keyword(std::string_view keyword) {
    const auto token = next();
    if (!is_keyword(token, keyword)) fail(quoted(keyword), token);
  }

  // On the keyword's line: assimp reads the numbers line by line, and leaked when they were split
  // over two lines (found by fuzzing).
  void expect_numbers(int count, std::string_view after) {
    const auto keyword_line = line_;
    for (int i = 0; i < count; ++i) {
      const std::string token(next());
      char* end = nullptr;
      std::strtod(token.c_str(), &end);
      if (token.empty() || end != token.c_str() + token.size() || line_ != keyword_line) {
        fail(std::to_string(count) + " numbers after " + quoted(after) + " on its line", token);
      }
    }
  }

  [[noreturn]] void fail(const std::string& expected, std::string_view found) const {
    const std::string got =
        found.empty() ? "the end of the file" : "'" + std::string(found.substr(0, 40)) + "'";
    throw InputError(name_, "line " + std::to_string(line_) + ": expected " + expected + ", got " +
                                got + " (ASCII STL)");
  }

 private:
  std::string_view text_;
  const std::string& name_;
  std::size_t position_ = 0;
  std::size_t line_ = 1;
};

}  // namespace

void check_ascii_stl_syntax(std::string_view text, const std::string& name) {
  Tokens tokens(text, name);
  tokens.expect_keyword("solid");
  tokens.skip_line();  // the solid's name
  for (;;) {
    const auto token = tokens.next();
    if (is_keyword(token, "endsolid")) return;
    if (!is_keyword(token, "facet")) tokens.fail("'facet' or 'endsolid'", token);
    tokens.expect_keyword("normal");
    tokens.expect_numbers(3, "normal");
    tokens.expect_keyword("outer");
    tokens.expect_keyword("loop");
    for (int corner = 0; corner < 3; ++corner) {
      tokens.expect_keyword("vertex");
      tokens.expect_numbers(3, "vertex");
    }
    tokens.expect_keyword("endloop");
    tokens.expect_keyword("endfacet");
  }
}

}  // namespace rbcsim::mesh
