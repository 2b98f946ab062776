#include "report/markup.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string>

namespace rbcsim::report {
namespace {

constexpr char32_t kReplacementCharacter = 0xFFFD;

struct Decoded {
  char32_t code_point;
  std::size_t length;  // bytes consumed; 1 for an invalid byte
};

// One UTF-8 sequence at text[0]: overlong forms, surrogates and values beyond U+10FFFF are
// invalid and decode as U+FFFD over a single byte, so decoding always advances.
Decoded decode_utf8(std::string_view text) {
  const auto lead = static_cast<unsigned char>(text[0]);
  if (lead < 0x80) return {lead, 1};
  const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 0;
  if (length == 0 || length > text.size()) return {kReplacementCharacter, 1};
  char32_t code_point = lead & (0x7F >> length);
  for (std::size_t i = 1; i < length; ++i) {
    const auto continuation = static_cast<unsigned char>(text[i]);
    if ((continuation & 0xC0) != 0x80) return {kReplacementCharacter, 1};
    code_point = (code_point << 6) | (continuation & 0x3F);
  }
  constexpr std::array<char32_t, 5> kSmallestOfLength{0, 0, 0x80, 0x800, 0x10000};
  const bool overlong = code_point < kSmallestOfLength[length];
  const bool surrogate = code_point >= 0xD800 && code_point <= 0xDFFF;
  if (overlong || surrogate || code_point > 0x10FFFF) return {kReplacementCharacter, 1};
  return {code_point, length};
}

// XML 1.0 §2.2: Char ::= #x9 | #xA | #xD | [#x20-#xD7FF] | [#xE000-#xFFFD] | [#x10000-#x10FFFF]
bool allowed_in_xml(char32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) ||
         (c >= 0xE000 && c <= 0xFFFD) || c >= 0x10000;
}

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// Calls emit(out, code_point) for every character of `text`, invalid UTF-8 as U+FFFD.
template <typename Emit>
std::string transcode(std::string_view text, Emit emit) {
  std::string out;
  out.reserve(text.size());
  while (!text.empty()) {
    const auto decoded = decode_utf8(text);
    emit(out, decoded.code_point);
    text.remove_prefix(decoded.length);
  }
  return out;
}

struct UnitSuffix {
  std::string_view suffix;
  std::string_view unit;
};

// Longer suffixes first: "_m_per_s" and "_m2_per_s" must win over "_per_s" and "_s".
constexpr std::array<UnitSuffix, 16> kUnitSuffixes{{
    {"_uN_per_m", "µN/m"},
    {"_m2_per_s", "m²/s"},
    {"_m_per_s", "m/s"},
    {"_per_s", "1/s"},
    {"_kBT", "kBT"},
    {"_pN", "pN"},
    {"_um2", "µm²"},
    {"_um3", "µm³"},
    {"_um", "µm"},
    {"_deg", "deg"},
    {"_rad", "rad"},
    {"_hz", "Hz"},
    {"_Hz", "Hz"},
    {"_J", "J"},
    {"_s", "s"},
    {"_m", "m"},
}};

}  // namespace

std::string escape_xml(std::string_view text) {
  return transcode(text, [](std::string& out, char32_t c) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        append_utf8(out, allowed_in_xml(c) ? c : kReplacementCharacter);
    }
  });
}

std::string escape_markdown(std::string_view text) {
  constexpr std::string_view kPunctuation = "\\`*_[]<>|~#!";
  return transcode(text, [kPunctuation](std::string& out, char32_t c) {
    if (c < 0x20 || c == 0x7F) {
      out += ' ';  // a table row is one line
      return;
    }
    if (c < 0x80 && kPunctuation.find(static_cast<char>(c)) != std::string_view::npos) out += '\\';
    append_utf8(out, c);
  });
}

std::string format_cell(const nlohmann::json& value) {
  if (value.is_null()) return "—";
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number_integer()) return value.dump();
  if (value.is_number()) return format_significant(value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  if (value.is_array() && std::none_of(value.begin(), value.end(),
                                       [](const auto& item) { return item.is_structured(); })) {
    std::string joined;
    for (const auto& item : value)
      joined.append(joined.empty() ? "" : ", ").append(format_cell(item));
    return joined;
  }
  return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

KeyLabel describe_key(std::string_view key) {
  for (const auto& [suffix, unit] : kUnitSuffixes) {
    if (key.size() > suffix.size() && key.ends_with(suffix)) {
      return {std::string(key.substr(0, key.size() - suffix.size())), std::string(unit)};
    }
  }
  return {std::string(key), ""};
}

std::string key_title(std::string_view key) {
  const auto label = describe_key(key);
  if (label.unit.empty()) return label.name;
  return label.name + " (" + label.unit + ")";
}

}  // namespace rbcsim::report
