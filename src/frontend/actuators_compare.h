// `actuators compare`: one program on one scene run with each combination of actuators at each
// module size (docs/actuators.md, "The paper's experiment by combination and size"): the
// makespan, the energy, the peak power and the force margins, as a CSV and a markdown table.
#pragma once

#include <string>
#include <vector>

#include "frontend/run_on_scene.h"
#include "io/scene.h"

namespace datomsim::frontend {

struct CompareRow {
  std::string combination;  // full names, deformation first
  std::string size;         // as given, "1cm"
  double radius = 0;        // m
  std::string failure;      // why the run did not do what it was asked; empty when it did
  uint64_t motions = 0;
  int mostAtOnce = 0;         // motions in flight at once, at most
  double makespan = 0;        // s
  double total = 0;           // J
  double perMotion = 0;       // J
  double peakPower = 0;       // W
  double heatedShare = 0;     // the share of the run the pistons compressed (the SMA: heated)
  double latchPerWeight = 0;  // a latch's holding force over one module's weight
  // A piston's force over the force asked (electro-ribbons); the SMA spring is sized to the
  // force asked, which it meets by construction (NaN).
  double pistonMargin = 0;
};

// Runs `run` (its actuators and size set for each) for every combination and size, in the order
// given; a UsageError for a bad combination, size or design file, before any run.
std::vector<CompareRow> compareActuators(const io::Scene& scene, const std::string& sceneName,
                                         const RunArguments& run,
                                         const std::vector<std::string>& combinations,
                                         const std::vector<std::string>& sizes);

// "combination,size,radius_m,motions,most_at_once,makespan_s,total_J,energy_per_motion_J,peak_power_W,
// heated_share,latch_force_per_weight,piston_force_margin,failure"
std::string compareCsv(const std::vector<CompareRow>& rows);
// The same as a markdown table, four significant digits.
std::string compareMarkdown(const std::vector<CompareRow>& rows);

}  // namespace datomsim::frontend
