#include "render/svg_ids.h"

#include <functional>
#include <map>
#include <string_view>

namespace datomsim::render {

void renumberSurfaceIds(std::string& svg) {
  constexpr std::string_view kName = "surface";
  std::map<std::string, int, std::less<>> numbers;
  std::string out;
  out.reserve(svg.size());
  size_t copied = 0;
  for (size_t at = svg.find(kName); at != std::string::npos; at = svg.find(kName, at + 1)) {
    const bool named = at > 0 && (svg[at - 1] == '"' || svg[at - 1] == '#');
    size_t end = at + kName.size();
    while (end < svg.size() && svg[end] >= '0' && svg[end] <= '9') ++end;
    if (!named || end == at + kName.size()) continue;
    const std::string serial = svg.substr(at + kName.size(), end - at - kName.size());
    const auto known = numbers.emplace(serial, static_cast<int>(numbers.size()) + 1).first;
    out.append(svg, copied, at + kName.size() - copied);
    out += std::to_string(known->second);
    copied = end;
  }
  out.append(svg, copied);
  svg = std::move(out);
}

}  // namespace datomsim::render
