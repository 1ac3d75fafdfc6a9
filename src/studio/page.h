// The studio's page: the viewer's script (viewer/, the same bundle as `datomsim view`'s pages),
// started in its studio mode, which talks to the server over its socket (docs/studio.md).
#pragma once

#include <string>

namespace datomsim::studio {

std::string studioPage(const std::string& viewerBundle);

}  // namespace datomsim::studio
