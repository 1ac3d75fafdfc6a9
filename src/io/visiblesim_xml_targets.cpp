// VisibleSim's <targetList>: reading each <target> into a target::Target with errors that name the
// line, the attribute and its value, and printing them back in VisibleSim's layout.
#include <fmt/format.h>

#include <cstring>
#include <map>
#include <string>
#include <utility>

#include "io/number_text.h"
#include "io/visiblesim_xml_detail.h"
#include "world/bounds.h"

namespace datomsim::io::detail {

namespace {

using tinyxml2::XMLElement;

// A value for an error message, cut short when long (CSG texts can be).
std::string brief(std::string_view text) {
  if (text.size() > 60) return std::string(text.substr(0, 57)) + "...";
  return std::string(text);
}

class TargetReader {
 public:
  TargetReader(std::string_view source, const world::Bounds& bounds)
      : source_(source), bounds_(bounds) {}

  Result<target::Target> read(const XMLElement& element) const {
    std::optional<Color> color;
    if (const char* text = element.Attribute("color")) {
      color = parseColor(text);
      if (!color) {
        return attributeError(source_, &element, "color", text,
                              "must be three integers 0..255 r,g,b");
      }
    }
    const char* format = element.Attribute("format");
    if (!format) {
      return errorAt(source_, &element, "target has no format attribute; expected grid or csg");
    }
    if (std::strcmp(format, "grid") == 0) return readGrid(element, color);
    if (std::strcmp(format, "csg") == 0) return readCsg(element, color);
    if (std::strcmp(format, "relativeGrid") == 0) {
      return attributeError(source_, &element, "format", format,
                            "is not supported (VisibleSim's relative grid); expected grid or csg");
    }
    return attributeError(source_, &element, "format", format, "must be grid or csg");
  }

 private:
  Result<target::Target> readGrid(const XMLElement& element, std::optional<Color> color) const {
    std::vector<target::GridCell> cells;
    // The line of each cell read so far, to name both lines of a cell listed twice.
    std::map<geometry::Cell, int> lines;
    for (const XMLElement* child = element.FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      if (std::strcmp(child->Name(), "targetLine") == 0) {
        return errorAt(
            source_, child,
            "<targetLine> is not supported; list the cells as <cell position=\"x,y,z\"/>");
      }
      if (std::strcmp(child->Name(), "cell") != 0) continue;
      const char* position = child->Attribute("position");
      if (!position) return errorAt(source_, child, "cell has no position attribute");
      target::GridCell cell;
      const auto parsed = parseCell(position);
      if (!parsed) {
        return attributeError(source_, child, "position", position, "must be three integers x,y,z");
      }
      cell.cell = *parsed;
      // A cell no module may hold could never be filled: refused as a module's would be.
      if (const std::string outside = bounds_.whyOutside(cell.cell); !outside.empty()) {
        return attributeError(source_, child, "position", position, outside);
      }
      if (const char* text = child->Attribute("color")) {
        cell.color = parseColor(text);
        if (!cell.color) {
          return attributeError(source_, child, "color", text,
                                "must be three integers 0..255 r,g,b");
        }
      }
      if (const auto [at, added] = lines.emplace(cell.cell, child->GetLineNum()); !added) {
        return attributeError(source_, child, "position", position,
                              fmt::format("is already in this target, on line {}", at->second));
      }
      cells.push_back(cell);
    }
    Result<target::Target> target = target::Target::grid(std::move(cells), color);
    if (!target) return errorAt(source_, &element, target.error());
    return target;
  }

  Result<target::Target> readCsg(const XMLElement& element, std::optional<Color> color) const {
    const XMLElement* csg = element.FirstChildElement("csg");
    if (!csg) return errorAt(source_, &element, "target of format csg has no <csg> element");
    if (const XMLElement* second = csg->NextSiblingElement("csg")) {
      return errorAt(source_, second,
                     fmt::format("a second <csg> in one target (the first is on line {}); only one "
                                 "is supported",
                                 csg->GetLineNum()));
    }
    const char* content = csg->Attribute("content");
    if (!content) return errorAt(source_, csg, "csg has no content attribute");

    target::CsgPlacement placement;
    for (const char* name : {"boundingBox", "offset"}) {
      const char* text = csg->Attribute(name);
      if (!text) continue;
      const std::optional<bool> value = parseBool(text);
      if (!value) return attributeError(source_, csg, name, text, "must be true or false");
      (std::strcmp(name, "offset") == 0 ? placement.offset : placement.boundingBox) = *value;
    }
    if (const char* text = csg->Attribute("translate")) {
      placement.translate = parseVector(text);
      if (!placement.translate) {
        return attributeError(source_, csg, "translate", text, "must be three numbers x,y,z");
      }
    }

    Result<target::Target> target = target::Target::csg(content, placement, color);
    if (!target) {
      return attributeError(source_, csg, "content", brief(content).c_str(),
                            "does not parse: " + target.error());
    }
    // A cell no module may hold in any world could never be filled: refused as a grid target's.
    if (const auto cell = target->firstCellNoModuleMayHold()) {
      return attributeError(
          source_, csg, "content", brief(content).c_str(),
          fmt::format("holds cell {}, which {}: no module could fill it", geometry::toString(*cell),
                      world::Bounds{}.whyOutside(*cell)));
    }
    return target;
  }

  std::string_view source_;
  world::Bounds bounds_;
};

std::string colorText(const Color& color) {
  return fmt::format("{},{},{}", color.r, color.g, color.b);
}

}  // namespace

Result<std::vector<target::Target>> readTargetList(const XMLElement& targetList,
                                                   std::string_view source,
                                                   const world::Bounds& bounds) {
  std::vector<target::Target> targets;
  const TargetReader reader(source, bounds);
  for (const XMLElement* element = targetList.FirstChildElement("target"); element;
       element = element->NextSiblingElement("target")) {
    Result<target::Target> target = reader.read(*element);
    if (!target) return Error{target.error()};
    targets.push_back(std::move(target).value());
  }
  return targets;
}

void printTargetList(XmlPrinter& printer, const std::vector<target::Target>& targets) {
  if (targets.empty()) return;
  printer.OpenElement("targetList");
  for (const target::Target& target : targets) {
    printer.OpenElement("target");
    printer.pushAttribute("format", std::string(target::formatName(target.format())).c_str());
    if (target.color()) printer.pushAttribute("color", colorText(*target.color()).c_str());
    for (const target::GridCell& cell : target.gridCells()) {
      printer.OpenElement("cell");
      printer.pushAttribute("position", geometry::toString(cell.cell).c_str());
      if (cell.color) printer.pushAttribute("color", colorText(*cell.color).c_str());
      printer.CloseElement();
    }
    if (target.format() == target::Format::kCsg) {
      // The attributes in the order of VisibleSim's own examples.
      const target::CsgPlacement& placement = target.csgPlacement();
      printer.OpenElement("csg");
      printer.pushAttribute("content", target.csgContent().c_str());
      if (placement.offset) printer.pushAttribute("offset", *placement.offset ? "true" : "false");
      if (placement.boundingBox) {
        printer.pushAttribute("boundingBox", *placement.boundingBox ? "true" : "false");
      }
      if (const auto& v = placement.translate) {
        printer.pushAttribute("translate", fmt::format("{},{},{}", formatNumber(v->x),
                                                       formatNumber(v->y), formatNumber(v->z))
                                               .c_str());
      }
      printer.CloseElement();
    }
    printer.CloseElement();
  }
  printer.CloseElement();
}

}  // namespace datomsim::io::detail
