#include "io/visiblesim_xml.h"

#include <fmt/format.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <optional>
#include <set>
#include <vector>

#include "io/number_text.h"
#include "io/visiblesim_xml_detail.h"

namespace datomsim::io {

using detail::parseBlockSize;
using detail::parseCell;
using detail::parseColor;
using detail::parseGridSize;
using detail::parseId;
using detail::parseOrientation;
using geometry::Cell;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLError;

namespace {

constexpr Color kDefaultColor{128, 128, 128};

// A readable phrase for tinyxml2's error codes; its own names are kept in parentheses.
const char* describeXmlError(XMLError error) {
  switch (error) {
    case tinyxml2::XML_ERROR_PARSING_ELEMENT:
      return "cannot parse an element (unclosed quote or tag?)";
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
      return "cannot parse an attribute";
    case tinyxml2::XML_ERROR_PARSING_TEXT:
      return "cannot parse text";
    case tinyxml2::XML_ERROR_PARSING_CDATA:
      return "cannot parse a CDATA section";
    case tinyxml2::XML_ERROR_PARSING_COMMENT:
      return "cannot parse a comment";
    case tinyxml2::XML_ERROR_PARSING_DECLARATION:
      return "cannot parse a declaration";
    case tinyxml2::XML_ERROR_PARSING_UNKNOWN:
      return "cannot parse a <!...> construct";
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT:
      return "the document is empty";
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
      return "an element is not closed by its matching end tag";
    case tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED:
      return "elements are nested too deeply";
    default:
      return "cannot parse";
  }
}

// Reads one document; keeps the source name and the line of every block for error messages.
class XmlSceneReader {
 public:
  explicit XmlSceneReader(std::string_view source) : source_(source) {}

  // Reads a document; with `scanned`, its <blockList> has been emptied and these are its blocks,
  // and any problem with them gives an empty error (the caller then reads the whole text).
  Result<Scene> read(std::string_view text, const std::vector<detail::ScannedBlock>* scanned) {
    scanned_ = scanned;
    if (Status characters = detail::checkXmlText(text, source_); !characters) {
      return Error{characters.error()};
    }
    XMLDocument document;
    if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
      return malformed(document);
    }
    const XMLElement* worldElement = document.RootElement();
    if (!worldElement) return Error{fmt::format("{}: missing <world> element", source_)};
    // tinyxml2 reads a second root element as if it were part of the document; XML allows one.
    if (const XMLElement* second = worldElement->NextSiblingElement()) {
      return errorAt(second,
                     fmt::format("a second root element <{}> after <{}> (line {}); a "
                                 "document has one",
                                 second->Name(), worldElement->Name(), worldElement->GetLineNum()));
    }
    if (std::strcmp(worldElement->Name(), "world") != 0) {
      return errorAt(worldElement, fmt::format("the root element is <{}>, expected <world>",
                                               worldElement->Name()));
    }

    Scene scene;
    if (Status status = readWorldAttributes(*worldElement, scene); !status) {
      return Error{status.error()};
    }

    // Viewer settings, the one blockList and the one targetList; anything else is VisibleSim's
    // business.
    const XMLElement* blockList = nullptr;
    const XMLElement* targetList = nullptr;
    for (const XMLElement* child = worldElement->FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      const std::string_view name = child->Name();
      if (name == "camera" && !scene.visibleSim.camera) {
        scene.visibleSim.camera = attributesOf(*child);
      } else if (name == "spotlight" && !scene.visibleSim.spotlight) {
        scene.visibleSim.spotlight = attributesOf(*child);
      } else if (name == "blockList") {
        if (blockList) {
          return errorAt(child, fmt::format("a second <blockList> (the first is on line {}); "
                                            "only one is supported",
                                            blockList->GetLineNum()));
        }
        blockList = child;
      } else if (name == "targetList") {
        if (targetList) {
          return errorAt(child, fmt::format("a second <targetList> (the first is on line {}); "
                                            "only one is supported",
                                            targetList->GetLineNum()));
        }
        targetList = child;
      }
    }
    if (!blockList) return errorAt(worldElement, "<world> has no <blockList>");

    if (Status status = readBlocks(*blockList, scene); !status) return Error{status.error()};
    if (targetList) {
      Result<std::vector<target::Target>> targets =
          detail::readTargetList(*targetList, source_, scene.world.bounds());
      if (!targets) return Error{targets.error()};
      scene.targets = std::move(targets).value();
    }
    scene.world.shrinkToFit();
    scene.world.latchAllNeighbours();
    return scene;
  }

 private:
  Error malformed(const XMLDocument& document) const {
    std::string message = fmt::format("malformed XML: {} ({}", describeXmlError(document.ErrorID()),
                                      document.ErrorName());
    // tinyxml2's own text ends with details such as "XMLElement name=blockList" after the line.
    const std::string_view detail = document.ErrorStr();
    if (const size_t colon = detail.find(": "); colon != std::string_view::npos) {
      message += fmt::format(": {}", detail.substr(colon + 2));
    }
    message += ")";
    if (document.ErrorLineNum() <= 0) return Error{fmt::format("{}: {}", source_, message)};
    return Error{fmt::format("{}:{}: {}", source_, document.ErrorLineNum(), message)};
  }

  Error errorAt(const XMLElement* element, std::string_view message) const {
    return detail::errorAt(source_, element, message);
  }

  Error attributeError(const XMLElement* element, const char* attribute, const char* value,
                       std::string_view rule) const {
    return detail::attributeError(source_, element, attribute, value, rule);
  }

  static AttributeList attributesOf(const XMLElement& element) {
    AttributeList list;
    for (auto* a = element.FirstAttribute(); a; a = a->Next()) {
      list.push_back({a->Name(), a->Value()});
    }
    return list;
  }

  Status readWorldAttributes(const XMLElement& element, Scene& scene) const {
    world::Bounds bounds;
    for (auto* a = element.FirstAttribute(); a; a = a->Next()) {
      const std::string_view name = a->Name();
      if (name == "gridSize") {
        bounds.gridSize = parseGridSize(a->Value());
        if (!bounds.gridSize) {
          return attributeError(&element, "gridSize", a->Value(),
                                "must be three positive integers X,Y,Z");
        }
      } else if (name == "name") {
        scene.name = a->Value();
      } else if (name == "description") {
        scene.description = a->Value();
      } else {
        scene.visibleSim.world.push_back({a->Name(), a->Value()});
      }
    }
    scene.world = world::World(bounds);
    return Ok{};
  }

  Status readBlocks(const XMLElement& blockList, Scene& scene) {
    Color defaultColor = kDefaultColor;
    if (const char* text = blockList.Attribute("blockSize")) {
      const auto size = parseBlockSize(text);
      if (!size) {
        return attributeError(&blockList, "blockSize", text, "must be three positive numbers");
      }
      scene.blockSize = *size;
    }
    // VisibleSim's files do not name the module (its executable does): datomsim says it here,
    // where VisibleSim's reader looks for nothing of that name and opens the file all the same.
    if (const char* text = blockList.Attribute("moduleKind")) {
      const auto kind = world::moduleKindNamed(text);
      if (!kind) {
        return attributeError(&blockList, "moduleKind", text, "must be datom or catom3d");
      }
      scene.moduleKind = *kind;
    }
    if (const char* text = blockList.Attribute("color")) {
      const auto color = parseColor(text);
      if (!color) {
        return attributeError(&blockList, "color", text, "must be three integers 0..255 r,g,b");
      }
      defaultColor = *color;
    }

    world::World& world = scene.world;
    uint32_t placeInFile = 0;
    for (const XMLElement* block = blockList.FirstChildElement("block"); block;
         block = block->NextSiblingElement("block")) {
      ++placeInFile;
      world::Module module;
      module.color = defaultColor;

      const char* position = block->Attribute("position");
      if (!position) return errorAt(block, "block has no position attribute");
      const auto cell = parseCell(position);
      if (!cell) return attributeError(block, "position", position, "must be three integers x,y,z");
      module.cell = *cell;

      if (const char* text = block->Attribute("color")) {
        const auto color = parseColor(text);
        if (!color) {
          return attributeError(block, "color", text, "must be three integers 0..255 r,g,b");
        }
        module.color = *color;
      }
      if (const char* text = block->Attribute("orientation")) {
        const auto orientation = parseOrientation(text);
        if (!orientation) {
          return attributeError(block, "orientation", text, "must be an integer 0..23");
        }
        module.orientation = *orientation;
      }
      const char* idText = block->Attribute("id");
      module.id = ModuleId{placeInFile};
      if (idText) {
        const auto id = parseId(idText);
        if (!id) return attributeError(block, "id", idText, "must be an integer 1..4294967295");
        module.id = ModuleId{*id};
      }

      // Check what World::add would refuse, to name the lines involved.
      if (!world.isInside(module.cell)) {
        return attributeError(block, "position", position, world.bounds().whyOutside(module.cell));
      }
      if (const world::Module* other = world.moduleAt(module.cell)) {
        return attributeError(
            block, "position", position,
            fmt::format("is already occupied by the block on line {}", lineOf(world, other)));
      }
      if (const world::Module* other = world.find(module.id)) {
        if (idText) {
          return attributeError(
              block, "id", idText,
              fmt::format("is already used by the block on line {}", lineOf(world, other)));
        }
        return errorAt(block, fmt::format("block gets id {} from its place in the file, already "
                                          "used by the block on line {}; give it an id attribute",
                                          module.id.value, lineOf(world, other)));
      }
      if (Status added = world.add(module); !added) return errorAt(block, added.error());
      lines_.push_back(block->GetLineNum());
    }
    if (scanned_) {
      world.reserve(world.size() + scanned_->size());
      for (const detail::ScannedBlock& block : *scanned_) {
        world::Module module = block.module;
        ++placeInFile;
        if (!block.hasColor) module.color = defaultColor;
        if (!block.hasId) module.id = ModuleId{placeInFile};
        // Cells are checked against each other once all are in (World::indexCells).
        if (!world.addUnindexed(module).ok()) return Error{""};
      }
      if (world.indexCells()) return Error{""};
    }
    return Ok{};
  }

  // Modules are stored in the order they were added, which is the order of lines_.
  int lineOf(const world::World& world, const world::Module* module) const {
    return lines_[size_t(module - world.modules().data())];
  }

  std::string_view source_;
  std::vector<int> lines_;
  const std::vector<detail::ScannedBlock>* scanned_ = nullptr;
};

}  // namespace

Result<Scene> parseVisibleSimXml(std::string_view text, std::string_view source) {
  if (auto region = detail::scanBlockList(text)) {
    // The document without its blocks, its lines kept where they were.
    std::string skeleton(text.substr(0, region->begin));
    skeleton.append(region->newlines, '\n');
    skeleton.append(text.substr(region->end));
    Result<Scene> scene = XmlSceneReader(source).read(skeleton, &region->blocks);
    if (scene.ok()) return scene;
  }
  return detail::readVisibleSimXmlGeneral(text, source);
}

namespace detail {

Result<Scene> readVisibleSimXmlGeneral(std::string_view text, std::string_view source) {
  return XmlSceneReader(source).read(text, nullptr);
}

}  // namespace detail

}  // namespace datomsim::io
