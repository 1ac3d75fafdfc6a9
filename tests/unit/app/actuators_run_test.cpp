// `run --actuators` as a user runs it: the durations of the pistons and latches are the design's
// at the module's size, the energy drawn is counted per module and in total (run --out's
// "energy", --power-csv, --stats), the same run gives the same bytes, a run without --actuators
// keeps its output, and bad values are refused before anything is written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "command_line.h"

namespace datomsim {
namespace {

using testing::readText;

class ActuatorsRun : public CommandLine {
 protected:
  std::string followGradient() {
    return "run " + arch(1) + " --program follow-gradient --goal 6,5,2 --start 0,0,2";
  }
  nlohmann::json run(const std::string& options, const std::string& name) {
    const Outcome outcome = datomsim(followGradient() + " " + options + " --out " + path(name));
    EXPECT_EQ(outcome.status, 0) << options << "\n" << outcome.output;
    return nlohmann::json::parse(readText(path(name)));
  }
  nlohmann::json show(const std::string& size) {
    const Outcome outcome = datomsim("actuators show sma-spring --json --size " + size);
    EXPECT_EQ(outcome.status, 0) << outcome.output;
    return nlohmann::json::parse(outcome.output)["designs"][0]["quantities"];
  }
  void refused(const std::string& options, const std::string& message) {
    const Outcome outcome = datomsim(followGradient() + " " + options + " --out " +
                                     path("refused.json") + " --power-csv " + path("refused.csv"));
    EXPECT_EQ(outcome.status, 1) << options << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos)
        << options << "\nexpected: " << message << "\ngot: " << outcome.output;
    EXPECT_FALSE(std::filesystem::exists(path("refused.json"))) << options;
    EXPECT_FALSE(std::filesystem::exists(path("refused.csv"))) << options;
  }
};

TEST_F(ActuatorsRun, TheSumOfTheModulesEnergiesIsTheTotal) {
  const nlohmann::json out = run("--actuators sma-spring+electrostatic --size 1cm", "run.json");
  ASSERT_TRUE(out.contains("energy"));
  const nlohmann::json& energy = out["energy"];
  EXPECT_EQ(energy["actuators"], "sma-spring+electrostatic-latch");
  double modules = 0, pistons = 0;
  for (const nlohmann::json& module : energy["modules"]) {
    modules += module["total_J"].get<double>();
    pistons += module["pistons_J"].get<double>();
  }
  const double total = energy["total_J"].get<double>();
  EXPECT_GT(total, 0);
  EXPECT_NEAR(modules, total, 1e-9 * total);
  EXPECT_NEAR(pistons, energy["pistons_J"].get<double>(), 1e-9 * total);
  // Each compression heats the spring once, at the design's energy (0.1712 J at 1 cm).
  EXPECT_NEAR(
      energy["pistons_J"].get<double>(),
      energy["compressions"].get<double>() * energy["energy_per_event_J"]["compress"].get<double>(),
      1e-9 * total);
  EXPECT_NEAR(energy["energy_per_event_J"]["compress"].get<double>(), 0.1712, 1e-4);
  EXPECT_NEAR(energy["energy_per_motion_J"].get<double>(), total / out["motions"].get<double>(),
              1e-12 * total);
  // Pistons heat for the spring's heating time and cool for its cooling time.
  EXPECT_NEAR(energy["durations_s"]["compress"].get<double>(), 1.027, 5e-4);
  EXPECT_NEAR(energy["durations_s"]["release"].get<double>(), 0.8412, 5e-5);
  EXPECT_GT(energy["peak_power_W"].get<double>(), 0.1668);
}

TEST_F(ActuatorsRun, TheCoolingTimeFollowsTheWireAsTheLawSays) {
  // Above the thinnest wire, d grows as r^1.5 and the cooling as d^1.5: between 1 cm and 10 cm
  // the run's release takes (d(10 cm) / d(1 cm))^1.5 times longer.
  const nlohmann::json small = run("--actuators sma-spring+mechanical --size 1cm", "1cm.json");
  const nlohmann::json large = run("--actuators sma-spring+mechanical --size 10cm", "10cm.json");
  const double ratio = show("10cm")["wire diameter"]["value"].get<double>() /
                       show("1cm")["wire diameter"]["value"].get<double>();
  EXPECT_NEAR(ratio, std::pow(10.0, 1.5), 1e-6 * ratio);
  const double cooling = large["energy"]["durations_s"]["release"].get<double>() /
                         small["energy"]["durations_s"]["release"].get<double>();
  EXPECT_NEAR(cooling, std::pow(ratio, 1.5), 1e-5 * cooling);
  // The larger module waits for its wire: the same motions take longer.
  EXPECT_EQ(small["motions"], large["motions"]);
  EXPECT_GT(large["makespan_s"].get<double>(), 10 * small["makespan_s"].get<double>());
}

TEST_F(ActuatorsRun, TheSameRunGivesTheSameBytes) {
  const std::string options =
      "--actuators electro-ribbon+electromagnetic --size 1mm --power-csv " + path("a.csv");
  ASSERT_EQ(datomsim(followGradient() + " " + options + " --out " + path("a.json")).status, 0);
  const std::string again =
      "--actuators electro-ribbon+electromagnetic --size 1mm --power-csv " + path("b.csv");
  ASSERT_EQ(datomsim(followGradient() + " " + again + " --out " + path("b.json")).status, 0);
  EXPECT_EQ(readText(path("a.json")), readText(path("b.json")));
  EXPECT_EQ(readText(path("a.csv")), readText(path("b.csv")));
  // The CSV's last row has drawn the whole total.
  const std::string csv = readText(path("a.csv"));
  ASSERT_EQ(csv.rfind("time_s,power_W,energy_J\n", 0), 0u);
  const std::string last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
  const double drawn = std::stod(last.substr(last.rfind(',') + 1));
  const double total =
      nlohmann::json::parse(readText(path("a.json")))["energy"]["total_J"].get<double>();
  EXPECT_NEAR(drawn, total, 1e-6 * total);
}

TEST_F(ActuatorsRun, ARunWithoutActuatorsKeepsItsOutput) {
  const nlohmann::json without = run("", "without.json");
  EXPECT_FALSE(without.contains("energy"));
  // The fixed times (0.5 s a deformation, 1 s a quarter turn): the makespan the run had before
  // actuators were modelled (the golden runs, tests/golden, hold the whole output).
  EXPECT_DOUBLE_EQ(without["makespan_s"].get<double>(), 24.38);
  nlohmann::json with = run("--actuators sma-spring+electrostatic", "with.json");
  EXPECT_EQ(with["motions"], without["motions"]);
  EXPECT_NE(with["makespan_s"], without["makespan_s"]);
}

// Reconfiguration calls a run stalled when no target cell is filled for 600 s of fixed-time
// motions; a motion of a 10 cm SMA module waits 150 s for its wire to cool, so the watch's limits
// stretch with the motions' time.
TEST_F(ActuatorsRun, SlowActuatorsStillBuildTheArch) {
  const std::string scene = path("reshape.json");
  ASSERT_EQ(datomsim("generate reshape arch1 -o " + scene).status, 0);
  const Outcome outcome =
      datomsim("run " + scene +
               " --program reconfigure --actuators sma-spring+electromagnetic --size 10cm --out " +
               path("run.json"));
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const nlohmann::json run = nlohmann::json::parse(readText(path("run.json")));
  EXPECT_TRUE(run["success"].get<bool>());
  EXPECT_GT(run["makespan_s"].get<double>(), 600.0);
}

// A mover's helpers latch to it again only once their pistons are back at rest, and the ways down
// the gradient about them are not among its motions before. A 10 cm module's latching takes
// seconds: a mover that went sideways after its few short rounds walked along a row of the arch's
// leg for hours, each time before the way up was there, and the lintel's last cell stayed empty
// (three of these arches, with SMA springs, stalled so).
TEST_F(ActuatorsRun, AMoverWaitsForItsHelpersToLatchAgainBeforeGoingSideways) {
  const std::string scene = std::string(DATOMSIM_SOURCE_DIR) + "/scenes/reshape-arch-hole2.json";
  for (const char* combination : {"sma-spring+mechanical", "sma-spring+electrostatic"}) {
    const Outcome outcome = datomsim("run " + scene + " --program reconfigure --actuators " +
                                     combination + " --size 10cm --out " + path("arch.json"));
    ASSERT_EQ(outcome.status, 0) << combination << "\n" << outcome.output.substr(0, 2000);
    const nlohmann::json run = nlohmann::json::parse(readText(path("arch.json")));
    EXPECT_TRUE(run["success"].get<bool>()) << combination;
  }
}

// A mover that no distance reaches falls towards the ground; on the side of the arch's box, at
// layer 1, its only motions swung it between two cells about one pivot, each with the other
// mover as a helper, whose own way up needed it still: for twenty hours of simulated time. A
// sideways motion, a fall that goes no lower included, now waits twice as long as the last, in
// motion times, and the other mover's motion goes meanwhile (these three stalled so).
TEST_F(ActuatorsRun, AMoverThatSwingsSidewaysWaitsLongerEachTime) {
  const std::string scene = std::string(DATOMSIM_SOURCE_DIR) + "/scenes/reshape-arch-hole2.json";
  for (const char* run :
       {"sma-spring+electromagnetic --seed 2", "sma-spring+electromagnetic --seed 16",
        "sma-spring+electrostatic --seed 5"}) {
    const Outcome outcome = datomsim("run " + scene + " --program reconfigure --actuators " + run +
                                     " --size 10cm --out " + path("arch.json"));
    ASSERT_EQ(outcome.status, 0) << run << "\n" << outcome.output.substr(0, 2000);
    EXPECT_TRUE(nlohmann::json::parse(readText(path("arch.json")))["success"].get<bool>()) << run;
  }
}

// On the arch's thin top, a helper's compressed piston lets go of the latches its request came
// by, and its answer may find no way back within its hops. The mover whose answers do not come
// tries the motion (the rules refuse it unless every helper is compressed): with 10 cm ribbons
// and electromagnetic latches it gave the round up instead, every time, and circled the top for
// hours with the last cell one helper away (seeds 1 and 4; seed 1 here).
TEST_F(ActuatorsRun, AMoverWhoseHelpersAnswersAreLostTriesTheMotion) {
  const std::string scene = std::string(DATOMSIM_SOURCE_DIR) + "/scenes/reshape-arch-hole2.json";
  const Outcome outcome = datomsim(
      "run " + scene + " --program reconfigure --actuators electro-ribbon+electromagnetic" +
      " --size 10cm --out " + path("arch.json"));
  ASSERT_EQ(outcome.status, 0) << outcome.output.substr(0, 2000);
  const nlohmann::json run = nlohmann::json::parse(readText(path("arch.json")));
  EXPECT_TRUE(run["success"].get<bool>());
}

// A version of the gradient seeds the open cells its modules sense at its start. On the arch's
// top with 1 cm SMA springs and electromagnetic latches, a mover stood on the second-last cell,
// not yet open, and stepped off it just as the version began: the cell opened, but its neighbours
// had sensed it occupied, and the cell beyond it looked open instead. No fill came to start
// another version; two movers circled the two cells for twenty minutes until the stall detector
// stopped the run. A mover that leaves a cell now seeds it if it is open.
TEST_F(ActuatorsRun, AMoverSeedsTheOpenCellItLeaves) {
  const std::string scene = std::string(DATOMSIM_SOURCE_DIR) + "/scenes/reshape-arch-hole2.json";
  const Outcome outcome =
      datomsim("run " + scene + " --program reconfigure --actuators sma-spring+electromagnetic" +
               " --size 1cm --out " + path("arch.json"));
  ASSERT_EQ(outcome.status, 0) << outcome.output.substr(0, 2000);
  const nlohmann::json run = nlohmann::json::parse(readText(path("arch.json")));
  EXPECT_TRUE(run["success"].get<bool>());
  EXPECT_TRUE(run["missing"].empty()) << run["missing"];
}

// A mover gives a round up when its helpers have not answered within a few seconds, and a helper
// lets its piston go when the motion it was held for has not come within a minute: both are waits
// for pistons and motions, which a 10 cm module's latches (5.2 s a mechanical latching) and
// ribbons (3.9 s a stroke) outlast. Each stretches by the actuators' times; with fixed waits every
// round of these movers was given up before their helpers had compressed, and the heap deadlocked.
TEST_F(ActuatorsRun, WaitsForPistonsStretchWithTheActuators) {
  const std::string scene = std::string(DATOMSIM_SOURCE_DIR) + "/scenes/reshape-heap.json";
  for (const char* combination :
       {"electro-ribbon+mechanical", "electro-ribbon+electromagnetic", "sma-spring+mechanical"}) {
    const Outcome outcome = datomsim("run " + scene + " --program reconfigure --actuators " +
                                     combination + " --size 10cm --out " + path("heap.json"));
    ASSERT_EQ(outcome.status, 0) << combination << "\n" << outcome.output.substr(0, 2000);
    const nlohmann::json run = nlohmann::json::parse(readText(path("heap.json")));
    EXPECT_TRUE(run["success"].get<bool>()) << combination;
  }
}

TEST_F(ActuatorsRun, StatsPrintTheEnergy) {
  const Outcome outcome = datomsim(
      followGradient() + " --actuators sma-spring+electrostatic --stats --out " + path("run.json"));
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  for (const char* line : {"energy      sma-spring+electrostatic-latch at r = 0.01 m",
                           "  power     peak", "heated share", "latchings"}) {
    EXPECT_NE(outcome.output.find(line), std::string::npos) << line << "\n" << outcome.output;
  }
}

TEST_F(ActuatorsRun, BadValuesAreRefusedBeforeAnythingIsWritten) {
  refused("--actuators sma-sprng+electrostatic",
          "unknown actuator design \"sma-sprng\": did you mean \"sma-spring\"?");
  refused("--actuators sma-spring", "expected one deformation design and one latch design");
  refused("--actuators sma-spring+electro-ribbon", "are both deformation designs");
  refused("--actuators sma-spring+electrostatic --size 1km",
          "--size 1km: expected a positive length with its unit");
  refused("--actuators sma-spring+electrostatic --size 0cm",
          "--size 0cm: expected a positive length with its unit");
  refused("--actuators sma-spring+electrostatic --designs " + path("none"),
          "none/sma-spring.json: no such file or not readable");
  refused("--size 1cm", "--size is an option of the actuators: it needs --actuators");
  refused("", "--power-csv is an option of the actuators: it needs --actuators");
  refused("--actuators sma-spring+electrostatic --module catom3d",
          "--actuators: the designs drive a Datom's pistons");
}

TEST_F(ActuatorsRun, APowerCsvOverAnInputIsRefused) {
  const std::string scene = arch(1);
  const std::string before = readText(scene);
  const Outcome outcome =
      datomsim("run " + scene +
               " --program follow-gradient --goal 6,5,2 --start 0,0,2 --actuators "
               "sma-spring+electrostatic --power-csv " +
               scene + " --out " + path("run.json"));
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("--power-csv"), std::string::npos) << outcome.output;
  EXPECT_EQ(readText(scene), before);
  EXPECT_FALSE(std::filesystem::exists(path("run.json")));
}

}  // namespace
}  // namespace datomsim
