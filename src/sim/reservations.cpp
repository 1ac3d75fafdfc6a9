#include "sim/reservations.h"

#include <fmt/format.h>

#include <algorithm>

#include "world/cell_index.h"

namespace datomsim::sim {

std::string untilText(Time until) {
  return fmt::format("until {:g} s", double(until) / kSecond);
}

Claim claimOf(const world::World& world, const motion::MotionModel& model,
              const motion::Motion& motion, uint32_t mobileIndex) {
  Claim claim;
  claim.mobile = mobileIndex;
  claim.pivot = *world.indexOf(motion.pivot);
  claim.cells = model.cellsHeld(world, motion);
  for (const motion::Deformation& d : motion.deformations) {
    claim.helpers.push_back({*world.indexOf(d.module), d.firstAxis, d.secondAxis >= 0});
  }
  return claim;
}

std::optional<Reservations::Holder> Reservations::cellHolder(const geometry::Cell& cell) const {
  const auto found = cells_.find(world::packCell(cell));
  if (found == cells_.end()) return std::nullopt;
  return found->second;
}

std::optional<Reservations::Holder> Reservations::holderOf(uint32_t module) const {
  const auto found = modules_.find(module);
  if (found == modules_.end()) return std::nullopt;
  return found->second.holders.front();
}

std::optional<std::pair<Reservations::Holder, std::string_view>> Reservations::holdOf(
    uint32_t module) const {
  const auto found = modules_.find(module);
  if (found == modules_.end()) return std::nullopt;
  const Role role = found->second.role;
  return std::pair{found->second.holders.front(), role == Role::kMobile  ? "mobile"
                                                  : role == Role::kPivot ? "pivot"
                                                                         : "blocking module"};
}

std::optional<Reservations::Holder> Reservations::helperHolder(uint32_t module) const {
  const auto found = modules_.find(module);
  if (found == modules_.end() || found->second.role != Role::kHelper) return std::nullopt;
  // The one that holds it longest: the piston may go only when every sharer is done.
  return *std::max_element(found->second.holders.begin(), found->second.holders.end(),
                           [](const Holder& a, const Holder& b) { return a.until < b.until; });
}

std::optional<MoveRefusal> Reservations::conflict(const world::World& world,
                                                  const Claim& claim) const {
  auto refusal = [](MoveRefusal::Reason reason, const Holder& holder, std::string text) {
    MoveRefusal refused;
    refused.reason = reason;
    refused.holder = holder.mobile;
    refused.until = holder.until;
    refused.text = std::move(text);
    return refused;
  };
  auto roleName = [](Role role) {
    return role == Role::kMobile ? "mobile" : role == Role::kPivot ? "pivot" : "blocking module";
  };
  for (const geometry::Cell& cell : claim.cells) {
    if (const auto holder = cellHolder(cell)) {
      MoveRefusal refused = refusal(
          MoveRefusal::Reason::kCellReserved, *holder,
          fmt::format("cell {} is reserved by the motion of module {} ({})",
                      geometry::toString(cell), holder->mobile.value, untilText(holder->until)));
      refused.cell = cell;
      return refused;
    }
  }
  // The mobile and the pivot serve this motion alone.
  for (const uint32_t index : {claim.mobile, claim.pivot}) {
    const auto found = modules_.find(index);
    if (found == modules_.end()) continue;
    const Holder& holder = found->second.holders.front();
    const world::Module& module = world.modules()[index];
    MoveRefusal refused = refusal(
        MoveRefusal::Reason::kModuleBusy, holder,
        fmt::format("{} {} is the {} of the motion of module {} ({})",
                    index == claim.pivot ? "pivot" : "module", module.id.value,
                    roleName(found->second.role), holder.mobile.value, untilText(holder.until)));
    refused.module = module.id;
    refused.cell = module.cell;
    return refused;
  }
  // A helper is shared only for the same single axis.
  for (const Claim::Helper& helper : claim.helpers) {
    const auto found = modules_.find(helper.module);
    if (found == modules_.end()) continue;
    const ModuleHold& hold = found->second;
    const Holder& holder = hold.holders.front();
    const world::Module& module = world.modules()[helper.module];
    std::string why;
    if (hold.role != Role::kHelper) {
      why = fmt::format("module {} in cell {} is the {} of the motion of module {} ({})",
                        module.id.value, geometry::toString(module.cell), roleName(hold.role),
                        holder.mobile.value, untilText(holder.until));
    } else if (hold.axis != helper.axis || hold.double_ || helper.double_) {
      why = fmt::format(
          "module {} in cell {} compresses its piston along axis {}{} for the motion of module "
          "{} ({}); this motion needs axis {}{}",
          module.id.value, geometry::toString(module.cell), hold.axis,
          hold.double_ ? " then another" : "", holder.mobile.value, untilText(holder.until),
          helper.axis, helper.double_ ? " then another" : "");
    } else {
      continue;
    }
    MoveRefusal refused = refusal(MoveRefusal::Reason::kModuleBusy, holder, std::move(why));
    refused.module = module.id;
    refused.cell = module.cell;
    return refused;
  }
  return std::nullopt;
}

void Reservations::reserve(const Claim& claim, const Holder& holder) {
  for (const geometry::Cell& cell : claim.cells) cells_[world::packCell(cell)] = holder;
  modules_[claim.mobile] = {Role::kMobile, -1, false, {holder}};
  modules_[claim.pivot] = {Role::kPivot, -1, false, {holder}};
  for (const Claim::Helper& helper : claim.helpers) {
    auto [it, fresh] = modules_.try_emplace(
        helper.module, ModuleHold{Role::kHelper, helper.axis, helper.double_, {}});
    it->second.holders.push_back(holder);
  }
}

void Reservations::release(const Claim& claim, int slot) {
  for (const geometry::Cell& cell : claim.cells) {
    const auto found = cells_.find(world::packCell(cell));
    if (found != cells_.end() && found->second.slot == slot) cells_.erase(found);
  }
  auto drop = [&](uint32_t module) {
    const auto found = modules_.find(module);
    if (found == modules_.end()) return;
    std::erase_if(found->second.holders, [&](const Holder& h) { return h.slot == slot; });
    if (found->second.holders.empty()) modules_.erase(found);
  };
  drop(claim.mobile);
  drop(claim.pivot);
  for (const Claim::Helper& helper : claim.helpers) drop(helper.module);
}

}  // namespace datomsim::sim
