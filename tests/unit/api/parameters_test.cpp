// A program's parameters: typed, defaulted, and refused with a message naming the key.
#include <gtest/gtest.h>

#include <stdexcept>

#include "datomsim/parameters.h"

namespace datomsim {
namespace {

const std::vector<Parameter> kDeclared = {
    Parameter::integer("steps", "how many steps", "10").range(1, 1000),
    Parameter::number("rate", "per second", "0.5"),
    Parameter::flag("verbose", "say more"),
    Parameter::cell("root", "where it starts"),
    Parameter::text("label", "a name", "walker"),
};

Result<Parameters> check(std::map<std::string, std::string> given) {
  return Parameters::check("walker", kDeclared, given);
}

TEST(Parameters, GivenValuesAreTypedAndTheOthersDefault) {
  const auto parameters = check({{"root", "(1, 2,3)"}, {"steps", "20"}, {"verbose", "on"}});
  ASSERT_TRUE(parameters.ok()) << parameters.error();
  EXPECT_EQ(parameters->integer("steps"), 20);
  EXPECT_DOUBLE_EQ(parameters->number("rate"), 0.5);
  EXPECT_TRUE(parameters->flag("verbose"));
  EXPECT_EQ(parameters->cell("root"), (Cell{1, 2, 3}));
  EXPECT_EQ(parameters->text("label"), "walker");
  EXPECT_TRUE(parameters->given("steps"));
  EXPECT_FALSE(parameters->given("rate"));
}

TEST(Parameters, AnUnknownKeyIsRefusedNamingItAndTheKnownOnes) {
  const auto parameters = check({{"root", "0,0,0"}, {"stepz", "3"}});
  ASSERT_FALSE(parameters.ok());
  EXPECT_EQ(parameters.error(),
            "program walker has no parameter \"stepz\" (its parameters: steps, rate, verbose, "
            "root, label)");
}

TEST(Parameters, ABadValueIsRefusedNamingTheKeyAndTheValue) {
  const std::map<std::string, std::string> cases[] = {
      {{"root", "0,0"}},
      {{"root", "0,0,0"}, {"steps", "ten"}},
      {{"root", "0,0,0"}, {"steps", "0"}},
      {{"root", "0,0,0"}, {"rate", "nan"}},
      {{"root", "0,0,0"}, {"verbose", "maybe"}},
  };
  const std::string expected[] = {
      "parameter root of program walker: \"0,0\" is not a cell x,y,z of three integers",
      "parameter steps of program walker: \"ten\" is not an integer",
      "parameter steps of program walker: \"0\" is out of its range, 1 to 1000",
      "parameter rate of program walker: \"nan\" is not a finite number",
      "parameter verbose of program walker: \"maybe\" is not a flag (true or false)",
  };
  for (size_t i = 0; i < std::size(cases); ++i) {
    const auto parameters = check(cases[i]);
    ASSERT_FALSE(parameters.ok()) << i;
    EXPECT_EQ(parameters.error(), expected[i]);
  }
}

TEST(Parameters, AMissingRequiredOneSaysHowToGiveIt) {
  const auto parameters = check({});
  ASSERT_FALSE(parameters.ok());
  EXPECT_EQ(parameters.error(),
            "program walker needs parameter root, a cell (where it starts): --param root=X,Y,Z");
}

TEST(Parameters, ReadingOneUndeclaredOrAsAnotherTypeIsAProgrammingError) {
  const auto parameters = check({{"root", "0,0,0"}});
  ASSERT_TRUE(parameters.ok());
  EXPECT_THROW((void)parameters->integer("speed"), std::logic_error);
  EXPECT_THROW((void)parameters->number("steps"), std::logic_error);
}

}  // namespace
}  // namespace datomsim
