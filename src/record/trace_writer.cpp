#include "record/trace_writer.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <nlohmann/json.hpp>

#include "catom3d/roll_path.h"
#include "datom/linkage.h"
#include "datom/motion_path.h"
#include "datom/parts.h"
#include "geometry/lattice.h"

namespace datomsim::record {

using geometry::Vec3;

namespace {

// Kinematics sampled at f = 0, 1/8, ..., 1: the viewer interpolates between samples.
constexpr int kSamples = 9;

// Numbers with 6 significant digits, and never "-0": the trace must be byte-stable.
std::string number(double value) {
  if (std::abs(value) < 5e-10) value = 0;
  return fmt::format("{:.6g}", value);
}

std::string vec(const Vec3& v) {
  return fmt::format("[{},{},{}]", number(v.x), number(v.y), number(v.z));
}

// A JSON string literal, escaped.
std::string quoted(const std::string& text) {
  return nlohmann::json(text).dump();
}

std::string seconds(Time t) {
  return number(double(t) / kSecond);
}

std::string partJson(const datom::Part& part, int index) {
  static constexpr const char* kKinds[] = {"core", "piston", "link", "connector"};
  return fmt::format(
      "{{\"i\":{},\"kind\":\"{}\",\"piston\":{},\"connector\":{},\"centre\":{},\"axes\":[{},{},{}],"
      "\"size\":[{},{},{}]}}",
      index, kKinds[static_cast<int>(part.kind)], part.piston, part.connector, vec(part.centre),
      vec(part.axes[0]), vec(part.axes[1]), vec(part.axes[2]), number(part.size[0]),
      number(part.size[1]), number(part.size[2]));
}

// The parts a piston moves: its plate, its 4 links and its 4 connectors.
bool movesWith(const datom::Part& part, int piston) {
  if (part.kind == datom::PartKind::kPiston || part.kind == datom::PartKind::kLink) {
    return part.piston == piston;
  }
  if (part.kind == datom::PartKind::kConnector) {
    return geometry::axisMovesDirection(piston, part.connector);
  }
  return false;
}

}  // namespace

TraceWriter::TraceWriter(const datom::Dimensions& dimensions) : dimensions_(dimensions) {}

TraceWriter::TraceWriter(world::ModuleKind kind, const datom::Dimensions& dimensions)
    : dimensions_(dimensions), kind_(kind) {}

void TraceWriter::header(const world::World& world, const std::string& description,
                         std::span<const std::vector<geometry::Cell>> targets) {
  auto out = std::back_inserter(text_);
  const datom::Dimensions& d = dimensions_;
  text_ += "{\"format\":\"datomsim-trace\",\"version\":1,";
  // Only a Catom's trace names its module: a Datom trace is byte for byte what every reader of
  // version 1 knows, and a trace without "module" is one of Datoms.
  if (kind_ != world::ModuleKind::kDatom) {
    fmt::format_to(out, "\"module\":\"{}\",", world::toString(kind_));
  }
  fmt::format_to(out,
                 "\"description\":{},"
                 "\"spacing\":{},\"dimensions\":{{\"r\":{},\"t\":{},\"c\":{},\"e\":{},\"a\":{},"
                 "\"core_edge\":{}}},",
                 quoted(description), number(spacing()), number(d.radius()), number(d.thickness()),
                 number(d.connectorWidth()), number(d.linkLength()), number(d.amplitude()),
                 number(d.coreEdge()));

  // The 24 orientations as rotation matrices (rows), module frame to world.
  text_ += "\"orientations\":[";
  for (int code = 0; code < geometry::Orientation::kCount; ++code) {
    const auto o = *geometry::Orientation::fromCode(code);
    const Vec3 x = o.apply({1, 0, 0}), y = o.apply({0, 1, 0}), z = o.apply({0, 0, 1});
    fmt::format_to(out, "{}[{},{},{}]", code ? "," : "", vec({x.x, y.x, z.x}), vec({x.y, y.y, z.y}),
                   vec({x.z, y.z, z.z}));
  }
  text_ += "],";

  // Joint angles and the moving parts of each piston, sampled from the C++ kinematics.
  text_ += "\"kinematics\":{\"fractions\":[";
  for (int k = 0; k < kSamples; ++k) {
    fmt::format_to(out, "{}{}", k ? "," : "", number(double(k) / (kSamples - 1)));
  }
  text_ += "],\"angles\":[";
  for (int k = 0; k < kSamples; ++k) {
    const auto linkage = datom::solveLinkage(d, double(k) / (kSamples - 1));
    fmt::format_to(out, "{}{{\"q0\":{},\"q1\":{},\"p0\":{},\"travel\":{}}}", k ? "," : "",
                   number(linkage->angles.q0), number(linkage->angles.q1),
                   number(linkage->angles.p0), number(linkage->travel));
  }
  const auto rest = datom::partsLayout(d, geometry::kNoAxis, 0);
  text_ += "],\"rest\":[";
  for (size_t i = 0; i < rest->size(); ++i) {
    if (i) text_ += ",";
    text_ += partJson((*rest)[i], int(i));
  }
  text_ += "],\"pistons\":[";
  for (int piston = 0; piston < geometry::kAxisCount; ++piston) {
    text_ += piston ? ",[" : "[";
    for (int k = 0; k < kSamples; ++k) {
      const auto parts = datom::partsLayout(d, piston, double(k) / (kSamples - 1));
      text_ += k ? ",[" : "[";
      bool first = true;
      for (size_t i = 0; i < parts->size(); ++i) {
        if (!movesWith((*parts)[i], piston)) continue;
        if (!first) text_ += ",";
        first = false;
        text_ += partJson((*parts)[i], int(i));
      }
      text_ += "]";
    }
    text_ += "]";
  }
  text_ += "]},";

  // The initial scene.
  text_ += "\"modules\":[";
  bool first = true;
  for (const world::Module& m : world.modules()) {
    fmt::format_to(out,
                   "{}{{\"id\":{},\"cell\":[{},{},{}],\"pos\":{},\"o\":{},\"rgb\":[{},{},{}],"
                   "\"latches\":{}}}",
                   first ? "" : ",", m.id.value, m.cell.x, m.cell.y, m.cell.z,
                   vec(geometry::worldPosition(m.cell, spacing())), m.orientation.code(), m.color.r,
                   m.color.g, m.color.b, m.latches);
    first = false;
  }
  text_ += "]";
  // The target shapes, as cells; only when the scene has some.
  if (!targets.empty()) {
    text_ += ",\"targets\":[";
    for (size_t t = 0; t < targets.size(); ++t) {
      text_ += t ? ",[" : "[";
      for (size_t i = 0; i < targets[t].size(); ++i) {
        const geometry::Cell& cell = targets[t][i];
        fmt::format_to(out, "{}[{},{},{}]", i ? "," : "", cell.x, cell.y, cell.z);
      }
      text_ += "]";
    }
    text_ += "]";
  }
  // Energies in full (shortest round trip): a viewer sums thousands of them.
  if (actuators_) {
    const sim::ActuatorModel& a = *actuators_;
    fmt::format_to(out,
                   ",\"actuators\":{{\"name\":{},\"compress_J\":{},\"release_J\":{},"
                   "\"latch_J\":{},\"unlatch_J\":{},\"holding_W\":{},\"latch_s\":{},"
                   "\"unlatch_s\":{}}}",
                   quoted(a.name), a.compressEnergy, a.releaseEnergy, a.latchEnergy,
                   a.unlatchEnergy, a.holdingPower, double(a.latch) / kSecond,
                   double(a.unlatch) / kSecond);
  }
  text_ += "}\n";
}

void TraceWriter::pistonMoving(Time, const sim::PistonMove& move) {
  fmt::format_to(std::back_inserter(text_),
                 "{{\"t\":{},\"piston\":{{\"m\":{},\"p\":{},\"from\":{},\"to\":{},\"d\":{}}}}}\n",
                 seconds(move.start), move.module.value, move.piston, number(move.from),
                 number(move.to), seconds(move.duration));
}

void TraceWriter::motionStarted(Time t, const sim::MotionStart& start) {
  note(t, fmt::format("module {} {} towards {}", start.mobile.value,
                      start.model->narrate(*start.plan), geometry::toString(start.plan->goal)));
  // The motion as a whole, for timelines: who moves, about which pivot, which modules make way,
  // and when it ends.
  const geometry::Cell& goal = start.plan->goal;
  std::string blockers;
  for (const motion::Deformation& d : start.plan->deformations) {
    blockers += fmt::format("{}{}", blockers.empty() ? "" : ",", d.module.value);
  }
  fmt::format_to(
      std::back_inserter(text_),
      "{{\"t\":{},\"motion\":{{\"m\":{},\"pivot\":{},\"goal\":[{},{},{}],\"blockers\":[{}],"
      "\"end\":{}}}}}\n",
      seconds(t), start.mobile.value, start.pivot.value, goal.x, goal.y, goal.z, blockers,
      seconds(start.until));
}

void TraceWriter::motionRefused(Time t, ModuleId, const MoveRefusal& refusal) {
  note(t, "motion refused: " + refusal.text);
}

void TraceWriter::deformationRefused(Time t, ModuleId, std::string_view, const std::string& text) {
  note(t, "deformation refused: " + text);
}

void TraceWriter::turnStarted(Time t, const sim::QuarterTurn& turn) {
  const Vec3 centre = datom::turnHinge(
      dimensions_, geometry::worldPosition(turn.pivotCell, spacing()), turn.up, turn.side);
  const bool compressing = turn.first;
  // The body turns twice as far as each connector (pivot's and mobile's turn together): the
  // fraction turned is theta(f) / 45 degrees, with f going 0 -> 1, or 1 -> 0 on the way back.
  std::string progress;
  for (int k = 0; k < kSamples; ++k) {
    const double u = double(k) / (kSamples - 1);
    const double turned =
        compressing ? datom::solveLinkage(dimensions_, u)->connectorTurn / 45.0
                    : 1.0 - datom::solveLinkage(dimensions_, 1.0 - u)->connectorTurn / 45.0;
    if (k) progress += ',';
    progress += number(turned);
  }
  fmt::format_to(std::back_inserter(text_),
                 "{{\"t\":{},\"turn\":{{\"m\":{},\"axis\":{},\"centre\":{},\"deg\":{},"
                 "\"d\":{},\"progress\":[{}]}}}}\n",
                 seconds(t), turn.mobile.value, vec(geometry::axisVector(turn.axis)), vec(centre),
                 number(turn.degrees), seconds(turn.duration), progress);
}

void TraceWriter::rollStarted(Time t, const sim::RollTurn& roll) {
  // One rigid turn about the normal of the triangle pivot, start, goal through its centre, which
  // takes the start to the goal (docs/catom3d.md, "In the simulator").
  const catom3d::RollAxis turn = catom3d::rollAxis(
      geometry::worldPosition(roll.pivotCell, spacing()),
      geometry::worldPosition(roll.from, spacing()), geometry::worldPosition(roll.goal, spacing()));
  fmt::format_to(std::back_inserter(text_),
                 "{{\"t\":{},\"turn\":{{\"m\":{},\"axis\":{},\"centre\":{},\"deg\":{},"
                 "\"d\":{}}}}}\n",
                 seconds(t), roll.mobile.value, vec(turn.axis), vec(turn.centre),
                 number(roll.degrees), seconds(roll.duration));
}

void TraceWriter::modulePlaced(Time t, const world::Module& module) {
  const geometry::Cell& cell = module.cell;
  fmt::format_to(std::back_inserter(text_),
                 "{{\"t\":{},\"place\":{{\"m\":{},\"cell\":[{},{},{}],\"pos\":{},\"o\":{}}}}}\n",
                 seconds(t), module.id.value, cell.x, cell.y, cell.z,
                 vec(geometry::worldPosition(cell, spacing())), module.orientation.code());
}

void TraceWriter::latchChanged(Time t, const world::LatchPair& pair, bool latched) {
  fmt::format_to(std::back_inserter(text_),
                 "{{\"t\":{},\"latch\":{{\"a\":{},\"ca\":{},\"b\":{},\"cb\":{},\"on\":{}}}}}\n",
                 seconds(t), pair.a.value, pair.connectorA, pair.b.value, pair.connectorB, latched);
}

void TraceWriter::colorChanged(Time t, ModuleId module, Color color) {
  fmt::format_to(std::back_inserter(text_),
                 "{{\"t\":{},\"color\":{{\"m\":{},\"rgb\":[{},{},{}]}}}}\n", seconds(t),
                 module.value, color.r, color.g, color.b);
}

void TraceWriter::programLog(Time t, ModuleId module, std::string_view text) {
  note(t, fmt::format("module {}: {}", module.value, text));
}

void TraceWriter::note(Time t, const std::string& text) {
  fmt::format_to(std::back_inserter(text_), "{{\"t\":{},\"note\":{}}}\n", seconds(t), quoted(text));
}

void TraceWriter::footer(Time t, const std::string& summaryJson) {
  fmt::format_to(std::back_inserter(text_), "{{\"t\":{},\"end\":{}}}\n", seconds(t), summaryJson);
}

}  // namespace datomsim::record
