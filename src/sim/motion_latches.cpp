// The latches of the motions in progress: which module holds behind a connector across a hinge,
// which latches a piston moves, and whom breaking them would cut off.
#include <algorithm>

#include "geometry/lattice.h"
#include "sim/motion_executor.h"

namespace datomsim::sim {

using world::Module;

std::optional<MotionExecutor::HingeEnd> MotionExecutor::hingePartner(uint32_t index,
                                                                     int ownConnector) const {
  // Asked for every message: with no motion in flight, the answer needs no look at the module.
  if (activeCount_ == 0 || motionOf_[index] < 0) return std::nullopt;
  const ActiveMotion& active = motions_[motionOf_[index]];
  if (active.mobile == index && ownConnector == active.mobileConnector()) {
    return HingeEnd{active.pivot, active.pivotConnector()};
  }
  if (active.pivot == index && ownConnector == active.pivotConnector()) {
    return HingeEnd{active.mobile, active.mobileConnector()};
  }
  return std::nullopt;
}

uint32_t MotionExecutor::latchedBehind(uint32_t index, int ownConnector) const {
  if (const auto hinge = hingePartner(index, ownConnector)) return hinge->module;
  const Module& module = world_.modules()[index];
  const Module* other = world_.neighbour(module, module.orientation.worldDirection(ownConnector));
  return other ? uint32_t(other - world_.modules().data()) : world::kNoModule;
}

std::vector<world::BrokenLatch> MotionExecutor::latchesMovedBy(uint32_t index,
                                                               int worldAxis) const {
  std::vector<world::BrokenLatch> broken;
  const Module& module = world_.modules()[index];
  for (const int direction : geometry::directionsOfAxis(worldAxis)) {
    const int own = module.orientation.ownConnector(direction);
    if (!(module.latches & (1u << own))) continue;
    const uint32_t other = latchedBehind(index, own);
    if (other == world::kNoModule) continue;
    broken.push_back({index, own});
    if (const auto hinge = hingePartner(index, own)) {
      broken.push_back({other, hinge->connector});
    } else {
      broken.push_back({other, world_.modules()[other].orientation.ownConnector(
                                   geometry::oppositeDirection(direction))});
    }
  }
  return broken;
}

std::vector<uint32_t> MotionExecutor::cutOff(std::vector<world::BrokenLatch> broken) const {
  // Double deformations of motions in progress still to switch will break their second
  // piston's latches: count them as broken already, so that no instant is missed.
  for (const ActiveMotion& active : motions_) {
    if (!active.active || active.resumed) continue;
    for (const motion::Deformation& d : active.plan.deformations) {
      if (d.secondAxis < 0) continue;
      const auto more = latchesMovedBy(*world_.indexOf(d.module), d.secondAxis);
      broken.insert(broken.end(), more.begin(), more.end());
    }
  }
  const std::span<const Module> modules = world_.modules();
  return world::cutOffPiece(
      broken, [&](uint32_t index, int connector) { return latchedBehind(index, connector); },
      [&](uint32_t index) { return modules[index].latches; }, [](uint32_t) { return false; });
}

std::optional<MoveRefusal> MotionExecutor::splitBy(std::vector<world::BrokenLatch> broken) const {
  const std::vector<uint32_t> cut = cutOff(std::move(broken));
  if (cut.empty()) return std::nullopt;
  MoveRefusal refused;
  refused.reason = MoveRefusal::Reason::kWouldDisconnect;
  for (const uint32_t i : cut) refused.cutOff.push_back(world_.modules()[i].id);
  std::sort(refused.cutOff.begin(), refused.cutOff.end());
  refused.text = "the ensemble would fall apart: " + motion::describeCutOff(refused.cutOff);
  return refused;
}

}  // namespace datomsim::sim
