// The XML scene reader's fast path: the <block> elements of a <blockList>, read in one pass over
// the text with no element built per block (visiblesim_xml_detail.h).
//
// A 2-million-block scene is 150 MB of XML; as a tinyxml2 document it takes more than a gigabyte.
// The blocks are nearly all of it and all alike, so this scanner reads them directly, and the
// document without them (a few lines) goes through the general reader. It declines, and the
// general reader reads the whole text, on anything it does not expect: a comment or CDATA before
// or among the blocks, another element in the list, an entity or a control character in a value,
// an unknown or repeated attribute, a value that breaks its rule.
#include <optional>
#include <string>
#include <string_view>

#include "io/visiblesim_xml_detail.h"

namespace datomsim::io::detail {

namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\n' || c == '\r' || c == '\t';
}

bool isNameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.' || c == ':';
}

class BlockScanner {
 public:
  explicit BlockScanner(std::string_view text) : text_(text) {}

  std::optional<BlockRegion> scan() {
    if (!findListStart()) return std::nullopt;
    BlockRegion region;
    region.begin = at_;
    for (;;) {
      while (at_ < text_.size() && isSpace(text_[at_])) region.newlines += text_[at_++] == '\n';
      if (constexpr std::string_view kEnd = "</blockList"; text_.substr(at_).starts_with(kEnd)) {
        if (!endTagCloses(at_ + kEnd.size())) return std::nullopt;
        break;
      }
      if (!text_.substr(at_).starts_with("<block") || at_ + 6 >= text_.size() ||
          !(isSpace(text_[at_ + 6]) || text_[at_ + 6] == '/')) {
        return std::nullopt;
      }
      at_ += 6;
      ScannedBlock block;
      if (!attributes(block)) return std::nullopt;
      region.blocks.push_back(block);
    }
    region.end = at_;
    return region;
  }

 private:
  // Whether the end tag whose name ends before `from` is closed as XML says, by spaces and ">":
  // tinyxml2 reads a malformed one such as "</blockList/>" in ways of its own, and what it
  // makes of the text after the blocks must be what it makes of the whole document.
  bool endTagCloses(size_t from) const {
    while (from < text_.size() && isSpace(text_[from])) ++from;
    return from < text_.size() && text_[from] == '>';
  }

  // Moves past the start tag of the <blockList> that is a child of the root element. Before it
  // only tags and text: no comment, CDATA or DTD declaration (a "<blockList" inside one of those
  // would not be an element).
  bool findListStart() {
    int depth = 0;  // of elements open around the text at at_
    bool inTag = false;
    bool endTag = false;
    char quote = 0;
    for (; at_ < text_.size(); ++at_) {
      const char c = text_[at_];
      if (quote) {
        if (c == quote) quote = 0;
      } else if (inTag) {
        if (c == '"' || c == '\'') quote = c;
        if (c == '>') {
          inTag = false;
          if (endTag) {
            --depth;
          } else if (text_[at_ - 1] != '/' && text_[at_ - 1] != '?') {
            ++depth;
          }
        }
      } else if (c == '<') {
        const std::string_view rest = text_.substr(at_);
        if (rest.starts_with("<!")) return false;
        if (depth == 1 && rest.starts_with("<blockList") && rest.size() > 10 &&
            (isSpace(rest[10]) || rest[10] == '>')) {
          break;
        }
        inTag = true;
        endTag = rest.starts_with("</");
      }
    }
    // The start tag's attributes are the general reader's; only its end matters here.
    for (quote = 0; at_ < text_.size(); ++at_) {
      const char c = text_[at_];
      if (quote) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>') {
        if (text_[at_ - 1] == '/') return false;  // <blockList/>: nothing to read fast
        ++at_;
        return true;
      }
    }
    return false;
  }

  // The attributes of a block up to its "/>", parsed as the general reader parses them.
  bool attributes(ScannedBlock& block) {
    bool hasPosition = false, hasOrientation = false;
    for (;;) {
      const size_t spaceStart = at_;
      while (at_ < text_.size() && isSpace(text_[at_])) ++at_;
      if (text_.substr(at_).starts_with("/>")) {
        at_ += 2;
        return hasPosition;
      }
      if (at_ == spaceStart) return false;  // attributes must be apart
      const size_t nameStart = at_;
      while (at_ < text_.size() && isNameChar(text_[at_])) ++at_;
      const std::string_view name = text_.substr(nameStart, at_ - nameStart);
      while (at_ < text_.size() && isSpace(text_[at_])) ++at_;
      if (at_ >= text_.size() || text_[at_] != '=') return false;
      ++at_;
      while (at_ < text_.size() && isSpace(text_[at_])) ++at_;
      if (at_ >= text_.size() || (text_[at_] != '"' && text_[at_] != '\'')) return false;
      const char quote = text_[at_++];
      const size_t valueStart = at_;
      for (; at_ < text_.size() && text_[at_] != quote; ++at_) {
        const char c = text_[at_];
        if (c == '<' || c == '&' || static_cast<unsigned char>(c) < 0x20) return false;
      }
      if (at_ >= text_.size()) return false;
      value_.assign(text_.substr(valueStart, at_ - valueStart));
      ++at_;
      world::Module& module = block.module;
      if (name == "position" && !hasPosition) {
        const auto cell = parseCell(value_.c_str());
        if (!cell) return false;
        module.cell = *cell;
        hasPosition = true;
      } else if (name == "color" && !block.hasColor) {
        const auto color = parseColor(value_.c_str());
        if (!color) return false;
        module.color = *color;
        block.hasColor = true;
      } else if (name == "orientation" && !hasOrientation) {
        const auto orientation = parseOrientation(value_.c_str());
        if (!orientation) return false;
        module.orientation = *orientation;
        hasOrientation = true;
      } else if (name == "id" && !block.hasId) {
        const auto id = parseId(value_.c_str());
        if (!id) return false;
        module.id = ModuleId{*id};
        block.hasId = true;
      } else {
        return false;  // unknown or repeated
      }
    }
  }

  std::string_view text_;
  size_t at_ = 0;
  std::string value_;
};

}  // namespace

std::optional<BlockRegion> scanBlockList(std::string_view text) {
  return BlockScanner(text).scan();
}

}  // namespace datomsim::io::detail
