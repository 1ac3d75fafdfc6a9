// What the "targets" array of a JSON scene must hold (docs/file-formats.md, "Targets"): each
// target object checked key by key, with errors naming its JSON path and showing the value.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/json_scene_handler.h"

namespace datomsim::io::detail {

namespace {

constexpr std::array<std::string_view, 4> kGridKeys = {"format", "color", "cells", "colors"};
constexpr std::array<std::string_view, 6> kCsgKeys = {"format",      "color",  "content",
                                                      "boundingBox", "offset", "translate"};

template <size_t N>
bool isOneOf(const std::array<std::string_view, N>& keys, std::string_view key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::optional<Color> colorOf(const Json& value) {
  const auto color = threeIntegers(value, 0, 255);
  if (!color) return std::nullopt;
  return Color{uint8_t((*color)[0]), uint8_t((*color)[1]), uint8_t((*color)[2])};
}

}  // namespace

bool SceneHandler::readTargets(const Json& v) {
  if (!v.is_array()) return fail("targets", "expected an array of targets, got " + brief(v));
  for (size_t i = 0; i < v.size(); ++i) {
    std::optional<target::Target> target = readTarget(v[i], fmt::format("targets[{}]", i));
    if (!target) return false;
    scene_.targets.push_back(std::move(*target));
  }
  return true;
}

std::optional<target::Target> SceneHandler::readTarget(const Json& v, const std::string& path) {
  if (!v.is_object()) {
    fail(path, "expected a target object, got " + brief(v));
    return std::nullopt;
  }
  const auto format = v.find("format");
  if (format == v.end()) {
    fail(path, "missing \"format\"");
    return std::nullopt;
  }
  if (!format->is_string() || (*format != "grid" && *format != "csg")) {
    fail(path + ".format", "expected \"grid\" or \"csg\", got " + brief(*format));
    return std::nullopt;
  }
  const bool grid = *format == "grid";
  for (const auto& [key, value] : v.items()) {
    if (!(grid ? isOneOf(kGridKeys, key) : isOneOf(kCsgKeys, key))) {
      fail(path, fmt::format("unknown key \"{}\" for a {} target", key, grid ? "grid" : "csg"));
      return std::nullopt;
    }
  }
  std::optional<Color> color;
  if (const auto found = v.find("color"); found != v.end()) {
    color = colorOf(*found);
    if (!color) {
      fail(path + ".color", "expected three integers 0..255, got " + brief(*found));
      return std::nullopt;
    }
  }
  return grid ? readGridTarget(v, path, color) : readCsgTarget(v, path, color);
}

std::optional<target::Target> SceneHandler::readGridTarget(const Json& v, const std::string& path,
                                                           std::optional<Color> color) {
  const auto cells = v.find("cells");
  if (cells == v.end()) {
    fail(path, "missing \"cells\"");
    return std::nullopt;
  }
  if (!cells->is_array()) {
    fail(path + ".cells", "expected an array of cells [x,y,z], got " + brief(*cells));
    return std::nullopt;
  }
  std::vector<target::GridCell> gridCells(cells->size());
  for (size_t i = 0; i < cells->size(); ++i) {
    const auto cell = threeIntegers((*cells)[i], std::numeric_limits<int32_t>::min(),
                                    std::numeric_limits<int32_t>::max());
    if (!cell) {
      fail(fmt::format("{}.cells[{}]", path, i),
           "expected three integers, got " + brief((*cells)[i]));
      return std::nullopt;
    }
    gridCells[i].cell = {int32_t((*cell)[0]), int32_t((*cell)[1]), int32_t((*cell)[2])};
  }

  // Colours, when given, come one per cell: [r,g,b] or null for a cell without.
  if (const auto colors = v.find("colors"); colors != v.end()) {
    if (!colors->is_array() || colors->size() != cells->size()) {
      fail(path + ".colors", fmt::format("expected an array of {} entries, one per cell, got {}",
                                         cells->size(), brief(*colors)));
      return std::nullopt;
    }
    for (size_t i = 0; i < colors->size(); ++i) {
      const Json& entry = (*colors)[i];
      if (entry.is_null()) continue;
      gridCells[i].color = colorOf(entry);
      if (!gridCells[i].color) {
        fail(fmt::format("{}.colors[{}]", path, i),
             "expected null or three integers 0..255, got " + brief(entry));
        return std::nullopt;
      }
    }
  }

  Result<target::Target> target = target::Target::grid(std::move(gridCells), color);
  if (!target) {
    fail(path + ".cells", target.error());
    return std::nullopt;
  }
  return std::move(target).value();
}

std::optional<target::Target> SceneHandler::readCsgTarget(const Json& v, const std::string& path,
                                                          std::optional<Color> color) {
  const auto content = v.find("content");
  if (content == v.end()) {
    fail(path, "missing \"content\"");
    return std::nullopt;
  }
  if (!content->is_string()) {
    fail(path + ".content", "expected a string, got " + brief(*content));
    return std::nullopt;
  }

  target::CsgPlacement placement;
  for (const char* name : {"boundingBox", "offset"}) {
    const auto found = v.find(name);
    if (found == v.end()) continue;
    if (!found->is_boolean()) {
      fail(path + "." + name, "expected true or false, got " + brief(*found));
      return std::nullopt;
    }
    (std::string_view(name) == "offset" ? placement.offset : placement.boundingBox) =
        found->get<bool>();
  }
  if (const auto found = v.find("translate"); found != v.end()) {
    bool good = found->is_array() && found->size() == 3;
    for (size_t i = 0; good && i < 3; ++i) {
      good = (*found)[i].is_number() && std::isfinite((*found)[i].get<double>());
    }
    if (!good) {
      fail(path + ".translate", "expected three numbers, got " + brief(*found));
      return std::nullopt;
    }
    placement.translate = geometry::Vec3{(*found)[0].get<double>(), (*found)[1].get<double>(),
                                         (*found)[2].get<double>()};
  }

  Result<target::Target> target =
      target::Target::csg(content->get<std::string>(), placement, color);
  if (!target) {
    fail(path + ".content", fmt::format("{}; the content is {}", target.error(), brief(*content)));
    return std::nullopt;
  }
  return std::move(target).value();
}

}  // namespace datomsim::io::detail
