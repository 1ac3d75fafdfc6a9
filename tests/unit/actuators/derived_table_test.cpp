// The tables of docs/actuators.md are the code's: written again from the shipped designs at
// r = 1 mm, 1 cm and 10 cm (t = r / 10) and compared with the page's, between its markers.
#include "actuators/derived_table.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "actuator_files.h"

namespace datomsim::testing {
namespace {

const std::filesystem::path kPage =
    std::filesystem::path(DATOMSIM_SOURCE_DIR) / "docs" / "actuators.md";

std::vector<actuators::Design> shippedDesigns() {
  std::vector<actuators::Design> designs;
  for (const char* name : {"sma-spring", "electro-ribbon", "mechanical-latch",
                           "electromagnetic-latch", "electrostatic-latch"}) {
    designs.push_back(shippedDesign(name));
  }
  return designs;
}

// Compares the page's text between "<!-- NAME: begin (tests/unit/actuators) -->" and
// "<!-- NAME: end -->" with `generated`. With DATOMSIM_WRITE_ACTUATOR_DOCS=1 in the environment
// it writes `generated` there instead: the way the page's tables are made.
void expectBlock(const std::string& name, const std::string& generated) {
  std::ifstream in(kPage);
  std::ostringstream text;
  text << in.rdbuf();
  std::string page = text.str();
  const std::string beginMarker = "<!-- " + name + ": begin (tests/unit/actuators) -->\n";
  const std::string endMarker = "<!-- " + name + ": end -->";
  const size_t begin = page.find(beginMarker);
  const size_t end = page.find(endMarker);
  ASSERT_NE(begin, std::string::npos) << beginMarker;
  ASSERT_NE(end, std::string::npos) << endMarker;
  const size_t from = begin + beginMarker.size();
  const char* write = std::getenv("DATOMSIM_WRITE_ACTUATOR_DOCS");
  if (write != nullptr && std::string_view(write) == "1") {
    page.replace(from, end - from, generated);
    std::ofstream(kPage, std::ios::binary) << page;
    return;
  }
  EXPECT_EQ(page.substr(from, end - from), generated)
      << "docs/actuators.md's " << name << " should be (or run this test with "
      << "DATOMSIM_WRITE_ACTUATOR_DOCS=1):\n"
      << generated;
}

TEST(DerivedTables, TheDocsShowWhatTheLawsGive) {
  constexpr std::array kRadii = {0.001, 0.01, 0.1};
  expectBlock("derived tables", actuators::derivedTablesMarkdown(shippedDesigns(), kRadii, 0.1));
}

TEST(DerivedTables, TheDocsListTheFiguresOfTheFiles) {
  expectBlock("design figures", actuators::designFiguresMarkdown(shippedDesigns()));
}

TEST(DerivedTables, EveryDesignHasItsRowsAtEverySize) {
  const auto design = shippedDesign("electrostatic");
  const auto rows = actuators::derivedQuantities(design, sizeOf(0.01));
  ASSERT_EQ(rows.size(), 8u);
  EXPECT_EQ(rows[0].name, "holding force");
  EXPECT_NEAR(rows[0].value, 0.4122802052473332, 1e-12);
  EXPECT_EQ(rows[0].unit, "N");
  // Force margin: 0.412 N over twice the 17.2 mN weight.
  EXPECT_NEAR(rows[1].value, 0.4122802052473332 / (2 * 0.017203059458131283), 1e-9);
}

}  // namespace
}  // namespace datomsim::testing
