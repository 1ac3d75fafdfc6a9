#include "layering.h"

#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

namespace datomsim::testing {

namespace fs = std::filesystem;

namespace {

std::string trim(const std::string& text) {
  const size_t begin = text.find_first_not_of(" \t`");
  if (begin == std::string::npos) return "";
  const size_t end = text.find_last_not_of(" \t`");
  return text.substr(begin, end - begin + 1);
}

std::set<std::string> nameList(const std::string& cell) {
  std::set<std::string> names;
  std::stringstream parts(cell);
  for (std::string part; std::getline(parts, part, ',');) {
    part = trim(part);
    if (!part.empty() && part != "-") names.insert(part);
  }
  return names;
}

// The layer of a quoted include seen from a file of `layer`: its first folder when that is a
// folder of the tree, else the file's own folder (a sibling header).
std::string layerOfInclude(const fs::path& root, const std::string& layer,
                           const std::string& path) {
  const size_t slash = path.find('/');
  if (slash != std::string::npos && fs::is_directory(root / path.substr(0, slash))) {
    return path.substr(0, slash);
  }
  return layer;
}

fs::path resolve(const fs::path& root, const std::string& layer, const std::string& path) {
  const fs::path fromRoot = root / path;
  if (fs::exists(fromRoot)) return fromRoot;
  return root / layer / path;
}

}  // namespace

std::vector<Include> includesOf(const fs::path& file) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*"([^"]+)\")");
  std::vector<Include> includes;
  std::ifstream input(file);
  int number = 0;
  for (std::string line; std::getline(input, line);) {
    ++number;
    std::smatch match;
    if (std::regex_search(line, match, kInclude)) includes.push_back({match[1], number});
  }
  return includes;
}

std::map<std::string, std::set<std::string>> layerClosures(
    const std::map<std::string, Layer>& layers) {
  std::map<std::string, std::set<std::string>> reached;
  std::function<const std::set<std::string>&(const std::string&)> visit =
      [&](const std::string& name) -> const std::set<std::string>& {
    if (const auto found = reached.find(name); found != reached.end()) return found->second;
    std::set<std::string>& below = reached[name];
    below.insert(name);
    if (const auto layer = layers.find(name); layer != layers.end()) {
      for (const std::string& used : layer->second.uses) {
        const std::set<std::string> usedBelow = visit(used);
        below.insert(usedBelow.begin(), usedBelow.end());
      }
    }
    return reached[name];
  };
  for (const auto& [name, layer] : layers) visit(name);
  return reached;
}

std::map<std::string, Layer> readLayerTable(const std::string& markdown) {
  std::map<std::string, Layer> layers;
  std::stringstream lines(markdown);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("## ", 0) == 0) break;
    if (line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    if (cells.size() < 4) continue;
    Layer layer;
    layer.library = trim(cells[1]);
    layer.uses = nameList(cells[3]);
    if (cells.size() >= 5) layer.never = nameList(cells[4]);
    layers[trim(cells[0])] = layer;
  }
  return layers;
}

std::map<std::string, FrontEnd> readFrontEndTable(const std::string& markdown,
                                                  const std::map<std::string, Layer>& layers) {
  std::map<std::string, FrontEnd> frontEnds;
  std::stringstream lines(markdown);
  bool inSection = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("## ", 0) == 0) inSection = line == "## Front ends";
    if (!inSection || line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    if (cells.size() < 3) continue;
    FrontEnd frontEnd;
    for (const std::string& name : nameList(cells[2])) {
      if (layers.count(name) && name.find('/') == std::string::npos) {
        frontEnd.layers.insert(name);
      } else {
        frontEnd.frontEnds.insert(name);
      }
    }
    frontEnds[trim(cells[0])] = frontEnd;
  }
  return frontEnds;
}

std::vector<std::string> layeringBreaches(const fs::path& root,
                                          const std::map<std::string, Layer>& layers) {
  std::vector<std::string> breaches;
  const auto allowed = layerClosures(layers);
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(root)) {
    if (entry.is_directory()) folders.push_back(entry.path());
  }
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) {
    const std::string layer = folder.filename().string();
    const auto found = layers.find(layer);
    if (found == layers.end()) {
      breaches.push_back(folder.string() + " is not a layer of the table");
      continue;
    }
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string extension = entry.path().extension().string();
      if (extension == ".h" || extension == ".cpp") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      // Direct includes: the own layer or a layer below it.
      for (const Include& include : includesOf(file)) {
        const std::string target = layerOfInclude(root, layer, include.path);
        if (!allowed.at(layer).count(target)) {
          breaches.push_back(file.string() + ":" + std::to_string(include.line) + " includes \"" +
                             include.path + "\": layer " + layer + " does not use " + target);
        }
      }
      // Chains: a file must not reach a layer it must never see, however indirectly.
      if (found->second.never.empty()) continue;
      std::set<fs::path> seen;
      std::function<void(const fs::path&, const std::string&, std::string)> follow =
          [&](const fs::path& at, const std::string& atLayer, std::string chain) {
            for (const Include& include : includesOf(at)) {
              const std::string target = layerOfInclude(root, atLayer, include.path);
              const std::string link = chain + " -> " + include.path;
              if (found->second.never.count(target)) {
                breaches.push_back(file.string() + " reaches layer " + target + ", which layer " +
                                   layer + " must never see:" + link);
                continue;
              }
              const fs::path next = resolve(root, atLayer, include.path);
              if (fs::exists(next) && seen.insert(next).second) follow(next, target, link);
            }
          };
      follow(file, layer, "");
    }
  }
  return breaches;
}

}  // namespace datomsim::testing
