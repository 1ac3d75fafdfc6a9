// What the XML text must be before tinyxml2 parses it: what tinyxml2 lets through and silently
// mangles, and what would make it slow. One pass over the text, linear in its length.
#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "io/visiblesim_xml_detail.h"

namespace datomsim::io::detail {

namespace {

// Whether a code point is a character XML 1.0 allows (its production Char).
bool isXmlChar(uint64_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) ||
         (c >= 0xE000 && c <= 0xFFFD) || (c >= 0x10000 && c <= 0x10FFFF);
}

// The length of the well-formed UTF-8 sequence starting at `i` (RFC 3629: no overlong form, no
// surrogate, nothing above U+10FFFF) whose code point XML allows; 0 when there is none.
size_t utf8SequenceAt(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  size_t length = 0;
  uint32_t point = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    point = lead & 0x1F;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    point = lead & 0x0F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    point = lead & 0x07;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  for (size_t k = i + 1; k < i + length; ++k) {
    if ((byte(k) & 0xC0) != 0x80) return 0;
    point = (point << 6) | (byte(k) & 0x3F);
  }
  const uint32_t smallest = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
  if (point < smallest || (point >= 0xD800 && point <= 0xDFFF)) return 0;
  return isXmlChar(point) ? length : 0;
}

// Whether `reference` ("&amp;", "&#65;"...) names a character XML allows.
bool isCharacterReference(std::string_view reference) {
  if (reference == "&lt;" || reference == "&gt;" || reference == "&amp;" || reference == "&quot;" ||
      reference == "&apos;") {
    return true;
  }
  if (!reference.starts_with("&#") || !reference.ends_with(';') || reference.size() <= 3) {
    return false;
  }
  const bool hex = reference[2] == 'x';
  const std::string_view digits = reference.substr(hex ? 3 : 2, reference.size() - (hex ? 4 : 3));
  if (digits.empty() || digits.size() > 8) return false;
  uint64_t value = 0;
  for (const char d : digits) {
    const int digit = d >= '0' && d <= '9'          ? d - '0'
                      : hex && d >= 'a' && d <= 'f' ? d - 'a' + 10
                      : hex && d >= 'A' && d <= 'F' ? d - 'A' + 10
                                                    : -1;
    if (digit < 0) return false;
    value = value * (hex ? 16 : 10) + uint64_t(digit);
  }
  return isXmlChar(value);
}

}  // namespace

Status checkXmlText(std::string_view text, std::string_view source) {
  int line = 1;
  auto error = [&](const std::string& what) {
    return Error{fmt::format("{}:{}: malformed XML: {}", source, line, what)};
  };
  // Within a start tag, outside its quoted values: its attributes are counted there.
  bool inTag = false;
  char quote = 0;
  size_t attributes = 0;
  // The length of the character at `k` (1 for ASCII), or 0 when XML allows none there: a byte
  // that starts no UTF-8 character (a file in Latin-1, say), or a control character.
  std::string refusal;
  auto characterAt = [&](size_t k) -> size_t {
    const auto byte = static_cast<unsigned char>(text[k]);
    if (byte >= 0x80) {
      const size_t length = utf8SequenceAt(text, k);
      if (length == 0) {
        refusal = fmt::format(
            "byte 0x{:02X} starts no UTF-8 character XML allows (a file in Latin-1 or another "
            "encoding must be converted to UTF-8)",
            byte);
      }
      return length;
    }
    if (byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r') {
      refusal = fmt::format("control character U+{:04X} is not allowed", int(byte));
      return 0;
    }
    return 1;
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const size_t length = characterAt(i);
    if (length == 0) return error(refusal);
    if (length > 1) {
      i += length - 1;
      continue;
    }
    if (c == '\n') ++line;
    if (inTag) {
      if (quote != 0) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '=' && ++attributes > kMaxXmlAttributes) {
        return error(fmt::format("an element with more than {} attributes (docs/limits.md)",
                                 kMaxXmlAttributes));
      } else if (c == '>') {
        inTag = false;
      }
    }
    if (c == '<' && quote == 0) {
      // Skip what may hold any character up to its end marker, checking its bytes as text.
      bool skipped = false;
      for (const auto& [open, close] :
           {std::pair{"<!--", "-->"}, std::pair{"<![CDATA[", "]]>"}, std::pair{"<?", "?>"}}) {
        if (!text.substr(i).starts_with(open)) continue;
        const size_t end = text.find(close, i);
        if (end == std::string_view::npos) return error(fmt::format("unclosed {}", open));
        for (size_t k = i; k < end; ++k) {
          const size_t inner = characterAt(k);
          if (inner == 0) return error(refusal);
          line += text[k] == '\n';
          k += inner - 1;
        }
        i = end + std::string_view(close).size() - 1;
        skipped = true;
        break;
      }
      if (!skipped) {
        inTag = true;
        attributes = 0;
      }
      continue;
    }
    if (c != '&') continue;
    // The reference: '&', then letters, digits and '#', then ';' when there is one.
    size_t end = i + 1;
    while (end < text.size() && end - i < 12 &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '#')) {
      ++end;
    }
    if (end < text.size() && text[end] == ';') ++end;
    const std::string_view reference = text.substr(i, end - i);
    if (!isCharacterReference(reference)) {
      return error(
          fmt::format("\"{}\" is no character reference: write & as &amp; (references "
                      "are &lt; &gt; &amp; &quot; &apos; and &#N; for an allowed "
                      "character)",
                      reference));
    }
  }
  return Ok{};
}

}  // namespace datomsim::io::detail
