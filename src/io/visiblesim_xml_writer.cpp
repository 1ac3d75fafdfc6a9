// Writing VisibleSim's XML scene files: the layout of VisibleSim's own files, with every text
// checked first so that what is written reads back as the same scene.
#include <fmt/format.h>
#include <tinyxml2.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <string_view>

#include "io/number_text.h"
#include "io/visiblesim_xml.h"
#include "io/visiblesim_xml_detail.h"

namespace datomsim::io {

namespace {
// An XML name as far as we write them: a letter or '_' then letters, digits, '_', '-', '.'.
bool isXmlName(std::string_view name) {
  auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (name.empty() || !letter(name.front())) return false;
  for (const char c : name) {
    if (!letter(c) && !(c >= '0' && c <= '9') && c != '-' && c != '.') return false;
  }
  return true;
}

Status checkAttributes(const AttributeList& list, std::string_view element,
                       const std::set<std::string_view>& reserved) {
  std::set<std::string_view> seen(reserved.begin(), reserved.end());
  for (const Attribute& attribute : list) {
    if (!isXmlName(attribute.name)) {
      return Error{fmt::format("<{}> attribute name \"{}\" is not a valid XML name", element,
                               attribute.name)};
    }
    if (!seen.insert(attribute.name).second) {
      return Error{
          fmt::format("<{}> attribute \"{}\" appears twice or is written by the scene "
                      "itself",
                      element, attribute.name)};
    }
  }
  return Ok{};
}

// A text XML 1.0 can hold: no NUL (tinyxml2 would end the text there) and no other control
// character but tab, line feed and carriage return.
Status checkXmlText(std::string_view text, std::string_view what) {
  for (const char c : text) {
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
      return Error{fmt::format("{} holds the control character U+{:04X}, which XML cannot hold",
                               what, int(c))};
    }
  }
  return Ok{};
}

Status checkWritable(const Scene& scene) {
  if (scene.name) {
    if (Status s = checkXmlText(*scene.name, "the scene's name"); !s) return s;
  }
  if (scene.description) {
    if (Status s = checkXmlText(*scene.description, "the scene's description"); !s) return s;
  }
  for (const AttributeList* list :
       {&scene.visibleSim.world, scene.visibleSim.camera ? &*scene.visibleSim.camera : nullptr,
        scene.visibleSim.spotlight ? &*scene.visibleSim.spotlight : nullptr}) {
    if (!list) continue;
    for (const Attribute& attribute : *list) {
      if (Status s = checkXmlText(attribute.value, "attribute " + attribute.name); !s) return s;
    }
  }
  for (const target::Target& target : scene.targets) {
    if (target.format() != target::Format::kCsg) continue;
    if (Status s = checkXmlText(target.csgContent(), "a CSG target"); !s) return s;
  }
  const VisibleSimView& view = scene.visibleSim;
  if (Status s = checkAttributes(view.world, "world", {"gridSize", "name", "description"}); !s) {
    return s;
  }
  if (view.camera) {
    if (Status s = checkAttributes(*view.camera, "camera", {}); !s) return s;
  }
  if (view.spotlight) {
    if (Status s = checkAttributes(*view.spotlight, "spotlight", {}); !s) return s;
  }
  return Ok{};
}

std::string colorText(const Color& color) {
  return fmt::format("{},{},{}", color.r, color.g, color.b);
}

void printElement(detail::XmlPrinter& printer, const char* name, const AttributeList& list) {
  printer.OpenElement(name);
  for (const Attribute& attribute : list) {
    printer.pushAttribute(attribute.name.c_str(), attribute.value.c_str());
  }
  printer.CloseElement();
}

// The layout follows VisibleSim's own files: declaration, world, viewer settings, blockList,
// targetList.
void printScene(detail::XmlPrinter& printer, const Scene& scene) {
  printer.PushDeclaration("xml version=\"1.0\" standalone=\"no\" ");
  printer.OpenElement("world");
  if (const auto& grid = scene.world.bounds().gridSize) {
    printer.pushAttribute("gridSize", geometry::toString(*grid).c_str());
  }
  for (const Attribute& attribute : scene.visibleSim.world) {
    printer.pushAttribute(attribute.name.c_str(), attribute.value.c_str());
  }
  if (scene.name) printer.pushAttribute("name", scene.name->c_str());
  if (scene.description) printer.pushAttribute("description", scene.description->c_str());
  if (scene.visibleSim.camera) printElement(printer, "camera", *scene.visibleSim.camera);
  if (scene.visibleSim.spotlight) printElement(printer, "spotlight", *scene.visibleSim.spotlight);

  printer.OpenElement("blockList");
  const auto& size = scene.blockSize;
  printer.pushAttribute("blockSize", fmt::format("{},{},{}", formatNumber(size[0]),
                                                 formatNumber(size[1]), formatNumber(size[2]))
                                         .c_str());
  if (scene.moduleKind != world::ModuleKind::kDatom) {
    printer.pushAttribute("moduleKind", std::string(world::toString(scene.moduleKind)).c_str());
  }
  // Ids 1, 2, 3... in order are what a reader assigns anyway; only other ids need writing.
  const auto modules = scene.world.modules();
  bool writeIds = false;
  for (size_t i = 0; i < modules.size() && !writeIds; ++i) writeIds = modules[i].id.value != i + 1;
  for (const world::Module& module : modules) {
    printer.OpenElement("block");
    if (writeIds) printer.pushAttribute("id", std::to_string(module.id.value).c_str());
    printer.pushAttribute("position", geometry::toString(module.cell).c_str());
    printer.pushAttribute("color", colorText(module.color).c_str());
    printer.pushAttribute("orientation", std::to_string(module.orientation.code()).c_str());
    printer.CloseElement();
  }
  printer.CloseElement();
  detail::printTargetList(printer, scene.targets);
  printer.CloseElement();
}

}  // namespace

Result<std::string> toVisibleSimXml(const Scene& scene) {
  if (Status status = checkWritable(scene); !status) return Error{status.error()};
  detail::XmlPrinter printer;
  printScene(printer, scene);
  return std::string(printer.CStr(), size_t(printer.CStrSize() - 1));
}

Status writeVisibleSimXml(const Scene& scene, std::FILE* file) {
  if (Status status = checkWritable(scene); !status) return status;
  detail::XmlPrinter printer(file);
  printScene(printer, scene);
  if (std::ferror(file)) return Error{std::strerror(errno)};
  return Ok{};
}

namespace detail {

void XmlPrinter::pushAttribute(const char* name, const char* value) {
  // The name and the quotes hold none of the three characters (names are checked before).
  inValue_ = true;
  PushAttribute(name, value);
  inValue_ = false;
}

void XmlPrinter::Write(const char* data, size_t size) {
  if (!inValue_) return tinyxml2::XMLPrinter::Write(data, size);
  size_t run = 0;
  for (size_t i = 0; i < size; ++i) {
    if (data[i] != '\t' && data[i] != '\n' && data[i] != '\r') continue;
    tinyxml2::XMLPrinter::Write(data + run, i - run);
    const char* reference = data[i] == '\t' ? "&#9;" : data[i] == '\n' ? "&#10;" : "&#13;";
    tinyxml2::XMLPrinter::Write(reference, std::strlen(reference));
    run = i + 1;
  }
  tinyxml2::XMLPrinter::Write(data + run, size - run);
}

void XmlPrinter::Putc(char c) {
  if (inValue_ && (c == '\t' || c == '\n' || c == '\r')) {
    const char text[] = {c, '\0'};
    return Write(text, 1);
  }
  tinyxml2::XMLPrinter::Putc(c);
}

}  // namespace detail

}  // namespace datomsim::io
