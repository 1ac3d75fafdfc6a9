// Private to the VisibleSim XML reader and writer: the rules of the attribute texts, the errors
// that name the source, line, attribute and value, and the <targetList> part of the format.
#pragma once

#include <tinyxml2.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "geometry/orientation.h"
#include "geometry/vec3.h"
#include "io/scene.h"
#include "target/target.h"
#include "world/bounds.h"
#include "world/module.h"

namespace datomsim::io::detail {

// Attribute texts -> values. Each returns nullopt when the text breaks the rule the caller names.

std::optional<geometry::Cell> parseCell(const char* text);
std::optional<geometry::Cell> parseGridSize(const char* text);
std::optional<Color> parseColor(const char* text);
std::optional<geometry::Orientation> parseOrientation(const char* text);
std::optional<uint32_t> parseId(const char* text);
std::optional<std::array<double, 3>> parseBlockSize(const char* text);
// "true" or "false" in any case, or "1" or "0": what tinyxml2's QueryBoolAttribute, which
// VisibleSim reads them with, accepts.
std::optional<bool> parseBool(const char* text);
// Three finite numbers "x,y,z".
std::optional<geometry::Vec3> parseVector(const char* text);

// The most attributes one element may have: tinyxml2 looks for each attribute among those before
// it, so an element of many attributes would be read in a time quadratic in their number.
inline constexpr size_t kMaxXmlAttributes = 100;

// What tinyxml2 lets through and silently mangles or reads slowly, refused naming the line: bytes
// that are not UTF-8 characters XML allows, control characters, a '&' that starts no reference,
// an element of more than kMaxXmlAttributes attributes (xml_text_check.cpp).
Status checkXmlText(std::string_view text, std::string_view source);

// "source:line: message", the line being the element's.
Error errorAt(std::string_view source, const tinyxml2::XMLElement* element,
              std::string_view message);

// "source:line: block position "1,2" must be three integers x,y,z"
Error attributeError(std::string_view source, const tinyxml2::XMLElement* element,
                     const char* attribute, const char* value, std::string_view rule);

// The fast path (visiblesim_xml_fast.cpp): the blocks of the <blockList> read straight from the
// text, and where they lie in it, so that the rest can go through the general reader.
struct ScannedBlock {
  world::Module module;
  // Whether the file gives them; otherwise the list's colour and the place in the file.
  bool hasColor = false;
  bool hasId = false;
};
struct BlockRegion {
  // The blocks lie in [begin, end) of the text, with this many line breaks among them.
  size_t begin = 0;
  size_t end = 0;
  size_t newlines = 0;
  std::vector<ScannedBlock> blocks;
};
// The blocks, or nullopt when the text holds anything the fast path does not read (the general
// reader then reads it all, and words any error).
std::optional<BlockRegion> scanBlockList(std::string_view text);

// The general reader alone, without the fast path (for tests that compare the two).
Result<Scene> readVisibleSimXmlGeneral(std::string_view text, std::string_view source);

// The targets of a <targetList>, in file order. A grid target's cell that `bounds` would not let a
// module hold is refused, as a module's would be.
Result<std::vector<target::Target>> readTargetList(const tinyxml2::XMLElement& targetList,
                                                   std::string_view source,
                                                   const world::Bounds& bounds);

// tinyxml2's printer, with attribute values that read back as written: tab, line feed and carriage
// return are written as character references, since a reader normalises them (tinyxml2 reads a
// carriage return as a line feed; XML 1.0 all three as spaces). Every attribute goes through
// pushAttribute.
class XmlPrinter : public tinyxml2::XMLPrinter {
 public:
  using tinyxml2::XMLPrinter::XMLPrinter;
  void pushAttribute(const char* name, const char* value);

 protected:
  void Write(const char* data, size_t size) override;
  void Putc(char c) override;

 private:
  bool inValue_ = false;
};

// Prints the <targetList> of the targets; nothing when there are none.
void printTargetList(XmlPrinter& printer, const std::vector<target::Target>& targets);

}  // namespace datomsim::io::detail
