// A module's parts as a triangle mesh, and the files that carry it: Wavefront OBJ, binary STL and
// binary glTF (GLB), to inspect a module in another program or to print it.
//
// The mesh dresses datom::partsLayout: each of the 43 boxes becomes 6 faces of 2 triangles, with
// 4 vertices per face so that every face has its own flat normal. Triangles turn counter-clockwise
// seen from outside. Lengths are in the unit of the radius (a module of radius 10 written as
// millimetres is 20 mm across). OBJ and STL keep the module frame (z up); GLB turns it to glTF's
// y up: (x, y, z) -> (x, z, -y).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "datom/parts.h"
#include "datomsim/result.h"
#include "geometry/vec3.h"

namespace datomsim::exporting {

enum class MeshFormat { kObj, kStl, kGlb };

// The format of a path by its extension (.obj, .stl, .glb, case-insensitive), or an error naming
// the extension and the ones known.
Result<MeshFormat> meshFormatOf(const std::filesystem::path& path);

// The triangles of one part.
struct MeshGroup {
  std::string name;  // "core", "piston 0", "link 0-2" (piston-connector), "connector 5"
  datom::PartKind kind = datom::PartKind::kCore;
  std::vector<geometry::Vec3> positions;
  std::vector<geometry::Vec3> normals;             // one per position
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into positions
};

struct Mesh {
  std::vector<MeshGroup> groups;

  size_t triangleCount() const;
  size_t vertexCount() const;
  // The smallest box holding every vertex: {min, max}.
  std::array<geometry::Vec3, 2> bounds() const;
};

// The mesh of a parts layout, one group per part, in the layout's order.
Mesh meshOfParts(const std::vector<datom::Part>& parts);

// The file contents. OBJ: one object per part, vertices, normals and faces. STL: binary, an
// 80-byte header, the triangle count, then each triangle with its normal. GLB: glTF 2.0, one mesh
// per part kind (core, pistons, links, connectors) with the paper's colours (connectors red,
// pistons blue, links green, figure "shape"), positions, normals and 32-bit indices.
std::string objText(const Mesh& mesh, const std::string& comment);
std::string stlBytes(const Mesh& mesh, const std::string& comment);
std::string glbBytes(const Mesh& mesh, const std::string& comment);

// The file's bytes in the format of `path`'s extension. `comment` goes into the file's header
// (OBJ comment, STL header, glTF asset.extras).
Result<std::string> meshBytes(const Mesh& mesh, const std::filesystem::path& path,
                              const std::string& comment);

// Writes the mesh in the format of the path's extension, atomically.
Status writeMesh(const Mesh& mesh, const std::filesystem::path& path, const std::string& comment);

}  // namespace datomsim::exporting
