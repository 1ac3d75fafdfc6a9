#include "frontend/geometry_json.h"

#include "datom/dimensions.h"
#include "datom/linkage.h"
#include "frontend/usage_error.h"

namespace datomsim::frontend {

nlohmann::ordered_json geometryJson(double radius, double thickness,
                                    const std::optional<double>& fraction) {
  const datom::Dimensions d = unwrap(datom::dimensionsFor(radius, thickness));
  nlohmann::ordered_json out = {
      {"r", d.radius()},
      {"t", d.thickness()},
      {"c", d.connectorWidth()},
      {"e", d.linkLength()},
      {"a", d.amplitude()},
      {"r_prime", d.correctedRadius()},
      {"c_prime", d.correctedConnectorWidth()},
      {"e_prime", d.correctedLinkLength()},
      {"t_max", d.maxThickness()},
      {"core_edge", d.coreEdge()},
  };
  if (fraction) {
    const datom::Linkage linkage = unwrap(datom::solveLinkage(d, *fraction));
    out["fraction"] = linkage.fraction;
    out["travel"] = linkage.travel;
    out["q0"] = linkage.angles.q0;
    out["q1"] = linkage.angles.q1;
    out["p0"] = linkage.angles.p0;
    out["connector_turn"] = linkage.connectorTurn;
  }
  return out;
}

}  // namespace datomsim::frontend
