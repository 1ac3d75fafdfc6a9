// `view --loads` and the energy the trace of a run with actuators carries (docs/viewer.md,
// "Colourings"): the loads of the page's own scene are put in the page; anything else is refused
// with the file named, and no page is left.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "command_line.h"

namespace datomsim {
namespace {

using Json = nlohmann::json;
using testing::readText;

class ViewColours : public CommandLine {
 protected:
  void SetUp() override {
    scene_ = arch(2);
    ASSERT_EQ(datomsim("loads " + scene_ + " -q --out " + path("loads.json")).status, 0);
    loads_ = Json::parse(readText(path("loads.json")));
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(path(name), std::ios::binary) << text;
  }
  // `view` of the scene with these loads must fail naming the file and `message`, and leave no
  // page.
  void refused(const std::string& loadsFile, const std::string& message) {
    const std::string page = path("page.html");
    const Outcome outcome = datomsim("view " + scene_ + " --loads " + loadsFile + " -o " + page);
    EXPECT_EQ(outcome.status, 1) << outcome.output;
    EXPECT_NE(outcome.output.find(loadsFile + message), std::string::npos)
        << "expected: " << loadsFile << message << "\ngot: " << outcome.output;
    EXPECT_FALSE(std::filesystem::exists(page));
  }
  void refusedChanged(Json loads, const std::string& message) {
    write("changed.json", loads.dump());
    refused(path("changed.json"), message);
  }
  std::string scene_;
  Json loads_;
};

TEST_F(ViewColours, ThePageHoldsTheLatchLoadsOfItsScene) {
  const Outcome outcome =
      datomsim("view " + scene_ + " --loads " + path("loads.json") + " -o " + path("page.html"));
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const std::string html = readText(path("page.html"));
  const std::string open = "<script type=\"application/json\" id=\"datomsim-loads\">";
  const size_t begin = html.find(open);
  ASSERT_NE(begin, std::string::npos);
  const size_t start = begin + open.size();
  const Json page = Json::parse(html.substr(start, html.find("</script>", start) - start));
  ASSERT_EQ(page["latches"].size(), loads_["loads"].size());
  EXPECT_EQ(page["overloaded"], loads_["overloaded"]);
  EXPECT_EQ(page["latch_force_n"], loads_["parameters"]["latch_force_n"]);
  // Each latch as [a, b, |force|, |moment|, safety], in the order of the loads.
  const Json& first = loads_["loads"][0];
  const Json& shown = page["latches"][0];
  EXPECT_EQ(shown[0], first["a"]);
  EXPECT_EQ(shown[1], first["b"]);
  const auto length = [](const Json& v) {
    return std::hypot(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  };
  EXPECT_DOUBLE_EQ(shown[2].get<double>(), length(first["force_n"]));
  EXPECT_DOUBLE_EQ(shown[3].get<double>(), length(first["moment_n_m"]));
  EXPECT_DOUBLE_EQ(shown[4].get<double>(), first["safety"].get<double>());
}

TEST_F(ViewColours, LoadsOfAnotherSceneAreRefused) {
  ASSERT_EQ(datomsim("loads " + arch(1) + " -q --out " + path("arch1-loads.json")).status, 0);
  refused(path("arch1-loads.json"), ": the loads of another scene: module 131 is not in the scene");
  // The same modules and latches one cell further: the centre of mass gives it away.
  Json moved = loads_;
  moved["tipping"]["centre_of_mass_m"][0] =
      moved["tipping"]["centre_of_mass_m"][0].get<double>() + 0.02;
  refusedChanged(moved, ": the loads of another scene: its centre of mass is (0.116");
  Json fewer = loads_;
  fewer["loads"].erase(fewer["loads"].size() - 1);
  refusedChanged(fewer,
                 ": the loads of another scene: 480 latches, the scene has 481 latched pairs");
  Json far = loads_;
  far["loads"][0]["b"] = 130;
  refusedChanged(far,
                 ": the loads of another scene: loads[0]: modules 1 and 130 are not neighbours");
  Json missing = loads_;
  missing["displacements"].erase(0);
  refusedChanged(missing, ": the loads of another scene: module 1 of the scene has no load");
}

TEST_F(ViewColours, WhatIsNotTheJsonOfLoadsIsRefused) {
  write("nul.json", std::string("{\"parameters\":{}}\n\0", 19));
  refused(path("nul.json"), ":2: a NUL byte, which no JSON text holds");
  write("broken.json", "{\"loads\": [");
  refused(path("broken.json"), ": invalid JSON");
  write("list.json", "[]");
  refused(path("list.json"), ": not the JSON of `datomsim loads --out`: it is not an object");
  // The distributed solver's run output: "program":"loads" too, but no latches.
  ASSERT_EQ(
      datomsim("run " + scene_ + " --program loads --root 6,5,0 --out " + path("run.json")).status,
      0);
  refused(path("run.json"),
          ": not the JSON of `datomsim loads --out`: \"parameters.latch_force_n\" is not a "
          "positive number");
  Json twice = loads_;
  twice["loads"][1] = twice["loads"][0];
  refusedChanged(twice, ": not the JSON of `datomsim loads --out`: loads[1]: latch");
  Json safety = loads_;
  safety["loads"][0]["safety"] = "high";
  refusedChanged(safety,
                 ": not the JSON of `datomsim loads --out`: loads[0]'s \"safety\" is neither a "
                 "number >= 0 nor null");
  refused(path("absent.json"), "");
  EXPECT_NE(
      datomsim("view " + scene_ + " --loads " + path("absent.json") + " -o " + path("page.html"))
          .output.find("cannot read " + path("absent.json")),
      std::string::npos);
}

TEST_F(ViewColours, AnActuatedRunsTraceCarriesItsActuatorsAndARunWithoutNone) {
  const std::string run = "run " + scene_ +
                          " --program follow-gradient --goal 6,5,2 --start 0,0,2 -q --out " +
                          path("r.json") + " --trace ";
  ASSERT_EQ(datomsim(run + path("plain.jsonl")).status, 0);
  ASSERT_EQ(
      datomsim(run + path("act.jsonl") + " --actuators sma-spring+electrostatic --size 1cm").status,
      0);
  const auto header = [&](const std::string& name) {
    const std::string text = readText(path(name));
    return Json::parse(text.substr(0, text.find('\n')));
  };
  EXPECT_FALSE(header("plain.jsonl").contains("actuators"));
  const Json actuators = header("act.jsonl")["actuators"];
  const Json energy = Json::parse(readText(path("r.json")))["energy"];
  EXPECT_EQ(actuators["name"], energy["actuators"]);
  EXPECT_EQ(actuators["compress_J"], energy["energy_per_event_J"]["compress"]);
  EXPECT_EQ(actuators["latch_J"], energy["energy_per_event_J"]["latch"]);
  EXPECT_EQ(actuators["holding_W"], energy["holding_power_per_latch_W"]);
  EXPECT_EQ(actuators["latch_s"], energy["durations_s"]["latch"]);
  // A trace whose figures are no energies is refused by view, naming the line.
  std::string text = readText(path("act.jsonl"));
  const size_t at = text.find("\"holding_W\":");
  text.replace(at, text.find(',', at) - at, "\"holding_W\":-1");
  write("bad.jsonl", text);
  const Outcome outcome = datomsim("view " + path("bad.jsonl") + " -o " + path("bad.html"));
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(
      outcome.output.find("bad.jsonl:1: \"actuators.holding_W\" must be a number >= 0, not -1"),
      std::string::npos)
      << outcome.output;
  EXPECT_FALSE(std::filesystem::exists(path("bad.html")));
}

}  // namespace
}  // namespace datomsim
