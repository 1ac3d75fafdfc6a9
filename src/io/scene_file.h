// Reading and writing scene files, whatever their format: the entry point for the command line.
//
// The format follows the file's extension: .xml is VisibleSim's XML (visiblesim_xml.h), .json the
// project's versioned JSON (json_scene.h). Writing is atomic (atomic_file.h): a failed write
// leaves no file behind and an existing file untouched.
#pragma once

#include <cstdio>
#include <filesystem>

#include "datomsim/result.h"
#include "io/scene.h"

namespace datomsim::io {

enum class SceneFormat { kVisibleSimXml, kJson };

// An XML scene is read whole into memory: at most this many bytes (about 25 million blocks).
inline constexpr size_t kMaxXmlSceneBytes = 2'000'000'000;

// The format of a path by its extension (case-insensitive), or an error naming the extension.
Result<SceneFormat> sceneFormatOf(const std::filesystem::path& path);

// Reads a scene file; errors name the path as given.
Result<Scene> readScene(const std::filesystem::path& path);

// Writes a scene file in the format of its extension, atomically.
Status writeScene(const Scene& scene, const std::filesystem::path& path);
// The same into an open file, in the format `path`'s extension names (a command's outputs are
// opened in one place: frontend/output_file.h).
Status writeScene(const Scene& scene, const std::filesystem::path& path, std::FILE* file);

}  // namespace datomsim::io
