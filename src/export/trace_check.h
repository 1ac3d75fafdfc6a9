// The checks the viewer makes of a trace (viewer/src/trace.js: checkHeader, checkEvent), made
// here too, with the same messages, so that `datomsim view` refuses exactly what the page would
// refuse, naming the line. Both are held to one table of cases
// (viewer/test/fixtures/trace-cases.json), read by the C++ tests and the viewer's.
#pragma once

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "datomsim/result.h"

namespace datomsim::exporting {

// One JSON document a page holds besides the trace (a distance map, latch loads): refused, naming
// `name` (and the line), when nested deeper than 32 levels, when it holds a NUL byte (nlohmann
// would take it for the end of the text) or when it is no JSON.
Result<nlohmann::json> parseDocument(const std::string& text, const std::string& name);

// What is wrong with a trace's header, or an empty string.
std::string headerProblem(const nlohmann::json& header);

// What is wrong with one change after the header (`ids`: the header's module ids), or an empty
// string. Changes of kinds the format does not know are accepted (a later format may add them).
std::string changeProblem(const nlohmann::json& change, const std::set<double>& ids);

}  // namespace datomsim::exporting
