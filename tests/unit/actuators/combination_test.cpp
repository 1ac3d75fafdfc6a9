// Designs combined by name: one deformation design and one latch, short latch names, and the
// closest name suggested for a misspelt one.
#include "actuators/combination.h"

#include <gtest/gtest.h>

#include "actuator_files.h"

namespace datomsim::testing {
namespace {

using actuators::parseCombination;

TEST(ActuatorCombination, ReadsADeformationDesignAndALatch) {
  auto combination = parseCombination("sma-spring+electrostatic-latch");
  ASSERT_TRUE(combination.ok()) << combination.error();
  EXPECT_EQ(combination->deformation, "sma-spring");
  EXPECT_EQ(combination->latch, "electrostatic-latch");
}

TEST(ActuatorCombination, AcceptsTheShortLatchNamesAndEitherOrder) {
  for (const auto& [text, deformation, latch] :
       {std::tuple{"sma-spring+electrostatic", "sma-spring", "electrostatic-latch"},
        std::tuple{"electro-ribbon+mechanical", "electro-ribbon", "mechanical-latch"},
        std::tuple{"electromagnetic+electro-ribbon", "electro-ribbon", "electromagnetic-latch"}}) {
    auto combination = parseCombination(text);
    ASSERT_TRUE(combination.ok()) << combination.error();
    EXPECT_EQ(combination->deformation, deformation) << text;
    EXPECT_EQ(combination->latch, latch) << text;
  }
}

TEST(ActuatorCombination, RefusesAnUnknownNameWithTheClosest) {
  EXPECT_EQ(parseCombination("sma-sprng+electrostatic").error(),
            "unknown actuator design \"sma-sprng\": did you mean \"sma-spring\"?");
  EXPECT_EQ(parseCombination("sma-spring+electrostatik").error(),
            "unknown actuator design \"electrostatik\": did you mean \"electrostatic-latch\"?");
  EXPECT_EQ(parseCombination("electroribbon+magnetic").error(),
            "unknown actuator design \"electroribbon\": did you mean \"electro-ribbon\"?");
  EXPECT_EQ(actuators::closestDesignName("mechanic"), "mechanical-latch");
}

TEST(ActuatorCombination, RefusesTwoOfAKindAndAnythingButTwoNames) {
  EXPECT_EQ(parseCombination("sma-spring+electro-ribbon").error(),
            "actuators \"sma-spring+electro-ribbon\": sma-spring and electro-ribbon are both "
            "deformation designs; a module carries one deformation design and one latch design");
  EXPECT_EQ(parseCombination("mechanical+electrostatic").error(),
            "actuators \"mechanical+electrostatic\": mechanical-latch and electrostatic-latch are "
            "both latch designs; a module carries one deformation design and one latch design");
  const std::string expected =
      "expected one deformation design and one latch design, DEFORMATION+LATCH (e.g. "
      "sma-spring+electrostatic)";
  EXPECT_EQ(parseCombination("sma-spring").error(), "actuators \"sma-spring\": " + expected);
  EXPECT_EQ(parseCombination("sma-spring+mechanical+electrostatic").error(),
            "actuators \"sma-spring+mechanical+electrostatic\": " + expected);
  EXPECT_EQ(parseCombination("+").error(),
            "unknown actuator design \"\": did you mean \"sma-spring\"?");
}

TEST(ActuatorCombination, LoadsBothDesignsOfACombination) {
  auto combination = parseCombination("electro-ribbon+electromagnetic");
  ASSERT_TRUE(combination.ok());
  const auto deformation = actuators::loadDesign(kDesignDirectory, combination->deformation);
  const auto latch = actuators::loadDesign(kDesignDirectory, combination->latch);
  ASSERT_TRUE(deformation.ok() && latch.ok());
  EXPECT_EQ(deformation->model, actuators::Model::kElectroRibbon);
  EXPECT_EQ(latch->model, actuators::Model::kElectromagneticLatch);
  EXPECT_EQ(actuators::loadDesign(kDesignDirectory, "glue").error(),
            "unknown actuator design \"glue\": did you mean \"sma-spring\"?");
}

}  // namespace
}  // namespace datomsim::testing
