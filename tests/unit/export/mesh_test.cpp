#include "export/mesh.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>

#include "datom/dimensions.h"
#include "geometry/lattice.h"
#include "support/temporary_directory.h"

namespace datomsim::exporting {
namespace {

using geometry::Vec3;

constexpr double kThickness = 0.1;

Mesh meshOf(int piston, double fraction, double radius = 1.0, double thickness = kThickness) {
  const auto dimensions = datom::dimensionsFor(radius, thickness);
  EXPECT_TRUE(dimensions.ok());
  const auto parts = datom::partsLayout(*dimensions, piston, fraction);
  EXPECT_TRUE(parts.ok()) << parts.error();
  return meshOfParts(*parts);
}

uint32_t u32At(const std::string& bytes, size_t offset) {
  uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = (value << 8) | static_cast<unsigned char>(bytes[offset + k]);
  return value;
}

float f32At(const std::string& bytes, size_t offset) {
  return std::bit_cast<float>(u32At(bytes, offset));
}

// The largest projection of the mesh's vertices on a unit direction.
double extentAlong(const Mesh& mesh, const Vec3& direction) {
  double best = -1e9;
  for (const MeshGroup& group : mesh.groups) {
    for (const Vec3& p : group.positions) best = std::max(best, geometry::dot(p, direction));
  }
  return best;
}

TEST(Mesh, HasOneGroupOfTwelveTrianglesPerPart) {
  const Mesh mesh = meshOf(geometry::kNoAxis, 0);
  ASSERT_EQ(mesh.groups.size(), 43u);
  EXPECT_EQ(mesh.triangleCount(), 43u * 12);
  EXPECT_EQ(mesh.vertexCount(), 43u * 24);
  EXPECT_EQ(mesh.groups[0].name, "core");
  EXPECT_EQ(mesh.groups[1].name, "piston 0");
  EXPECT_EQ(mesh.groups[7].name, "link 0-0");
  EXPECT_EQ(mesh.groups[42].name, "connector 11");
}

TEST(Mesh, TurnsEveryTriangleCounterClockwiseSeenFromOutside) {
  for (const MeshGroup& group : meshOf(0, 0.5).groups) {
    for (const auto& t : group.triangles) {
      const Vec3 a = group.positions[t[0]], b = group.positions[t[1]], c = group.positions[t[2]];
      const Vec3 n = geometry::cross(b - a, c - a);
      EXPECT_GT(geometry::dot(n, group.normals[t[0]]), 0) << group.name;
      EXPECT_NEAR(geometry::norm(group.normals[t[0]]), 1, 1e-9);
    }
  }
}

TEST(Mesh, SpansTwoRadiiBetweenTheFacesOfOppositeConnectorsAtRest) {
  // Connectors 0 and 6 touch their neighbours at x = +-r; pistons 4 and 5 reach
  // (r + c/2)/sqrt2 + t/2 up and down. The links' boxes stand out of the contact planes by
  // t/(2 sqrt2) at their hinges (datom/parts.h: the boxes overlap at the hinges).
  for (const double radius : {1.0, 10.0}) {
    const double t = kThickness * radius;
    const Mesh mesh = meshOf(geometry::kNoAxis, 0, radius, t);
    Mesh connectors;
    for (const MeshGroup& group : mesh.groups) {
      if (group.kind == datom::PartKind::kConnector) connectors.groups.push_back(group);
    }
    const auto [low, high] = connectors.bounds();
    EXPECT_NEAR(high.x, radius, 1e-9);
    EXPECT_NEAR(low.x, -radius, 1e-9);
    EXPECT_NEAR(high.y - low.y, 2 * radius, 1e-9);
    const auto [allLow, allHigh] = mesh.bounds();
    EXPECT_NEAR(allHigh.x - allLow.x, 2 * radius + t / std::sqrt(2.0), 1e-9);
    const double c = datom::dimensionsFor(radius, 0).value().connectorWidth();
    EXPECT_NEAR(allHigh.z, (radius + c / 2) / std::sqrt(2.0) + t / 2, 1e-9);
    EXPECT_NEAR(allLow.z, -allHigh.z, 1e-9);
  }
}

TEST(Mesh, ShrinksAlongACompressedPistonToItsConnectorsPlane) {
  // Paper III.B: fully compressed, the four connectors lie in the plane at c/2 + e from the
  // centre, perpendicular to the piston.
  const auto d = *datom::dimensionsFor(1.0, kThickness);
  const Vec3 u = geometry::axisVector(0);
  const double rest = extentAlong(meshOf(geometry::kNoAxis, 0), u);
  EXPECT_NEAR(rest, (1 + d.connectorWidth() / 2) / std::sqrt(2.0) + kThickness / 2, 1e-9);
  EXPECT_NEAR(extentAlong(meshOf(0, 1), u), d.connectorWidth() / 2 + d.linkLength(), 1e-6);
  const double half = extentAlong(meshOf(0, 0.5), u);
  EXPECT_LT(half, rest);
  EXPECT_GT(half, d.connectorWidth() / 2 + d.linkLength());
  // The opposite side does not move.
  EXPECT_NEAR(extentAlong(meshOf(0, 1), -u), rest, 1e-9);
}

TEST(Obj, ListsVerticesNormalsAndFacesOfEveryPart) {
  const std::string text = objText(meshOf(geometry::kNoAxis, 0), "unit test");
  std::istringstream lines(text);
  std::string line;
  int objects = 0, vertices = 0, normals = 0, faces = 0;
  size_t largestIndex = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("o ", 0) == 0) ++objects;
    if (line.rfind("v ", 0) == 0) ++vertices;
    if (line.rfind("vn ", 0) == 0) ++normals;
    if (line.rfind("f ", 0) == 0) {
      ++faces;
      std::istringstream corners(line.substr(2));
      std::string corner;
      while (corners >> corner) largestIndex = std::max(largestIndex, std::stoul(corner));
    }
  }
  EXPECT_EQ(text.rfind("# unit test\n", 0), 0u);
  EXPECT_EQ(objects, 43);
  EXPECT_EQ(vertices, 43 * 24);
  EXPECT_EQ(normals, 43 * 24);
  EXPECT_EQ(faces, 43 * 12);
  EXPECT_EQ(largestIndex, 43u * 24);
  EXPECT_NE(text.find("o connector_11\n"), std::string::npos);
}

TEST(Stl, IsBinaryWithOneRecordPerTriangle) {
  const Mesh mesh = meshOf(4, 0.75);
  const std::string bytes = stlBytes(mesh, "unit test");
  ASSERT_EQ(bytes.size(), 84 + 50 * mesh.triangleCount());
  EXPECT_NE(bytes.rfind("solid", 0), 0u) << "a binary STL must not start like an ASCII one";
  EXPECT_EQ(u32At(bytes, 80), mesh.triangleCount());
  // The first record: normal and first vertex of the core's first triangle.
  const MeshGroup& core = mesh.groups[0];
  EXPECT_FLOAT_EQ(f32At(bytes, 84), static_cast<float>(core.normals[0].x));
  EXPECT_FLOAT_EQ(f32At(bytes, 84 + 12), static_cast<float>(core.positions[0].x));
  EXPECT_FLOAT_EQ(f32At(bytes, 84 + 20), static_cast<float>(core.positions[0].z));
}

TEST(Glb, HasAValidHeaderJsonChunkAndBuffer) {
  const Mesh mesh = meshOf(geometry::kNoAxis, 0);
  const std::string bytes = glbBytes(mesh, "unit test");
  ASSERT_GE(bytes.size(), 28u);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(u32At(bytes, 4), 2u);
  EXPECT_EQ(u32At(bytes, 8), bytes.size());
  const uint32_t jsonLength = u32At(bytes, 12);
  EXPECT_EQ(bytes.substr(16, 4), std::string("JSON"));
  EXPECT_EQ(jsonLength % 4, 0u);
  const auto json = nlohmann::json::parse(bytes.substr(20, jsonLength));
  const size_t binHeader = 20 + jsonLength;
  const uint32_t binLength = u32At(bytes, binHeader);
  EXPECT_EQ(bytes.substr(binHeader + 4, 4), std::string("BIN\0", 4));
  EXPECT_EQ(binHeader + 8 + binLength, bytes.size());

  EXPECT_EQ(json["asset"]["version"], "2.0");
  EXPECT_EQ(json["buffers"][0]["byteLength"], binLength);
  ASSERT_EQ(json["meshes"].size(), 4u);
  EXPECT_EQ(json["meshes"][3]["name"], "connector");
  EXPECT_EQ(json["nodes"].size(), 4u);
  size_t triangles = 0, vertices = 0;
  for (const auto& m : json["meshes"]) {
    const auto& primitive = m["primitives"][0];
    const auto& position = json["accessors"][primitive["attributes"]["POSITION"].get<size_t>()];
    const auto& indices = json["accessors"][primitive["indices"].get<size_t>()];
    vertices += position["count"].get<size_t>();
    triangles += indices["count"].get<size_t>() / 3;
    EXPECT_EQ(position["min"].size(), 3u);
    // Every view lies inside the buffer.
    for (const auto& accessor : {position, indices}) {
      const auto& view = json["bufferViews"][accessor["bufferView"].get<size_t>()];
      EXPECT_LE(view["byteOffset"].get<size_t>() + view["byteLength"].get<size_t>(), binLength);
    }
  }
  EXPECT_EQ(triangles, mesh.triangleCount());
  EXPECT_EQ(vertices, mesh.vertexCount());
  // Turned to y up: the module's z extent is glTF's y extent.
  const auto [low, high] = mesh.bounds();
  const auto& core = json["accessors"][0];
  EXPECT_LE(core["max"][1].get<double>(), high.z + 1e-6);
  (void)low;
}

TEST(MeshFiles, ChoosesTheFormatByExtensionAndRefusesOthers) {
  EXPECT_EQ(*meshFormatOf("a/b.OBJ"), MeshFormat::kObj);
  EXPECT_EQ(*meshFormatOf("b.stl"), MeshFormat::kStl);
  EXPECT_EQ(*meshFormatOf("b.glb"), MeshFormat::kGlb);
  const auto refused = meshFormatOf("part.ply");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error(), "part.ply: unknown mesh format '.ply': use .obj, .stl or .glb");
  EXPECT_FALSE(meshFormatOf("noextension").ok());
}

TEST(MeshFiles, WritesAtomicallyAndLeavesNothingOnError) {
  testing::TemporaryDirectory directory;
  const Mesh mesh = meshOf(geometry::kNoAxis, 0);
  ASSERT_TRUE(writeMesh(mesh, directory.path() / "m.stl", "c").ok());
  ASSERT_TRUE(writeMesh(mesh, directory.path() / "m.glb", "c").ok());
  ASSERT_TRUE(writeMesh(mesh, directory.path() / "m.obj", "c").ok());
  EXPECT_EQ(directory.fileNames(), (std::vector<std::string>{"m.glb", "m.obj", "m.stl"}));
  EXPECT_EQ(testing::readText(directory.path() / "m.stl").size(), 84 + 50 * 516u);
  EXPECT_FALSE(writeMesh(mesh, directory.path() / "m.ply", "c").ok());
  const Status missing = writeMesh(mesh, directory.path() / "no" / "m.obj", "c");
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("m.obj"), std::string::npos) << missing.error();
  EXPECT_EQ(directory.fileNames().size(), 3u);
}

}  // namespace
}  // namespace datomsim::exporting
