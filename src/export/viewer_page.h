// Pages of the browser viewer (viewer/, docs/viewer.md): one self-contained HTML file per trace or
// scene, that works offline from disk.
//
// A page holds three things inline: the trace (JSON Lines, in a <script type="application/x-ndjson"
// id="datomsim-trace"> element), optionally a distance map with a path (JSON, id
// "datomsim-overlay"), and the viewer itself, the script viewer/build.mjs bundles with three.js
// (viewer.bundle.js). The bundle is a build product: the build puts it next to the datomsim binary
// when Node.js and viewer/node_modules are there, and writers find it from the binary's location
// or from an explicit path, never from the current directory.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "world/module_kind.h"
#include "world/world.h"

namespace datomsim::exporting {

// File name of the bundled viewer script.
inline constexpr const char* kViewerBundleName = "viewer.bundle.js";

struct ViewerPage {
  std::string title;
  // The trace, JSON Lines (sim/trace.h); a header alone shows a scene at rest.
  std::string trace;
  // A distance map: {"goal":[x,y,z],"distances":[[x,y,z,d],...],"path":[[x,y,z],...]}, every
  // field optional; `datomsim reach --out` writes one.
  std::optional<std::string> overlay;
  // Latch loads to colour latches by: the document export/loads_check.h makes (id
  // "datomsim-loads").
  std::optional<std::string> loads;
};

// The most bytes read from a file the viewer's page holds (a trace, a reach map, the viewer's
// script): 512 MiB, about the longest string a browser's JavaScript holds (V8: 2^29 - 24
// characters), which the page must.
inline constexpr size_t kMaxPageInputBytes = size_t{512} << 20;

// The whole file's bytes: a regular file of at most kMaxPageInputBytes (a larger one refused
// before it is read), or a FIFO read up to that bound; a directory, a device (/dev/zero would
// never end) or a socket refused. The error names the path.
Result<std::string> readFile(const std::filesystem::path& path);

// The directory of the binary holding datomsim's code: the shared library's when a researcher's
// executable links it, else the running executable's (Linux: /proc/self/exe).
Result<std::filesystem::path> executableDirectory();

// Where the bundle is looked for, in order: next to that binary, then in ../share/datomsim/ (an
// installed layout), then in ../bin/ (the shared library of a build tree).
std::vector<std::filesystem::path> viewerBundleCandidates(
    const std::filesystem::path& executableDirectory);

// The bundle's text: from `explicitPath` when it is not empty, else from the first candidate that
// exists. The error says where it looked and how to build the bundle.
Result<std::string> loadViewerBundle(const std::filesystem::path& explicitPath,
                                     const std::filesystem::path& executableDirectory);

// True when the first JSON value of `text` is a trace header ("format": "datomsim-trace").
bool looksLikeTrace(const std::string& text);

// Checks a trace: every value is JSON, the first a header of format "datomsim-trace" version 1,
// the others objects with a time "t". Errors name `name`, the line and what is wrong. Returns the
// header's description (empty when it has none).
Result<std::string> checkTrace(const std::string& text, const std::string& name);

// A header-only trace of a world at rest (record::TraceWriter::header, unit module), naming the
// module kind when it is not the Datom.
std::string sceneTrace(const world::World& world, const std::string& description,
                       world::ModuleKind kind = world::ModuleKind::kDatom);

// Checks a distance map document (as ViewerPage::overlay describes) and returns it compact.
Result<std::string> checkOverlay(const std::string& text, const std::string& name);

// A distance map document from cells and distances, a path and a goal (either may be empty).
std::string overlayJson(const std::vector<std::pair<geometry::Cell, int>>& distances,
                        const std::vector<geometry::Cell>& path,
                        const std::optional<geometry::Cell>& goal);

// The page for an input file: a trace (recognised by its header, whatever its extension) or a
// scene (.xml or .json, io/scene_file.h) shown at rest, as modules of the scene's kind. The title
// is the trace's description, else the scene's name, else the file name.
Result<ViewerPage> pageForFile(const std::filesystem::path& input);

// The HTML text of a page. Refuses a bundle that cannot stand inside a <script> element (it
// contains "</script" or "<!--"); the trace and the overlay are escaped ('<' as \u003c).
Result<std::string> viewerHtml(const std::string& bundle, const ViewerPage& page);

// Writes the page atomically.
Status writeViewerPage(const std::filesystem::path& path, const std::string& bundle,
                       const ViewerPage& page);

}  // namespace datomsim::exporting
