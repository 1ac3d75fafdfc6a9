// Reading and checking a design file: the shipped ones load, and every kind of bad input is
// refused with a message naming the file, the key and the value.
#include "actuators/design.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "actuator_files.h"

namespace datomsim::testing {
namespace {

using actuators::Model;
using actuators::parseDesign;

std::string shippedText(const std::string& name) {
  std::ifstream in(kDesignDirectory / (name + ".json"));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The electrostatic latch's file with one piece of text replaced.
std::string editedLatch(const std::string& from, const std::string& to) {
  std::string text = shippedText("electrostatic-latch");
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string refusal(const std::string& text) {
  auto design = parseDesign(text, "bad.json");
  EXPECT_FALSE(design.ok());
  return design ? "" : design.error();
}

TEST(ActuatorDesign, EveryShippedDesignLoadsWithEveryFigureSourced) {
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kDesignDirectory)) {
    ++files;
    auto design = actuators::readDesign(entry.path());
    ASSERT_TRUE(design.ok()) << design.error();
    EXPECT_EQ(entry.path().stem().string(), design->name);
    EXPECT_EQ(design->figures.size(), actuators::figureSpecs(design->model).size());
    for (const auto& [key, figure] : design->figures) EXPECT_FALSE(figure.source.empty()) << key;
  }
  EXPECT_EQ(files, 5u);
}

TEST(ActuatorDesign, ReadsTheFiguresAsWritten) {
  const auto design = shippedDesign("electrostatic");
  EXPECT_EQ(design.model, Model::kElectrostaticLatch);
  EXPECT_EQ(actuators::kindOf(design.model), actuators::ActuatorKind::kLatch);
  EXPECT_DOUBLE_EQ(design.figure("relative_permittivity"), 3.4);
  EXPECT_DOUBLE_EQ(design.figure("voltage"), 300.0);
  EXPECT_EQ(design.figures.at("voltage").unit, "V");
  EXPECT_TRUE(design.figures.at("voltage").assumption);
  EXPECT_FALSE(design.figures.at("relative_permittivity").assumption);
  const auto sma = shippedDesign("sma-spring");
  EXPECT_DOUBLE_EQ(sma.figure("latent_heat"), 24200.0);
  EXPECT_EQ(sma.figures.at("specific_heat").unit, "J/(kg K)");
}

TEST(ActuatorDesign, RefusesTextThatIsNotJson) {
  EXPECT_NE(refusal("{ \"format\": ").find("bad.json: not JSON"), std::string::npos);
}

// nlohmann takes a NUL byte for the end of its input: what follows would go unread.
TEST(ActuatorDesign, RefusesANulByteNamingItsLine) {
  EXPECT_EQ(refusal("{\n}\n" + std::string(1, '\0') + "junk"),
            "bad.json:3: a NUL byte, which no JSON text holds");
}

TEST(ActuatorDesign, RefusesUnknownKeys) {
  EXPECT_EQ(refusal(editedLatch("\"summary\"", "\"colour\": 1, \"summary\"")),
            "bad.json: unknown key \"colour\" (a design holds format, version, name, model, "
            "summary and figures)");
  EXPECT_EQ(refusal(editedLatch("\"voltage\"", "\"voltag\"")),
            "bad.json: figures.voltag: unknown key for the model electrostatic-latch");
  EXPECT_EQ(refusal(editedLatch("\"unit\": \"V\"", "\"unit\": \"V\", \"note\": 1")),
            "bad.json: figures.voltage: unknown key \"note\" (a figure holds value, unit, source "
            "and assumption)");
}

TEST(ActuatorDesign, RefusesAMissingFigure) {
  std::string text = shippedText("electrostatic-latch");
  const size_t from = text.find("    \"drive_current\"");
  const size_t to = text.find('\n', from);
  text.erase(from, to - from + 1);
  // The figure before it loses its comma's follower: drop the comma too.
  const size_t comma = text.rfind(',', from);
  text.erase(comma, 1);
  EXPECT_EQ(refusal(text),
            "bad.json: figures.drive_current is missing (the model electrostatic-latch needs it, "
            "in A)");
}

TEST(ActuatorDesign, RefusesValuesThatAreNotFiniteAndPositive) {
  EXPECT_EQ(refusal(editedLatch("\"value\": 300,", "\"value\": -300,")),
            "bad.json: figures.voltage: value -300 must be finite and positive");
  EXPECT_EQ(refusal(editedLatch("\"value\": 300,", "\"value\": 0,")),
            "bad.json: figures.voltage: value 0 must be finite and positive");
  // JSON has no infinity or NaN: a number too large for a double is refused as it is read.
  const std::string overflow = refusal(editedLatch("\"value\": 300,", "\"value\": 1e999,"));
  EXPECT_NE(overflow.find("bad.json: not JSON: "), std::string::npos) << overflow;
  EXPECT_NE(overflow.find("number overflow parsing '1e999'"), std::string::npos) << overflow;
  EXPECT_NE(refusal(editedLatch("\"value\": 300,", "\"value\": NaN,")).find("not JSON"),
            std::string::npos);
  EXPECT_EQ(refusal(editedLatch("\"value\": 300,", "\"value\": \"300\",")),
            "bad.json: figures.voltage: \"value\" must be a number, got \"300\"");
  EXPECT_EQ(refusal(editedLatch("\"value\": 0.8,", "\"value\": 1.5,")),
            "bad.json: figures.electrode_fraction: value 1.5 is a share and must be at most 1");
}

TEST(ActuatorDesign, RefusesWrongUnits) {
  EXPECT_EQ(refusal(editedLatch("\"unit\": \"V\"", "\"unit\": \"kV\"")),
            "bad.json: figures.voltage: unit \"kV\" is not the one accepted, \"V\" (SI units, "
            "docs/actuators.md)");
  EXPECT_EQ(refusal(editedLatch("\"unit\": \"V\"", "\"unit\": 1")),
            "bad.json: figures.voltage: \"unit\" must be the text \"V\"");
}

TEST(ActuatorDesign, RefusesAFigureWithoutItsSource) {
  std::string text = shippedText("electrostatic-latch");
  const size_t from = text.find(", \"source\": \"assumption: 300 V");
  const size_t to = text.find(", \"assumption\"", from);
  text.erase(from, to - from);
  EXPECT_EQ(refusal(text),
            "bad.json: figures.voltage: \"source\" must say where the figure comes from");
  std::string empty = shippedText("electrostatic-latch");
  const size_t at = empty.find("\"source\": \"assumption: 300 V");
  empty.replace(at, empty.find("\", \"assumption\"", at) + 1 - at, "\"source\": \"\"");
  EXPECT_EQ(refusal(empty),
            "bad.json: figures.voltage: \"source\" must say where the figure comes from");
}

TEST(ActuatorDesign, RefusesAnUnknownModelFormatOrVersion) {
  EXPECT_EQ(refusal(editedLatch("\"model\": \"electrostatic-latch\"", "\"model\": \"glue\"")),
            "bad.json: \"model\" is \"glue\", not a model of actuator (known: sma-spring, "
            "electro-ribbon, mechanical-latch, electromagnetic-latch, electrostatic-latch)");
  EXPECT_EQ(refusal(editedLatch("\"version\": 1", "\"version\": 2")),
            "bad.json: \"version\" must be 1, got 2");
  EXPECT_EQ(refusal(editedLatch("\"format\": \"datomsim-actuator\"", "\"format\": \"scene\"")),
            "bad.json: \"format\" must be \"datomsim-actuator\", got \"scene\"");
}

TEST(ActuatorDesign, RefusesAVoltageTheFilmCannotHold) {
  // 3,500 V across 10 um is 3.5e8 V/m, above the thin Kapton film's specified 1.18e8.
  EXPECT_EQ(refusal(editedLatch("\"value\": 300,", "\"value\": 3500,")),
            "bad.json: voltage 3500 V across dielectric_thickness 1e-05 m is 3.5e+08 V/m, not "
            "below dielectric_strength 1.18e+08 V/m");
}

TEST(ActuatorDesign, ReadingAMissingFileSaysWhich) {
  auto design = actuators::readDesign(kDesignDirectory / "nothing.json");
  ASSERT_FALSE(design.ok());
  EXPECT_NE(design.error().find("nothing.json: no such file"), std::string::npos);
}

}  // namespace
}  // namespace datomsim::testing
