// VisibleSim's XML reader on any bytes: it refuses with a message or reads a scene; a scene it
// writes back as XML (when XML can hold it) reads again to the same modules. Its fast path and
// the general reader alone give the same scene or the same error.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "io/visiblesim_xml.h"
#include "io/visiblesim_xml_detail.h"
#include "same_outcome.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto scene = datomsim::io::parseVisibleSimXml(text, "fuzz.xml");
  if (!sameOutcome(scene, datomsim::io::detail::readVisibleSimXmlGeneral(text, "fuzz.xml"))) {
    std::abort();
  }
  if (!scene.ok()) {
    if (scene.error().empty()) std::abort();
    return 0;
  }
  const auto written = datomsim::io::toVisibleSimXml(*scene);
  if (!written.ok()) return 0;  // refused with a reason (text XML cannot hold, say)
  const auto again = datomsim::io::parseVisibleSimXml(*written, "again.xml");
  if (!again.ok() || again->world.size() != scene->world.size()) std::abort();
  return 0;
}
