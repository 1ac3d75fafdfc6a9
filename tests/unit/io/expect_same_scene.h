// Test helpers comparing what the scene files carry: modules (id, cell, orientation, colour, in
// order), bounds, block size, viewer settings and targets. Latches and pistons are not in the
// files.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "io/scene.h"
#include "support/temporary_directory.h"

namespace datomsim::io::testing {

using datomsim::testing::readText;
using datomsim::testing::TemporaryDirectory;

inline ::testing::AssertionResult sameModules(const world::World& a, const world::World& b) {
  if (a.size() != b.size()) {
    return ::testing::AssertionFailure() << a.size() << " modules vs " << b.size();
  }
  for (size_t i = 0; i < a.size(); ++i) {
    const world::Module& x = a.modules()[i];
    const world::Module& y = b.modules()[i];
    if (x.id != y.id || x.cell != y.cell || x.orientation != y.orientation || x.color != y.color) {
      return ::testing::AssertionFailure()
             << "module #" << i << ": id " << x.id.value << " at " << geometry::toString(x.cell)
             << " orientation " << x.orientation.code() << " color " << int(x.color.r) << ","
             << int(x.color.g) << "," << int(x.color.b) << " vs id " << y.id.value << " at "
             << geometry::toString(y.cell) << " orientation " << y.orientation.code() << " color "
             << int(y.color.r) << "," << int(y.color.g) << "," << int(y.color.b);
    }
  }
  if (!(a.bounds() == b.bounds())) return ::testing::AssertionFailure() << "bounds differ";
  return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult sameScene(const Scene& a, const Scene& b) {
  if (auto modules = sameModules(a.world, b.world); !modules) return modules;
  if (a.blockSize != b.blockSize) return ::testing::AssertionFailure() << "block sizes differ";
  if (a.name != b.name) return ::testing::AssertionFailure() << "names differ";
  if (a.description != b.description) return ::testing::AssertionFailure() << "descriptions differ";
  if (!(a.visibleSim == b.visibleSim)) {
    return ::testing::AssertionFailure() << "viewer settings differ";
  }
  if (a.targets.size() != b.targets.size()) {
    return ::testing::AssertionFailure() << a.targets.size() << " targets vs " << b.targets.size();
  }
  for (size_t i = 0; i < a.targets.size(); ++i) {
    if (!(a.targets[i] == b.targets[i]))
      return ::testing::AssertionFailure() << "targets[" << i << "] differ";
  }
  return ::testing::AssertionSuccess();
}

// A scene file of the repository's scenes/ folder, e.g. VisibleSim's reference files of the
// paper's scenes. The path is returned even when the file is missing, so that the test can fail
// naming it: ASSERT_TRUE(std::filesystem::exists(path)) << path.
inline std::filesystem::path repositoryScene(const std::string& name) {
  return std::filesystem::path(DATOMSIM_SOURCE_DIR "/scenes/") / name;
}

}  // namespace datomsim::io::testing
