// The law beyond src/: what the folders built on the layers include, and what every CMake target
// of the project links.
#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "layering.h"

namespace datomsim::testing {

namespace fs = std::filesystem;

namespace {

// The files of a folder and its subfolders whose name ends in `.h` or `.cpp`, or is exactly
// `CMakeLists.txt` when `cmake` is set.
std::vector<fs::path> filesOf(const fs::path& folder, bool cmake) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const std::string extension = entry.path().extension().string();
    const bool wanted = cmake ? entry.path().filename() == "CMakeLists.txt"
                              : extension == ".h" || extension == ".cpp";
    if (entry.is_regular_file() && wanted) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The layers a front end reaches: those of its row and every layer below them.
std::set<std::string> reachedLayers(const FrontEnd& frontEnd,
                                    const std::map<std::string, std::set<std::string>>& closures) {
  std::set<std::string> reached;
  for (const std::string& layer : frontEnd.layers) {
    const std::set<std::string>& below = closures.at(layer);
    reached.insert(below.begin(), below.end());
  }
  return reached;
}

// The names of libraries a CMake file mentions (in link lines, or in the arguments of a function
// that links them), with their line numbers; comments are passed over.
std::vector<std::pair<std::string, int>> librariesNamed(const fs::path& file) {
  static const std::regex kLibrary(R"(\bdatomsim_[a-z0-9_]+)");
  std::vector<std::pair<std::string, int>> named;
  std::ifstream input(file);
  int number = 0;
  for (std::string line; std::getline(input, line);) {
    ++number;
    line = line.substr(0, line.find('#'));
    for (auto it = std::sregex_iterator(line.begin(), line.end(), kLibrary);
         it != std::sregex_iterator(); ++it) {
      named.push_back({it->str(), number});
    }
  }
  return named;
}

}  // namespace

std::vector<std::string> frontEndBreaches(const fs::path& repository,
                                          const std::map<std::string, Layer>& layers,
                                          const std::map<std::string, FrontEnd>& frontEnds) {
  std::vector<std::string> breaches;
  const auto closures = layerClosures(layers);
  for (const auto& [name, frontEnd] : frontEnds) {
    const fs::path folder = repository / name;
    if (!fs::is_directory(folder)) {
      breaches.push_back("front end " + name + " is not a folder of the repository");
      continue;
    }
    const std::set<std::string> reached = reachedLayers(frontEnd, closures);
    for (const fs::path& file : filesOf(folder, false)) {
      for (const Include& include : includesOf(file)) {
        const std::string where = file.string() + ":" + std::to_string(include.line) +
                                  " includes \"" + include.path + "\": ";
        const size_t slash = include.path.find('/');
        const std::string first = include.path.substr(0, slash);
        if (include.path.rfind("../", 0) == 0) {
          breaches.push_back(where + "a path out of " + name + "; include a layer's header");
        } else if (first == "datomsim" && slash != std::string::npos) {
          continue;  // the public API, for everyone
        } else if (slash != std::string::npos && layers.count(first)) {
          if (!reached.count(first)) {
            breaches.push_back(where + name + " does not use layer " + first);
          }
        } else {
          bool found =
              fs::exists(file.parent_path() / include.path) || fs::exists(folder / include.path);
          for (const std::string& used : frontEnd.frontEnds) {
            found = found || fs::exists(repository / used / include.path);
          }
          if (!found) {
            breaches.push_back(where + "neither a header of " + name +
                               " nor of a front end it uses");
          }
        }
      }
    }
  }
  return breaches;
}

std::vector<std::string> linkBreaches(const fs::path& repository,
                                      const std::map<std::string, Layer>& layers,
                                      const std::map<std::string, FrontEnd>& frontEnds) {
  std::vector<std::string> breaches;
  const auto closures = layerClosures(layers);
  std::map<std::string, std::string> layerOfLibrary;
  for (const auto& [name, layer] : layers) layerOfLibrary[layer.library] = name;
  const auto check = [&](const fs::path& file, const std::string& owner,
                         const std::set<std::string>& allowed) {
    for (const auto& [library, line] : librariesNamed(file)) {
      const auto layer = layerOfLibrary.find(library);
      if (layer != layerOfLibrary.end() && !allowed.count(layer->second)) {
        breaches.push_back(file.string() + ":" + std::to_string(line) + " links " + library + ": " +
                           owner + " does not use layer " + layer->second);
      }
    }
  };
  for (const auto& [name, layer] : layers) {
    const fs::path file = repository / "src" / name / "CMakeLists.txt";
    if (fs::exists(file)) check(file, "layer " + name, closures.at(name));
  }
  for (const auto& [name, frontEnd] : frontEnds) {
    if (!fs::is_directory(repository / name)) continue;  // frontEndBreaches says so
    const std::set<std::string> reached = reachedLayers(frontEnd, closures);
    for (const fs::path& file : filesOf(repository / name, true)) check(file, name, reached);
  }
  return breaches;
}

}  // namespace datomsim::testing
