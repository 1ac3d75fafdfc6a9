// The values of a studio request's fields, checked: each refusal is a frontend::UsageError that
// names the field and what it holds ("\"seed\" must be text, got number").
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "datomsim/values.h"
#include "geometry/cell.h"

namespace datomsim::studio {

// "text" for a string, else JSON's name of the value's type ("number", "object", ...).
std::string typeName(const nlohmann::json& value);

// The field's text, number, integer or boolean; the field must be there.
const std::string& text(const nlohmann::json& request, const char* key);
double number(const nlohmann::json& request, const char* key);
int64_t integer(const nlohmann::json& request, const char* key);
bool flag(const nlohmann::json& request, const char* key);

// A colour as three integers 0..255, [r, g, b], or as a page's colour input gives it, "#rrggbb".
Color colorOf(const nlohmann::json& request, const char* key);

// A seed as text, or as an integer (a page's number field): as the command line spells it.
std::string seedOf(const nlohmann::json& request);

// A cell as the command line types it ("x,y,z") or as three integers.
geometry::Cell cellOf(const nlohmann::json& request, const char* key);

}  // namespace datomsim::studio
