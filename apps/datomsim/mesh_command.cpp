// `mesh`: one module's parts as a triangle mesh (OBJ, STL or GLB), at rest or deformed.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <optional>

#include "commands.h"
#include "datom/dimensions.h"
#include "datom/parts.h"
#include "export/mesh.h"

namespace datomsim::app {

void addMeshCommand(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    double radius = 0;
    double thickness = 0;
    std::optional<int> piston;
    std::optional<double> fraction;
    std::string out;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "mesh",
      "One Datom's parts as a mesh (.obj, .stl or .glb), at rest or with a piston compressed");
  command
      ->add_option("--radius", args->radius,
                   "Radius r: half the distance between opposite connectors, in the mesh's unit")
      ->required();
  command
      ->add_option("--thickness", args->thickness,
                   "Thickness t of connectors, links and pistons: 0 < t < 0.19859 r")
      ->required();
  command->add_option("--piston", args->piston, "The compressed piston, 0..5 (default: at rest)");
  command->add_option("--fraction", args->fraction,
                      "How far the piston is compressed: 0 (rest) .. 1 (default 1)");
  command->add_option("-o,--out", args->out, "Mesh file: .obj, .stl or .glb")->required();
  addExample(*command, "mesh --radius 1 --thickness 0.1 --piston 4 --fraction 1 -o datom.glb");
  command->callback([args, &reporter] {
    // The output's format first: a wrong extension is the cheapest mistake to report.
    unwrap(exporting::meshFormatOf(args->out));
    CommandFiles files({}, {{"-o", args->out}});
    if (!std::isfinite(args->radius) || args->radius <= 0) {
      throw UsageError(fmt::format("--radius must be a positive number, got {}", args->radius));
    }
    if (!std::isfinite(args->thickness) || args->thickness <= 0) {
      throw UsageError(fmt::format(
          "--thickness must be greater than 0 for a mesh (parts of thickness 0 have no volume), "
          "got {}",
          args->thickness));
    }
    if (args->fraction && !args->piston) {
      throw UsageError("--fraction needs --piston: which piston is compressed?");
    }
    if (args->piston && (*args->piston < 0 || *args->piston > 5)) {
      throw UsageError(fmt::format("--piston must be 0..5, got {}", *args->piston));
    }
    const double fraction = args->fraction.value_or(args->piston ? 1.0 : 0.0);
    if (!std::isfinite(fraction) || fraction < 0 || fraction > 1) {
      throw UsageError(fmt::format("--fraction must be between 0 and 1, got {}", fraction));
    }
    const datom::Dimensions dimensions =
        unwrap(datom::dimensionsFor(args->radius, args->thickness));
    const int piston = args->piston.value_or(geometry::kNoAxis);
    const std::vector<datom::Part> parts = unwrap(datom::partsLayout(dimensions, piston, fraction));
    const exporting::Mesh mesh = exporting::meshOfParts(parts);
    const std::string state =
        piston < 0 ? "at rest" : fmt::format("piston {} compressed to {}", piston, fraction);
    const std::string comment =
        fmt::format("Datom, r = {}, t = {}, {}", args->radius, args->thickness, state);
    files.write("-o", unwrap(exporting::meshBytes(mesh, args->out, comment)));
    const auto [low, high] = mesh.bounds();
    files.describe(
        "-o", fmt::format("{} parts, {} triangles, {:.4g} x {:.4g} x {:.4g}", mesh.groups.size(),
                          mesh.triangleCount(), high.x - low.x, high.y - low.y, high.z - low.z));
    files.commit(reporter);
  });
}

}  // namespace datomsim::app
