#include "record/trace_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/lattice.h"
#include "sim/simulator.h"
#include "support/rule_table.h"
#include "support/scripted_program.h"
#include "support/world_builder.h"

namespace datomsim::record {
namespace {

using geometry::Cell;
using testing::Script;
using testing::WorldBuilder;

std::vector<nlohmann::json> lines(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::stringstream stream(text);
  for (std::string line; std::getline(stream, line);) out.push_back(nlohmann::json::parse(line));
  return out;
}

// A mobile goes ahead around a pivot in mid-air: the trace, subscribed like any recorder, has
// every change the viewer replays, with the hinge worked out from the module's model.
TEST(TraceWriter, RecordsAMotionAsTheSimulatorAnnouncesIt) {
  const motion::Rule& rule = testing::paperRules().rule(2);  // direction 0, first piston, go ahead
  const Cell pivot{5, 5, 5};
  const Cell mobile = pivot + rule.mobileOffset;
  std::map<uint32_t, Script> programs;
  programs[2].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (m.rule == rule.index) {
        ASSERT_TRUE(c.move(m).ok());
      }
    }
  };
  const world::World world = WorldBuilder().module(pivot).module(mobile).build();
  TraceWriter trace;
  trace.header(world, "one motion");
  sim::Simulator simulator(world, testing::paperRules(), {});
  simulator.subscribe(&trace);
  simulator.install(testing::scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());

  const auto records = lines(trace.text());
  ASSERT_GE(records.size(), 2u);
  EXPECT_EQ(records[0]["format"], "datomsim-trace");
  std::vector<nlohmann::json> turns, pistons, places, latches, notes;
  for (size_t i = 1; i < records.size(); ++i) {
    if (records[i].contains("turn")) turns.push_back(records[i]["turn"]);
    if (records[i].contains("piston")) pistons.push_back(records[i]);
    if (records[i].contains("place")) places.push_back(records[i]["place"]);
    if (records[i].contains("latch")) latches.push_back(records[i]["latch"]);
    if (records[i].contains("note")) notes.push_back(records[i]["note"]);
  }
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "module 2 turns ahead about pivot 1 (piston " + std::to_string(rule.up) +
                          ") towards " + geometry::toString(pivot + rule.goalOffset));
  // Two quarter turns of 90 degrees, the first about -R through the hinge on the -F side.
  ASSERT_EQ(turns.size(), 2u);
  // The hinge: the edge of the pivot's compressed connector, c/2 + e along U and (r + c/2) / sqrt2
  // towards -F (the unit Datom: r = 1).
  const datom::Dimensions unit;
  const geometry::Vec3 hinge =
      geometry::worldPosition(pivot, trace.spacing()) +
      geometry::axisVector(rule.up) * (unit.connectorWidth() / 2 + unit.linkLength()) +
      geometry::axisVector(geometry::oppositeAxis(rule.front)) *
          ((1 + unit.connectorWidth() / 2) / std::sqrt(2.0));
  EXPECT_NEAR(turns[0]["centre"][0].get<double>(), hinge.x, 1e-5);
  EXPECT_NEAR(turns[0]["centre"][1].get<double>(), hinge.y, 1e-5);
  EXPECT_NEAR(turns[0]["centre"][2].get<double>(), hinge.z, 1e-5);
  EXPECT_EQ(turns[0]["deg"], 90);
  EXPECT_EQ(turns[0]["progress"].front(), 0);
  EXPECT_EQ(turns[1]["progress"].back(), 1);
  // Pivot and mobile compress over the first quarter turn and come back over the second.
  ASSERT_EQ(pistons.size(), 4u);
  EXPECT_EQ(pistons[0]["piston"]["to"], 1);
  EXPECT_EQ(pistons[3]["piston"]["to"], 0);
  EXPECT_EQ(pistons[3]["t"], 1);  // the second quarter turn starts after one second
  // The mobile arrives at the goal; the hinge's new pair latched before the old one let go.
  ASSERT_EQ(places.size(), 1u);
  EXPECT_EQ(places[0]["m"], 2);
  const Cell goal = pivot + rule.goalOffset;
  EXPECT_EQ(places[0]["cell"], (std::vector<int>{goal.x, goal.y, goal.z}));
  size_t on = latches.size(), off = latches.size();
  for (size_t i = 0; i < latches.size(); ++i) {
    if (latches[i]["on"] == true && on == latches.size()) on = i;
    if (latches[i]["on"] == false) off = i;
  }
  ASSERT_LT(on, latches.size());
  EXPECT_LT(on, off);
}

// The header names the module kind for 3D Catoms only: a Datom trace stays byte for byte what it
// was, without "module", whether the kind is given or not.
TEST(TraceWriter, NamesTheModuleKindInTheHeaderOfACatomWorldOnly) {
  const world::World world = WorldBuilder().module({0, 0, 0}).module({1, 0, 0}).build();
  TraceWriter catoms(world::ModuleKind::kCatom3D);
  catoms.header(world, "two Catoms");
  const nlohmann::json catomHeader = lines(catoms.text()).front();
  EXPECT_EQ(catomHeader["module"], "catom3d");
  EXPECT_EQ(catoms.text().rfind(R"({"format":"datomsim-trace","version":1,"module":"catom3d",)", 0),
            0u);
  // The rest of the header is the Datom's, modules included: the viewer reads both alike.
  EXPECT_EQ(catomHeader["modules"].size(), 2u);
  EXPECT_EQ(catomHeader["orientations"].size(), 24u);

  TraceWriter datoms;
  datoms.header(world, "two Catoms");
  EXPECT_FALSE(lines(datoms.text()).front().contains("module"));
  EXPECT_EQ(datoms.text().find("\"module\""), std::string::npos);
  TraceWriter named(world::ModuleKind::kDatom);
  named.header(world, "two Catoms");
  EXPECT_EQ(named.text(), datoms.text());
  // Apart from the field, the two headers are the same bytes.
  const std::string field = R"("module":"catom3d",)";
  std::string withoutField = catoms.text();
  const size_t at = withoutField.find(field);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(withoutField.erase(at, field.size()), datoms.text());
}

}  // namespace
}  // namespace datomsim::record
