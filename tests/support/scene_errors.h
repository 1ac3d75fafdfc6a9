// What the scene readers say about a text they refuse (a test expects the refusal).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "io/json_scene.h"
#include "io/visiblesim_xml.h"

namespace datomsim::testing {

inline std::string jsonSceneError(const std::string& text) {
  const auto scene = io::parseJsonScene(text, "box.json");
  EXPECT_FALSE(scene.ok());
  return scene.ok() ? std::string() : scene.error();
}

inline std::string xmlSceneError(const std::string& text) {
  const auto scene = io::parseVisibleSimXml(text, "scene.xml");
  EXPECT_FALSE(scene.ok());
  return scene.ok() ? std::string() : scene.error();
}

}  // namespace datomsim::testing
