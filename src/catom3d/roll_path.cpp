#include "catom3d/roll_path.h"

namespace datomsim::catom3d {

using geometry::Vec3;

RollAxis rollAxis(const Vec3& pivot, const Vec3& start, const Vec3& goal) {
  return {geometry::normalized(geometry::cross(start - pivot, goal - pivot)),
          (pivot + start + goal) * (1.0 / 3.0)};
}

}  // namespace datomsim::catom3d
