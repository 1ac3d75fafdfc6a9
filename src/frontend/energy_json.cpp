#include "frontend/energy_json.h"

#include <fmt/format.h>

namespace datomsim::frontend {
namespace {

double seconds(Time t) {
  return double(t) / kSecond;
}

// Exact: a time is a whole number of microseconds.
std::string secondsText(Time t) {
  return fmt::format("{}{}.{:06}", t < 0 ? "-" : "", std::abs(t) / kSecond, std::abs(t) % kSecond);
}

double perMotion(const sim::EnergyReport& report, uint64_t motions) {
  return motions > 0 ? report.total / double(motions) : 0.0;
}

}  // namespace

nlohmann::ordered_json energyJson(const sim::EnergyReport& report, uint64_t motions) {
  const sim::ActuatorModel& model = report.model;
  nlohmann::ordered_json out;
  out["actuators"] = model.name;
  out["radius_m"] = model.radius;
  out["thickness_m"] = model.thickness;
  out["durations_s"] = {{"compress", seconds(model.compress)},
                        {"release", seconds(model.release)},
                        {"latch", seconds(model.latch)},
                        {"unlatch", seconds(model.unlatch)}};
  out["energy_per_event_J"] = {{"compress", model.compressEnergy},
                               {"release", model.releaseEnergy},
                               {"latch", model.latchEnergy},
                               {"unlatch", model.unlatchEnergy}};
  out["holding_power_per_latch_W"] = model.holdingPower;
  out["total_J"] = report.total;
  out["pistons_J"] = report.pistons;
  out["latching_J"] = report.latching;
  out["holding_J"] = report.holding;
  out["energy_per_motion_J"] = perMotion(report, motions);
  out["compressions"] = report.compressions;
  out["latchings"] = report.latchings;
  out["unlatchings"] = report.unlatchings;
  out["peak_power_W"] = report.peakPower;
  out["peak_power_at_s"] = seconds(report.peakAt);
  out["mean_power_W"] = report.meanPower();
  out["heated_s"] = seconds(report.heated);
  out["cooling_s"] = seconds(report.cooling);
  out["heated_share"] = report.heatedShare();
  nlohmann::ordered_json modules = nlohmann::ordered_json::array();
  for (const sim::ModuleEnergy& module : report.modules) {
    modules.push_back({{"id", module.module.value},
                       {"total_J", module.total()},
                       {"pistons_J", module.pistons},
                       {"latching_J", module.latching},
                       {"holding_J", module.holding},
                       {"compressions", module.compressions},
                       {"heated_s", seconds(module.heated)},
                       {"cooling_s", seconds(module.cooling)}});
  }
  out["modules"] = std::move(modules);
  return out;
}

std::string powerCsv(const sim::EnergyReport& report) {
  std::string text = "time_s,power_W,energy_J\n";
  double energy = 0;
  Time last = 0;
  double watts = 0;
  const auto row = [&](Time time, double power) {
    energy += watts * seconds(time - last);
    last = time;
    watts = power;
    text += fmt::format("{},{:.9g},{:.9g}\n", secondsText(time), power, energy);
  };
  for (const sim::PowerStep& step : report.power) row(step.time, step.watts);
  if (report.power.empty() || report.power.back().time < report.end) row(report.end, watts);
  return text;
}

std::string energySummary(const sim::EnergyReport& report, uint64_t motions) {
  return fmt::format(
      "energy      {} at r = {:g} m: {:.4g} J ({:.4g} J pistons, {:.4g} J latching, {:.4g} J "
      "holding), {:.4g} J per motion\n"
      "  power     peak {:.4g} W at {:.3f} s, mean {:.4g} W\n"
      "  pistons   {} compressions, heated {:.3f} s, cooling {:.3f} s, heated share {:.4f}\n"
      "  latches   {} latchings, {} unlatchings\n",
      report.model.name, report.model.radius, report.total, report.pistons, report.latching,
      report.holding, perMotion(report, motions), report.peakPower, seconds(report.peakAt),
      report.meanPower(), report.compressions, seconds(report.heated), seconds(report.cooling),
      report.heatedShare(), report.latchings, report.unlatchings);
}

}  // namespace datomsim::frontend
