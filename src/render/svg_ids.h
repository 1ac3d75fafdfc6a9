// Making cairo's SVG files the same bytes for the same picture, whatever else the process drew.
#pragma once

#include <string>

namespace datomsim::render {

// Cairo names each SVG group after its surface's process-wide serial number ("surface126"), so
// the same picture drawn twice in one process (or after another picture) would differ. Renumbers
// them in order of first appearance; the names only appear as id="surfaceN" and references
// "#surfaceN".
void renumberSurfaceIds(std::string& svg);

}  // namespace datomsim::render
