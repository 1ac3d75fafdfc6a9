// The shapes of VisibleSim's CSG targets: a tree of OpenSCAD's primitives (cube, sphere, cylinder),
// boolean operations and transforms, and the two questions a target asks of it: is a point inside,
// and which axis-aligned box holds the shape (docs/file-formats.md, "CSG targets").
//
// Coordinates are VisibleSim's unscaled world frame: lattice spacing 1, z up. Boundaries belong to
// the shape (a point on a cube's face is inside), as in VisibleSim's CSGNode::isInside; nothing
// is rounded, so a cell centre that falls exactly on a face counts. The tree is a plain value: it
// is built by the parser (csg_parser.h) and never changes afterwards.
#pragma once

#include <array>
#include <vector>

#include "datomsim/values.h"
#include "geometry/vec3.h"

namespace datomsim::target::csg {

enum class Kind {
  // Groups, with one or more children.
  kUnion,
  kIntersection,
  kDifference,  // the first child minus all the others
  // Transforms of one child (color only paints it).
  kTranslate,
  kRotate,
  kScale,
  kColor,
  // Primitives, without children.
  kCube,
  kSphere,
  kCylinder,  // a cone when its two radii differ
};

// A closed axis-aligned box. An intersection of disjoint boxes is empty: low > high on some axis.
struct Box {
  geometry::Vec3 low;
  geometry::Vec3 high;

  bool empty() const { return low.x > high.x || low.y > high.y || low.z > high.z; }
  bool operator==(const Box&) const = default;
};

// A rotation as the rows of a 3x3 matrix, applied to column vectors.
using Matrix = std::array<geometry::Vec3, 3>;

struct Node {
  Kind kind = Kind::kUnion;
  // translate: the offset; rotate: the angles in degrees; scale: the factors; cube: the size.
  geometry::Vec3 vector;
  // rotate: the matrix of `vector` (rotationMatrix), computed once when the node is built.
  Matrix rotation{};
  // sphere: the radius in radius1; cylinder: height, bottom radius1 and top radius2.
  double height = 0;
  double radius1 = 0;
  double radius2 = 0;
  // cube and cylinder: centred on the origin instead of starting at it.
  bool centred = false;
  // color: the colour it paints its child with, 0..255 per component as VisibleSim reads it.
  Color color;
  std::vector<Node> children;
};

// OpenSCAD's rotate([ax, ay, az]), angles in degrees: about x first, then y, then z, so the matrix
// is Rz * Ry * Rx. Sines and cosines of multiples of 90 degrees are exact (0 or +-1), so that the
// quarter turns targets are made of map lattice points onto lattice points.
Matrix rotationMatrix(const geometry::Vec3& degrees);

// The nodes of the tree, itself included: what one containment test may visit at most.
size_t nodeCount(const Node& node);

// Whether `point` lies in the shape (boundaries included).
bool contains(const Node& node, const geometry::Vec3& point);

// The box VisibleSim computes for a shape (TargetCSG's boundingBox), as docs/file-formats.md
// defines it: union, the hull of its children's boxes; intersection, the intersection of their
// boxes; difference, its first child's box; translate, scale and rotate move their child's box
// (rotate: the box of its 8 rotated corners); color, its child's box. The shape always lies in it.
Box boundingBox(const Node& node);

}  // namespace datomsim::target::csg
