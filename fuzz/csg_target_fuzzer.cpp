// A CSG target on any text: it parses, or refuses with a message; placed in the lattice, its
// cells are listed within the bounds of docs/limits.md, or refused with a message. The cells it
// lists are exactly those it says it contains, counted alike. Scans above a million containment
// tests are left to the bound's own test (tests/unit/target), to keep each input fast.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "target/csg.h"
#include "target/target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using datomsim::target::Target;
  namespace csg = datomsim::target::csg;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto target = Target::csg(text);
  if (!target.ok()) {
    if (target.error().empty()) std::abort();  // a refusal always says why
    return 0;
  }
  // Membership never fails, wherever the cell.
  for (const datomsim::geometry::Cell cell :
       {datomsim::geometry::Cell{0, 0, 0}, datomsim::geometry::Cell{-5, 3, 2},
        datomsim::geometry::Cell{1000000, -1000000, 7}}) {
    (void)target->contains(cell);
  }
  const csg::Box box = csg::boundingBox(target->csgShape());
  const double volume =
      (box.high.x - box.low.x + 4) * (box.high.y - box.low.y + 4) * (box.high.z - box.low.z + 4);
  if (!(volume * double(csg::nodeCount(target->csgShape())) <= 1e6)) return 0;
  const auto cells = target->cells();
  const auto count = target->count();
  if (cells.ok() != count.ok()) std::abort();
  if (!cells.ok()) {
    if (cells.error().empty() || cells.error() != count.error()) std::abort();
    return 0;
  }
  if (cells->size() != *count) std::abort();
  for (const auto& cell : *cells) {
    if (!target->contains(cell)) std::abort();
  }
  return 0;
}
