#include "export/mesh.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

#include "common/atomic_file.h"

namespace datomsim::exporting {
namespace {

using geometry::Vec3;

constexpr std::array<const char*, 4> kKindNames = {"core", "piston", "link", "connector"};

// Colours of the GLB materials (linear RGB): the paper's figure "shape" draws connectors red,
// pistons blue and links green; the core is light grey.
constexpr std::array<std::array<double, 3>, 4> kKindColors = {{
    {0.60, 0.60, 0.62},
    {0.05, 0.18, 0.80},
    {0.05, 0.55, 0.10},
    {0.75, 0.03, 0.03},
}};

std::string partName(const datom::Part& part) {
  switch (part.kind) {
    case datom::PartKind::kCore:
      return "core";
    case datom::PartKind::kPiston:
      return fmt::format("piston {}", part.piston);
    case datom::PartKind::kLink:
      return fmt::format("link {}-{}", part.piston, part.connector);
    case datom::PartKind::kConnector:
      return fmt::format("connector {}", part.connector);
  }
  return "part";
}

// Appends the 6 faces of a box: for each axis k and side, the face's 4 corners counter-clockwise
// seen from outside (axis i x axis j = axis k for the cyclic pair), and 2 triangles.
void appendBox(const datom::Part& part, MeshGroup& group) {
  const std::array<Vec3, 3> half = {part.axes[0] * (part.size[0] / 2),
                                    part.axes[1] * (part.size[1] / 2),
                                    part.axes[2] * (part.size[2] / 2)};
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3;
    const int j = (k + 2) % 3;
    for (const double side : {1.0, -1.0}) {
      const Vec3 centre = part.centre + half[k] * side;
      const Vec3 normal = part.axes[k] * side;
      // Swapping i and j on the negative side keeps the turn counter-clockwise from outside.
      const Vec3 a = side > 0 ? half[i] : half[j];
      const Vec3 b = side > 0 ? half[j] : half[i];
      const auto first = static_cast<uint32_t>(group.positions.size());
      for (const Vec3& corner : {centre - a - b, centre + a - b, centre + a + b, centre - a + b}) {
        group.positions.push_back(corner);
        group.normals.push_back(normal);
      }
      group.triangles.push_back({first, first + 1, first + 2});
      group.triangles.push_back({first, first + 2, first + 3});
    }
  }
}

std::string number(double value) {
  if (std::abs(value) < 5e-10) value = 0;
  return fmt::format("{:.7g}", value);
}

// Little-endian binary output, whatever the host.
void putU32(std::string& out, uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8)
    out.push_back(static_cast<char>((value >> shift) & 0xff));
}

void putU16(std::string& out, uint16_t value) {
  out.push_back(static_cast<char>(value & 0xff));
  out.push_back(static_cast<char>(value >> 8));
}

void putF32(std::string& out, double value) {
  putU32(out, std::bit_cast<uint32_t>(static_cast<float>(value)));
}

Vec3 yUp(const Vec3& v) {
  return {v.x, v.z, -v.y};
}

// The glTF JSON and binary buffer of a mesh: per part kind, positions, normals, indices.
struct GltfParts {
  nlohmann::ordered_json json;
  std::string buffer;
};

GltfParts gltf(const Mesh& mesh, const std::string& comment) {
  using Gltf = nlohmann::ordered_json;
  GltfParts out;
  Gltf nodes = Gltf::array(), meshes = Gltf::array(), materials = Gltf::array();
  Gltf views = Gltf::array(), accessors = Gltf::array();
  constexpr int kFloat = 5126, kUnsignedInt = 5125, kArrayBuffer = 34962, kElementBuffer = 34963;

  auto addView = [&](const std::string& bytes, int target) {
    const size_t offset = out.buffer.size();
    out.buffer += bytes;
    while (out.buffer.size() % 4 != 0) out.buffer.push_back('\0');
    views.push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}, {"target", target}});
    return views.size() - 1;
  };

  for (size_t kind = 0; kind < kKindNames.size(); ++kind) {
    std::string positions, normals, indices;
    std::array<double, 3> low{}, high{};
    low.fill(std::numeric_limits<double>::max());
    high.fill(std::numeric_limits<double>::lowest());
    uint32_t base = 0, count = 0, indexCount = 0;
    for (const MeshGroup& group : mesh.groups) {
      if (static_cast<size_t>(group.kind) != kind) continue;
      for (size_t v = 0; v < group.positions.size(); ++v) {
        const Vec3 p = yUp(group.positions[v]);
        const Vec3 n = yUp(group.normals[v]);
        const std::array<double, 3> coordinates = {p.x, p.y, p.z};
        for (int axis = 0; axis < 3; ++axis) {
          // min and max must be those of the float32 data.
          const double value = static_cast<float>(coordinates[axis]);
          low[axis] = std::min(low[axis], value);
          high[axis] = std::max(high[axis], value);
          putF32(positions, coordinates[axis]);
        }
        putF32(normals, n.x);
        putF32(normals, n.y);
        putF32(normals, n.z);
      }
      for (const auto& triangle : group.triangles) {
        for (const uint32_t index : triangle) putU32(indices, base + index);
        indexCount += 3;
      }
      base += static_cast<uint32_t>(group.positions.size());
      count += static_cast<uint32_t>(group.positions.size());
    }
    if (count == 0) continue;
    const size_t positionView = addView(positions, kArrayBuffer);
    const size_t normalView = addView(normals, kArrayBuffer);
    const size_t indexView = addView(indices, kElementBuffer);
    const size_t first = accessors.size();
    accessors.push_back({{"bufferView", positionView},
                         {"componentType", kFloat},
                         {"count", count},
                         {"type", "VEC3"},
                         {"min", low},
                         {"max", high}});
    accessors.push_back({{"bufferView", normalView},
                         {"componentType", kFloat},
                         {"count", count},
                         {"type", "VEC3"}});
    accessors.push_back({{"bufferView", indexView},
                         {"componentType", kUnsignedInt},
                         {"count", indexCount},
                         {"type", "SCALAR"}});
    const auto& color = kKindColors[kind];
    materials.push_back({{"name", kKindNames[kind]},
                         {"pbrMetallicRoughness",
                          {{"baseColorFactor", {color[0], color[1], color[2], 1.0}},
                           {"metallicFactor", 0.0},
                           {"roughnessFactor", 0.6}}}});
    meshes.push_back({{"name", kKindNames[kind]},
                      {"primitives",
                       {{{"attributes", {{"POSITION", first}, {"NORMAL", first + 1}}},
                         {"indices", first + 2},
                         {"material", materials.size() - 1}}}}});
    nodes.push_back({{"name", kKindNames[kind]}, {"mesh", meshes.size() - 1}});
  }

  Gltf sceneNodes = Gltf::array();
  for (size_t n = 0; n < nodes.size(); ++n) sceneNodes.push_back(n);
  out.json = {{"asset", {{"version", "2.0"}, {"generator", "datomsim mesh"}}},
              {"scene", 0},
              {"scenes", {{{"nodes", sceneNodes}}}},
              {"nodes", nodes},
              {"meshes", meshes},
              {"materials", materials},
              {"buffers", {{{"byteLength", out.buffer.size()}}}},
              {"bufferViews", views},
              {"accessors", accessors}};
  out.json["asset"]["extras"] = {{"comment", comment}};
  return out;
}

}  // namespace

Result<MeshFormat> meshFormatOf(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return MeshFormat::kObj;
  if (extension == ".stl") return MeshFormat::kStl;
  if (extension == ".glb") return MeshFormat::kGlb;
  return Error{fmt::format("{}: unknown mesh format '{}': use .obj, .stl or .glb", path.string(),
                           extension)};
}

size_t Mesh::triangleCount() const {
  size_t count = 0;
  for (const MeshGroup& group : groups) count += group.triangles.size();
  return count;
}

size_t Mesh::vertexCount() const {
  size_t count = 0;
  for (const MeshGroup& group : groups) count += group.positions.size();
  return count;
}

std::array<Vec3, 2> Mesh::bounds() const {
  constexpr double kBig = std::numeric_limits<double>::max();
  Vec3 low{kBig, kBig, kBig}, high{-kBig, -kBig, -kBig};
  for (const MeshGroup& group : groups) {
    for (const Vec3& p : group.positions) {
      low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
  }
  return {low, high};
}

Mesh meshOfParts(const std::vector<datom::Part>& parts) {
  Mesh mesh;
  mesh.groups.reserve(parts.size());
  for (const datom::Part& part : parts) {
    MeshGroup group;
    group.name = partName(part);
    group.kind = part.kind;
    appendBox(part, group);
    mesh.groups.push_back(std::move(group));
  }
  return mesh;
}

std::string objText(const Mesh& mesh, const std::string& comment) {
  std::string out;
  auto sink = std::back_inserter(out);
  fmt::format_to(sink, "# {}\n# {} parts, {} vertices, {} triangles\n", comment, mesh.groups.size(),
                 mesh.vertexCount(), mesh.triangleCount());
  size_t base = 1;  // OBJ indices start at 1 and run over the whole file
  for (const MeshGroup& group : mesh.groups) {
    std::string name = group.name;
    std::replace(name.begin(), name.end(), ' ', '_');
    fmt::format_to(sink, "o {}\n", name);
    for (const Vec3& p : group.positions) {
      fmt::format_to(sink, "v {} {} {}\n", number(p.x), number(p.y), number(p.z));
    }
    for (const Vec3& n : group.normals) {
      fmt::format_to(sink, "vn {} {} {}\n", number(n.x), number(n.y), number(n.z));
    }
    for (const auto& t : group.triangles) {
      fmt::format_to(sink, "f {0}//{0} {1}//{1} {2}//{2}\n", base + t[0], base + t[1], base + t[2]);
    }
    base += group.positions.size();
  }
  return out;
}

std::string stlBytes(const Mesh& mesh, const std::string& comment) {
  std::string out;
  // The header must not start with "solid", which would announce an ASCII STL.
  std::string header = "datomsim mesh: " + comment;
  header.resize(80, ' ');
  out += header;
  putU32(out, static_cast<uint32_t>(mesh.triangleCount()));
  for (const MeshGroup& group : mesh.groups) {
    for (const auto& t : group.triangles) {
      const Vec3& n = group.normals[t[0]];
      for (const double value : {n.x, n.y, n.z}) putF32(out, value);
      for (const uint32_t index : t) {
        const Vec3& p = group.positions[index];
        for (const double value : {p.x, p.y, p.z}) putF32(out, value);
      }
      putU16(out, 0);
    }
  }
  return out;
}

std::string glbBytes(const Mesh& mesh, const std::string& comment) {
  const GltfParts parts = gltf(mesh, comment);
  std::string json = parts.json.dump();
  while (json.size() % 4 != 0) json.push_back(' ');
  constexpr uint32_t kMagic = 0x46546C67;  // "glTF"
  constexpr uint32_t kJsonChunk = 0x4E4F534A;
  constexpr uint32_t kBinChunk = 0x004E4942;
  const size_t total = 12 + 8 + json.size() + 8 + parts.buffer.size();
  std::string out;
  out.reserve(total);
  putU32(out, kMagic);
  putU32(out, 2);
  putU32(out, static_cast<uint32_t>(total));
  putU32(out, static_cast<uint32_t>(json.size()));
  putU32(out, kJsonChunk);
  out += json;
  putU32(out, static_cast<uint32_t>(parts.buffer.size()));
  putU32(out, kBinChunk);
  out += parts.buffer;
  return out;
}

Result<std::string> meshBytes(const Mesh& mesh, const std::filesystem::path& path,
                              const std::string& comment) {
  const auto format = meshFormatOf(path);
  if (!format) return Error{format.error()};
  switch (*format) {
    case MeshFormat::kObj:
      return objText(mesh, comment);
    case MeshFormat::kStl:
      return stlBytes(mesh, comment);
    case MeshFormat::kGlb:
      return glbBytes(mesh, comment);
  }
  return Error{"unknown mesh format"};
}

Status writeMesh(const Mesh& mesh, const std::filesystem::path& path, const std::string& comment) {
  const Result<std::string> bytes = meshBytes(mesh, path, comment);
  if (!bytes) return Error{bytes.error()};
  return writeFileAtomically(path, *bytes);
}

}  // namespace datomsim::exporting
