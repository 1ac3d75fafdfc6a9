// What `actuators show` computes and prints with --json: one actuator design, or a combination
// DEFORMATION+LATCH, derived at a module's size (docs/actuators.md), and where the design files
// are found.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace datomsim::frontend {

// A length with its unit, "1mm", "1cm", "10cm", "0.02m", or a bare number of metres. Throws a
// UsageError naming `option` for anything else, or a length that is not finite and positive.
double parseLength(std::string_view text, std::string_view option);

// Where the shipped designs are looked for beside a binary in `executableDirectory`, in order:
// ../share/datomsim/actuators (the executable or library of an installed prefix, and of a build
// tree, where the build copies them), then ../../share/datomsim/actuators (a library installed
// in a multiarch folder, lib/x86_64-linux-gnu).
std::vector<std::filesystem::path> actuatorDesignCandidates(
    const std::filesystem::path& executableDirectory);

// `explicitDirectory` when given, else the first candidate that exists; a UsageError naming the
// places looked at when none does.
std::filesystem::path actuatorDesignDirectory(const std::filesystem::path& explicitDirectory,
                                              const std::filesystem::path& executableDirectory);

struct ActuatorsShowRequest {
  std::string designs;  // "sma-spring", or "sma-spring+electrostatic"
  double radius = 0.01;
  double thickness = 0.001;
  std::filesystem::path directory;  // the folder of design files
};

// {"radius", "thickness", "module": {quantity: {"value", "unit"}}, "designs": [{"name",
// "model", "kind", "quantities": {...}}]}. Throws a UsageError for unknown designs, a bad design
// file or a size that makes no Datom.
nlohmann::ordered_json actuatorsShowJson(const ActuatorsShowRequest& request);

}  // namespace datomsim::frontend
