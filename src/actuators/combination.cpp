#include "actuators/combination.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace datomsim::actuators {
namespace {

// Every name a design answers to: the model's name, and for a latch its short name.
std::vector<std::pair<std::string, std::string>> aliases() {
  std::vector<std::pair<std::string, std::string>> names;
  for (Model model : allModels()) {
    const std::string full(modelName(model));
    names.emplace_back(full, full);
    constexpr std::string_view kSuffix = "-latch";
    if (kindOf(model) == ActuatorKind::kLatch && full.ends_with(kSuffix)) {
      names.emplace_back(full.substr(0, full.size() - kSuffix.size()), full);
    }
  }
  return names;
}

// Levenshtein distance, two rows.
size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> previous(b.size() + 1);
  std::vector<size_t> current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), size_t{0});
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

Model modelOf(const std::string& fullName) {
  for (Model model : allModels()) {
    if (modelName(model) == fullName) return model;
  }
  return Model::kSmaSpring;
}

}  // namespace

std::string closestDesignName(std::string_view name) {
  std::string best;
  size_t bestDistance = SIZE_MAX;
  // The first alias at the least distance wins: the order of allModels() breaks ties.
  for (const auto& [alias, full] : aliases()) {
    const size_t distance = editDistance(name, alias);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = full;
    }
  }
  return best;
}

Result<std::string> designName(std::string_view name) {
  for (const auto& [alias, full] : aliases()) {
    if (alias == name) return full;
  }
  return Error{fmt::format("unknown actuator design \"{}\": did you mean \"{}\"?", name,
                           closestDesignName(name))};
}

Result<Combination> parseCombination(std::string_view text) {
  const size_t plus = text.find('+');
  if (plus == std::string_view::npos || text.find('+', plus + 1) != std::string_view::npos) {
    return Error{
        fmt::format("actuators \"{}\": expected one deformation design and one latch design, "
                    "DEFORMATION+LATCH (e.g. sma-spring+electrostatic)",
                    text)};
  }
  auto first = designName(text.substr(0, plus));
  if (!first) return Error{first.error()};
  auto second = designName(text.substr(plus + 1));
  if (!second) return Error{second.error()};
  const bool firstDeforms = kindOf(modelOf(*first)) == ActuatorKind::kDeformation;
  const bool secondDeforms = kindOf(modelOf(*second)) == ActuatorKind::kDeformation;
  if (firstDeforms == secondDeforms) {
    return Error{
        fmt::format("actuators \"{}\": {} and {} are both {} designs; a module carries "
                    "one deformation design and one latch design",
                    text, *first, *second, firstDeforms ? "deformation" : "latch")};
  }
  return firstDeforms ? Combination{*first, *second} : Combination{*second, *first};
}

Result<Design> loadDesign(const std::filesystem::path& directory, std::string_view name) {
  auto full = designName(name);
  if (!full) return Error{full.error()};
  const std::filesystem::path path = directory / (*full + ".json");
  auto design = readDesign(path);
  if (!design) return design;
  if (modelName(design->model) != *full) {
    return Error{fmt::format("{}: \"model\" is \"{}\", but the file is named for {}", path.string(),
                             modelName(design->model), *full)};
  }
  return design;
}

}  // namespace datomsim::actuators
