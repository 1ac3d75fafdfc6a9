// Whether two reads of one document agree: both refused with the same message, or both read the
// same modules, bounds and targets.
#pragma once

#include "io/scene.h"

inline bool sameOutcome(const datomsim::Result<datomsim::io::Scene>& a,
                        const datomsim::Result<datomsim::io::Scene>& b) {
  if (a.ok() != b.ok()) return false;
  if (!a.ok()) return a.error() == b.error();
  const auto x = a->world.modules();
  const auto y = b->world.modules();
  if (x.size() != y.size() || !(a->world.bounds() == b->world.bounds())) return false;
  for (size_t i = 0; i < x.size(); ++i) {
    if (x[i].id != y[i].id || x[i].cell != y[i].cell || x[i].orientation != y[i].orientation ||
        x[i].color != y[i].color || x[i].latches != y[i].latches) {
      return false;
    }
  }
  return a->targets == b->targets && a->parameters == b->parameters &&
         a->visibleSim == b->visibleSim && a->blockSize == b->blockSize && a->name == b->name;
}
