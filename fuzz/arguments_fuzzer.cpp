// The parsers of values users type: cells and seeds on the command line, program parameters of
// every type, and CSG targets. Each accepts or refuses with a message; nothing else may happen.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>

#include "datomsim/parameters.h"
#include "frontend/arguments.h"
#include "frontend/usage_error.h"
#include "target/csg_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)datomsim::frontend::parseCell("--goal", text);
  } catch (const datomsim::frontend::UsageError&) {
  }
  try {
    (void)datomsim::frontend::parseSeed("--seed", text);
  } catch (const datomsim::frontend::UsageError&) {
  }
  using datomsim::Parameter;
  static const std::vector<Parameter> declared = {
      Parameter::integer("i", "", "1").range(-5, 5), Parameter::number("n", "", "0"),
      Parameter::flag("f", ""), Parameter::cell("c", "", "0,0,0"), Parameter::text("t", "", "x")};
  for (const Parameter& parameter : declared) {
    const auto checked = datomsim::Parameters::check("fuzz", declared, {{parameter.name, text}});
    if (!checked.ok() && checked.error().empty()) std::abort();
  }
  const auto csg = datomsim::target::csg::parse(text);
  (void)csg;
  return 0;
}
