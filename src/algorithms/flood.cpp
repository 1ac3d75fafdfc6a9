#include "algorithms/flood.h"

#include <array>
#include <memory>

namespace datomsim::algorithms {

namespace {

// A colour per hop count, repeating: rings around the root in the viewer.
constexpr std::array<Color, 6> kRings = {Color{230, 60, 60},  Color{240, 160, 40},
                                         Color{230, 220, 60}, Color{80, 200, 90},
                                         Color{60, 150, 230}, Color{150, 90, 220}};

}  // namespace

ProgramEntry FloodProgram::entry() {
  ProgramEntry entry;
  entry.name = "flood";
  entry.summary = "every module learns its hop count from a root by flooding (--root X,Y,Z)";
  entry.parameters = {Parameter::cell("root", "the module the flood starts from").module()};
  entry.make = [](ModuleId, const Parameters& parameters) {
    return std::make_unique<FloodProgram>(parameters.cell("root"));
  };
  return entry;
}

void FloodProgram::onStart(Context& context) {
  if (context.cell() == root_) learn(context, 0, -1);
}

void FloodProgram::onMessage(Context& context, int connector, const Message& message) {
  if (const auto* told = message.as<HopsMsg>(); told && (hops_ < 0 || told->hops < hops_)) {
    learn(context, told->hops, connector);
  }
}

void FloodProgram::learn(Context& context, int32_t hops, int from) {
  hops_ = hops;
  context.setColor(kRings[size_t(hops) % kRings.size()]);
  context.sendToAll(Message::of(HopsMsg{hops + 1}), from);
}

void FloodProgram::report(Report& report) const {
  if (hops_ >= 0) report.set("hops", hops_);
}

std::string FloodProgram::describe() const {
  return hops_ < 0 ? "not reached yet" : "hops from the source: " + std::to_string(hops_);
}

}  // namespace datomsim::algorithms
