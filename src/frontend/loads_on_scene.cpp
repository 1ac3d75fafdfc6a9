#include "frontend/loads_on_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>

#include <fmt/format.h>

#include "frontend/usage_error.h"
#include "render/value_map.h"

namespace datomsim::frontend {

geometry::Vec3 parseVector(const std::string& option, const std::string& text) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) {
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != part.size() || !std::isfinite(value)) {
      throw UsageError(fmt::format("{} \"{}\" must be three finite numbers x,y,z", option, text));
    }
    values.push_back(value);
  }
  if (values.size() != 3 || text.back() == ',') {
    throw UsageError(fmt::format("{} \"{}\" must be three finite numbers x,y,z", option, text));
  }
  return {values[0], values[1], values[2]};
}

LoadsOutput loadsOnScene(const world::World& world, const LoadsArguments& args) {
  if (args.top < 0) throw UsageError(fmt::format("--top must not be negative, not {}", args.top));
  const auto started = std::chrono::steady_clock::now();
  LoadsOutput output;
  output.model = unwrap(mechanics::buildLoadModel(world, args.parameters));
  mechanics::SolverOptions options;
  options.method = args.method;
  output.solution = unwrap(mechanics::solveLoads(output.model, options));
  output.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  output.tipping = mechanics::checkTipping(output.model);
  // The most loaded latches: the lowest safety factors, ties by order of the beams.
  const std::vector<elastic::LatchLoad>& latches = output.solution.latches;
  std::vector<uint32_t> order(latches.size());
  std::iota(order.begin(), order.end(), 0u);
  const size_t top = std::min(order.size(), size_t(args.top));
  std::partial_sort(order.begin(), order.begin() + top, order.end(), [&](uint32_t a, uint32_t b) {
    return latches[a].safety < latches[b].safety ||
           (latches[a].safety == latches[b].safety && a < b);
  });
  order.resize(top);
  output.mostLoaded = std::move(order);
  return output;
}

namespace {

std::string safetyText(double safety) {
  return std::isinf(safety) ? "none (no load)" : fmt::format("{:.3g}", safety);
}

}  // namespace

std::vector<std::string> loadsSummary(const LoadsOutput& output) {
  const mechanics::LoadModel& model = output.model;
  const mechanics::LoadSolution& solution = output.solution;
  size_t supported = 0;
  for (const mechanics::Node& node : model.nodes) supported += node.supported ? 1 : 0;
  size_t overloaded = 0;
  for (const elastic::LatchLoad& latch : solution.latches) overloaded += latch.safety < 1 ? 1 : 0;
  std::vector<std::string> lines;
  lines.push_back(fmt::format("{} modules ({} on the ground), {} latches, weight {} ({} each)",
                              model.nodes.size(), supported, model.beams.size(),
                              elastic::quantityText(solution.totalWeight, "N"),
                              elastic::quantityText(model.moduleMass * 1000, "g")));
  lines.push_back(fmt::format("solved by {} in {:.3g} s{}", solution.method, output.seconds,
                              solution.iterations > 0
                                  ? fmt::format(" ({} iterations)", solution.iterations)
                                  : std::string{}));
  lines.push_back(fmt::format("latches overloaded (safety below 1): {}", overloaded));
  for (const uint32_t k : output.mostLoaded) {
    const mechanics::Beam& beam = model.beams[k];
    const elastic::LatchLoad& load = solution.latches[k];
    lines.push_back(fmt::format(
        "latch {}-{}: {} (limit {}), {} (limit {}), safety {}", model.nodes[beam.a].module.value,
        model.nodes[beam.b].module.value, elastic::quantityText(geometry::norm(load.moment), "N m"),
        elastic::quantityText(model.parameters.latchMoment, "N m"),
        elastic::quantityText(geometry::norm(load.force), "N"),
        elastic::quantityText(model.parameters.latchForce, "N"), safetyText(load.safety)));
  }
  lines.push_back(output.tipping.tips
                      ? "tips: " + output.tipping.reason
                      : fmt::format("stands: the centre of mass is {} inside its support",
                                    elastic::quantityText(output.tipping.margin, "m")));
  return lines;
}

void addLoadPictureOutputs(const LoadsArguments& args, std::vector<NamedPath>& outputs) {
  if (!args.png.empty()) outputs.push_back({"--png", args.png});
  if (!args.svg.empty()) outputs.push_back({"--svg", args.svg});
}

void writeLoadPictures(const LoadsOutput& output, const LoadsArguments& args,
                       const std::string& sceneName, CommandFiles& files) {
  if (args.png.empty() && args.svg.empty()) return;
  const mechanics::LoadModel& model = output.model;
  render::ValueMapPicture picture;
  const double spacing = 2 * model.parameters.radius;
  for (const mechanics::Node& node : model.nodes)
    picture.centres.push_back(node.position / spacing);
  picture.values = mechanics::worstSafetyByNode(model, output.solution);
  for (const uint32_t k : output.mostLoaded) {
    picture.marked.emplace_back(model.beams[k].a, model.beams[k].b);
  }
  picture.markedLabel = fmt::format("the {} most loaded latches", output.mostLoaded.size());
  picture.bands = render::safetyBands();
  picture.view = args.view == "top" ? render::ValueMapView::kTop : render::ValueMapView::kSide;
  picture.title = fmt::format("Latch safety factors: {} ({} view)", sceneName, args.view);
  const std::vector<std::string> summary = loadsSummary(output);
  picture.lines = {summary.front(),
                   fmt::format("each module coloured by the lowest safety factor of its latches "
                               "(a latch holds {} and {})",
                               elastic::quantityText(model.parameters.latchMoment, "N m"),
                               elastic::quantityText(model.parameters.latchForce, "N")),
                   summary.back()};
  if (!args.png.empty()) {
    files.write(args.png, unwrap(render::renderValueMapPng(picture)));
    files.describe(args.png, "the safety map");
  }
  if (!args.svg.empty()) {
    files.write(args.svg, unwrap(render::renderValueMapSvg(picture)));
    files.describe(args.svg, "the safety map");
  }
}

}  // namespace datomsim::frontend
