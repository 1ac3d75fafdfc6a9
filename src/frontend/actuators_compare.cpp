#include "frontend/actuators_compare.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "actuators/combination.h"
#include "actuators/derived_table.h"
#include "actuators/module_demand.h"
#include "datom/dimensions.h"
#include "frontend/actuator_model.h"
#include "frontend/actuators_json.h"
#include "frontend/usage_error.h"

namespace datomsim::frontend {
namespace {

double quantity(const std::vector<actuators::Quantity>& quantities, std::string_view name) {
  for (const actuators::Quantity& q : quantities) {
    if (q.name == name) return q.value;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string number(double value) {
  return std::isnan(value) ? "" : fmt::format("{:.6g}", value);
}

std::string short4(double value) {
  return std::isnan(value) ? "sized" : fmt::format("{:.4g}", value);
}

}  // namespace

std::vector<CompareRow> compareActuators(const io::Scene& scene, const std::string& sceneName,
                                         const RunArguments& run,
                                         const std::vector<std::string>& combinations,
                                         const std::vector<std::string>& sizes) {
  if (combinations.empty()) throw UsageError("--combinations: at least one DEFORMATION+LATCH");
  if (sizes.empty()) throw UsageError("--sizes: at least one size, e.g. 1mm,1cm,10cm");
  // Every value checked before the first run: a bad one costs nothing.
  for (const std::string& combination : combinations) {
    for (const std::string& size : sizes) {
      const double radius = parseLength(size, "--sizes");
      actuatorModel({combination, radius, radius / 10.0, run.actuatorDesigns});
    }
  }
  std::vector<CompareRow> rows;
  for (const std::string& combination : combinations) {
    const actuators::Combination names = unwrap(actuators::parseCombination(combination));
    for (const std::string& size : sizes) {
      RunArguments arguments = run;
      arguments.actuators = combination;
      arguments.size = size;
      const RunOutput output = runOnScene(scene, sceneName, arguments);
      CompareRow row;
      row.combination = names.deformation + "+" + names.latch;
      row.size = size;
      row.radius = parseLength(size, "--sizes");
      row.failure = output.failure.value_or("");
      const sim::Statistics& statistics = output.result.statistics;
      row.motions = statistics.motions;
      row.mostAtOnce = statistics.maxConcurrentMotions;
      row.makespan = double(statistics.lastMotionEnd) / kSecond;
      if (const auto& energy = output.result.energy) {
        row.total = energy->total;
        row.perMotion = row.motions > 0 ? energy->total / double(row.motions) : 0.0;
        row.peakPower = energy->peakPower;
        row.heatedShare = energy->heatedShare();
      }
      const datom::Dimensions dimensions =
          unwrap(datom::dimensionsFor(row.radius, row.radius / 10.0));
      const double weight = actuators::demandOf(dimensions).weight;
      const actuators::Design latch =
          unwrap(actuators::loadDesign(run.actuatorDesigns, names.latch));
      row.latchPerWeight =
          quantity(actuators::derivedQuantities(latch, dimensions), "holding force") / weight;
      const actuators::Design deformation =
          unwrap(actuators::loadDesign(run.actuatorDesigns, names.deformation));
      row.pistonMargin =
          quantity(actuators::derivedQuantities(deformation, dimensions), "force margin");
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

std::string compareCsv(const std::vector<CompareRow>& rows) {
  std::string text =
      "combination,size,radius_m,motions,most_at_once,makespan_s,total_J,energy_per_motion_J,peak_"
      "power_W,"
      "heated_share,latch_force_per_weight,piston_force_margin,failure\n";
  for (const CompareRow& row : rows) {
    text += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{}\n", row.combination, row.size,
                        number(row.radius), row.motions, row.mostAtOnce, number(row.makespan),
                        number(row.total), number(row.perMotion), number(row.peakPower),
                        number(row.heatedShare), number(row.latchPerWeight),
                        number(row.pistonMargin), csvField(row.failure));
  }
  return text;
}

std::string compareMarkdown(const std::vector<CompareRow>& rows) {
  std::string text =
      "| combination | r | motions | at once | makespan (s) | energy (J) | per motion (J) | peak "
      "power (W) "
      "| heated share | latch force / weight | piston force margin |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const CompareRow& row : rows) {
    text += fmt::format(
        "| {} | {} | {}{} | {} | {:.4g} | {:.4g} | {:.4g} | {:.4g} | {:.3f} | {:.4g} | {} |\n",
        row.combination, row.size, row.motions, row.failure.empty() ? "" : " (failed)",
        row.mostAtOnce, row.makespan, row.total, row.perMotion, row.peakPower, row.heatedShare,
        row.latchPerWeight, short4(row.pistonMargin));
  }
  return text;
}

}  // namespace datomsim::frontend
