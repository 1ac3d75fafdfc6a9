// The JSON of `loads` (docs/file-formats.md, "Loads"): streamed, since a large scene has millions
// of latches.
#include <cmath>

#include <nlohmann/json.hpp>

#include "frontend/json_stream.h"
#include "frontend/loads_on_scene.h"

namespace datomsim::frontend {

namespace {

nlohmann::ordered_json vectorJson(const geometry::Vec3& v) {
  return nlohmann::ordered_json::array({v.x, v.y, v.z});
}

// A safety factor, null for a latch that carries nothing (infinite).
nlohmann::ordered_json safetyJson(double safety) {
  return std::isinf(safety) ? nlohmann::ordered_json() : nlohmann::ordered_json(safety);
}

void streamLoadsJson(const LoadsOutput& output, JsonObjectStream::Emit emit) {
  const mechanics::LoadModel& model = output.model;
  const mechanics::LoadSolution& solution = output.solution;
  const elastic::LoadParameters& p = model.parameters;
  JsonObjectStream out(std::move(emit));
  out.field("program", "loads");
  out.field("parameters", {{"radius_m", p.radius},
                           {"thickness_m", p.thickness},
                           {"density_kg_m3", p.density},
                           {"solid_fraction", p.solidFraction},
                           {"young_modulus_pa", p.youngModulus},
                           {"poisson_ratio", p.poissonRatio},
                           {"latch_force_n", p.latchForce},
                           {"latch_moment_n_m", p.latchMoment},
                           {"gravity_m_s2", vectorJson(p.gravity)}});
  out.field("modules", model.nodes.size());
  size_t supported = 0;
  for (const mechanics::Node& node : model.nodes) supported += node.supported ? 1 : 0;
  out.field("supported", supported);
  out.field("latches", model.beams.size());
  out.field("module_mass_kg", model.moduleMass);
  out.field("total_weight_n", solution.totalWeight);
  out.field("solver", {{"method", solution.method},
                       {"iterations", solution.iterations},
                       {"relative_residual", solution.residual}});
  const mechanics::Tipping& tipping = output.tipping;
  out.field("tipping", {{"tips", tipping.tips},
                        {"centre_of_mass_m", vectorJson(tipping.centreOfMass)},
                        {"projected_m", {tipping.projected.x, tipping.projected.y}},
                        {"margin_m", tipping.margin},
                        {"reason", tipping.reason}});
  size_t overloaded = 0;
  double worst = INFINITY;
  for (const elastic::LatchLoad& latch : solution.latches) {
    overloaded += latch.safety < 1 ? 1 : 0;
    worst = std::min(worst, latch.safety);
  }
  out.field("overloaded", overloaded);
  out.field("worst_safety", safetyJson(worst));
  out.field("most_loaded", [&] {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const uint32_t k : output.mostLoaded) list.push_back(k);
    return list;
  }());
  // Every latch in the model's order; "most_loaded" indexes this list.
  out.records("loads", model.beams.size(), [&](size_t k) {
    const mechanics::Beam& beam = model.beams[k];
    const elastic::LatchLoad& load = solution.latches[k];
    return nlohmann::ordered_json{{"a", model.nodes[beam.a].module.value},
                                  {"b", model.nodes[beam.b].module.value},
                                  {"force_n", vectorJson(load.force)},
                                  {"moment_n_m", vectorJson(load.moment)},
                                  {"axial_n", load.axialForce},
                                  {"shear_n", load.shearForce},
                                  {"torsion_n_m", load.torsion},
                                  {"bending_n_m", load.bendingMoment},
                                  {"safety", safetyJson(load.safety)}};
  });
  // Every module's displacement, m, in the scene's order of modules.
  out.records("displacements", model.nodes.size(), [&](size_t i) {
    const geometry::Vec3& d = solution.displacement[i];
    return nlohmann::ordered_json{model.nodes[i].module.value, d.x, d.y, d.z};
  });
  out.close();
}

}  // namespace

std::string loadsJson(const LoadsOutput& output) {
  std::string text;
  streamLoadsJson(output, [&](std::string_view piece) { text += piece; });
  return text;
}

Status writeLoadsJson(const LoadsOutput& output, std::FILE* file) {
  FileEmitter emitter{file};
  streamLoadsJson(output, emitter.emit());
  return emitter.status("the loads");
}

}  // namespace datomsim::frontend
