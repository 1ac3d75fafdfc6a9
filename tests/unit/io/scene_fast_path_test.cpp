// The scene readers' fast paths (json_scene_fast.cpp, visiblesim_xml_fast.cpp) against the
// general readers: on every document, the same scene or the same error, whether the fast path
// read it or declined. And the fast paths do read the files the writers write, so they are the
// path large scenes take.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "io/json_scene.h"
#include "io/json_scene_handler.h"
#include "io/visiblesim_xml.h"
#include "io/visiblesim_xml_detail.h"
#include "scene/random_scene.h"
#include "unit/io/expect_same_scene.h"

namespace datomsim::io {
namespace {

using testing::sameScene;

::testing::AssertionResult sameOutcome(const Result<Scene>& a, const Result<Scene>& b) {
  if (a.ok() != b.ok()) {
    return ::testing::AssertionFailure() << (a.ok() ? "read" : "refused: " + a.error()) << " vs "
                                         << (b.ok() ? "read" : "refused: " + b.error());
  }
  if (!a.ok()) {
    if (a.error() == b.error()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "\"" << a.error() << "\" vs \"" << b.error() << "\"";
  }
  return sameScene(*a, *b);
}

// Both entry points of the JSON reader (text and stream) give what the general reader gives.
::testing::AssertionResult jsonAgrees(const std::string& text) {
  const Result<Scene> general = detail::readJsonSceneGeneral(text, "s.json");
  if (auto same = sameOutcome(parseJsonScene(text, "s.json"), general); !same) {
    return same << " (text) for: " << text;
  }
  std::istringstream stream(text);
  if (auto same = sameOutcome(parseJsonScene(stream, "s.json"), general); !same) {
    return same << " (stream) for: " << text;
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult xmlAgrees(const std::string& text) {
  const Result<Scene> general = detail::readVisibleSimXmlGeneral(text, "s.xml");
  if (auto same = sameOutcome(parseVisibleSimXml(text, "s.xml"), general); !same) {
    return same << " for: " << text;
  }
  return ::testing::AssertionSuccess();
}

Scene randomScene() {
  Scene scene;
  scene.world = scene::random(7, 60).value();
  scene.name = "random";
  return scene;
}

// A document with a little of everything the fast path hands on (grid, targets, parameters) and
// modules of each shape it reads itself.
const std::string kJson = R"({"format": "datomsim-scene", "version": 1, "grid": [9, 9, 4],
 "modules": [
  {"id": 4, "cell": [1, 2, 0], "orientation": 3, "color": [10, 20, 30]},
  {"cell":[2,2,0]},
  { "color" : [ 1 , 2 , 3 ] , "cell" : [ 3 , 3 , 1 ] , "id" : 9 }
 ],
 "targets": [{"format": "grid", "cells": [[1, 1, 0]]}],
 "parameters": {"flood": {"root": [1, 2, 0]}}}
)";

const std::string kXml = R"(<?xml version="1.0" standalone="no" ?>
<world gridSize="9,9,4" windowSize="800,600">
    <camera target="50,50,0" directionSpherical="0,38,90"/>
    <blockList blockSize="10,10,10" color="200,100,0">
        <block position="1,2,0" color="10,20,30" orientation="3"/>
        <block position='2,2,0'/>
        <block id="9"  position="3,3,1"
               orientation="1" />
    </blockList>
    <targetList><target format="grid"><cell position="1,1,0"/></target></targetList>
</world>
)";

TEST(JsonFastPath, ReadsWhatTheWriterWritesAndHandWrittenModules) {
  Scene scene = randomScene();
  scene.parameters["flood"]["root"] = "1,2,0";
  const std::string written = toJson(scene);
  const auto fast = detail::readJsonSceneFast(written, "w.json");
  ASSERT_TRUE(fast.has_value()) << "declined the writer's output";
  ASSERT_TRUE(fast->ok()) << fast->error();
  EXPECT_TRUE(sameScene(**fast, scene));
  EXPECT_EQ((*fast)->parameters, scene.parameters);

  const auto handWritten = detail::readJsonSceneFast(kJson, "h.json");
  ASSERT_TRUE(handWritten.has_value());
  ASSERT_TRUE(handWritten->ok()) << handWritten->error();
  EXPECT_EQ((*handWritten)->world.size(), 3u);
  EXPECT_TRUE(jsonAgrees(kJson));
}

TEST(JsonFastPath, DeclinesWhatItDoesNotReadAndTheGeneralReaderWordsIt) {
  // Each is read by the general reader or refused by it; the fast path leaves them all to it.
  const std::vector<std::string> documents = {
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[1.0,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[-0,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"c\u0065ll":[0,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[0,0,0],"size":1}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[0,0,0],"cell":[1,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[01,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[1e1,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"id":0,"cell":[0,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[0,0,0],"color":[256,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[0,0,0]},]})",
      R"({"format":"datomsim-scene","version":1,"modules":[[0,0,0]]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[0,0,0]}]} x)",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[99999999999999999999,0,0]}]})",
      "\xEF\xBB\xBF"
      R"({"format":"datomsim-scene","version":1,"modules":[]})",
      // A NUL after a value, which nlohmann's parser takes for the end of the input.
      std::string(R"({"format":"datomsim-scene","version":1,"grid":null)") + '\0' + "\xFF}",
      std::string(R"({"format":"datomsim-scene","version":1,"name":"a")") + '\0' + ',' +
          R"("modules":[]})",
  };
  for (const std::string& text : documents) {
    EXPECT_FALSE(detail::readJsonSceneFast(text, "s.json").has_value()) << text;
    EXPECT_TRUE(jsonAgrees(text));
  }
}

TEST(JsonFastPath, PlacementErrorsAndLateGridsAgreeWithTheGeneralReader) {
  const std::vector<std::string> documents = {
      // Two modules in one cell; a repeated id; a cell outside the grid; an id taken by place.
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[0,0,0]},{"cell":[0,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"id":3,"cell":[0,0,0]},{"id":3,"cell":[1,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"grid":[2,2,2],"modules":[{"cell":[5,0,0]}]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"id":2,"cell":[0,0,0]},{"cell":[1,0,0]}]})",
      // The grid after the modules: they wait for it; before a syntax error, no placement error.
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[5,0,0]}],"grid":[2,2,2]})",
      R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[1,0,0]}],"grid":[2,2,2]})",
      R"({"format":"datomsim-scene","version":1,"grid":[2,2,2],"modules":[{"cell":[5,0,0]}],)",
      R"({"format":"datomsim-scene","version":1,"grid":null,"modules":[{"cell":[0,0,-1]}]})",
  };
  for (const std::string& text : documents) EXPECT_TRUE(jsonAgrees(text));
}

TEST(JsonFastPath, AgreesOnEveryPrefixAndEveryChangedByte) {
  for (size_t length = 0; length <= kJson.size(); ++length) {
    ASSERT_TRUE(jsonAgrees(kJson.substr(0, length)));
  }
  const std::string replacements = "\"',1-.e }]{[\\x:0\n";
  for (size_t at = 0; at < kJson.size(); ++at) {
    std::string removed = kJson;
    removed.erase(at, 1);
    ASSERT_TRUE(jsonAgrees(removed));
    for (const char c : replacements) {
      std::string changed = kJson;
      changed[at] = c;
      ASSERT_TRUE(jsonAgrees(changed));
    }
  }
}

TEST(XmlFastPath, ReadsWhatTheWriterWritesAndHandWrittenBlocks) {
  const Scene scene = randomScene();
  const std::string written = toVisibleSimXml(scene).value();
  const auto region = detail::scanBlockList(written);
  ASSERT_TRUE(region.has_value()) << "declined the writer's output";
  EXPECT_EQ(region->blocks.size(), scene.world.size());
  const Result<Scene> read = parseVisibleSimXml(written, "w.xml");
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_TRUE(sameScene(*read, scene));

  const auto handWritten = detail::scanBlockList(kXml);
  ASSERT_TRUE(handWritten.has_value());
  EXPECT_EQ(handWritten->blocks.size(), 3u);
  EXPECT_TRUE(xmlAgrees(kXml));
  // The list's colour for a block without its own, ids by place unless given.
  const Scene hand = parseVisibleSimXml(kXml, "h.xml").value();
  EXPECT_EQ(hand.world.modules()[1].color, (Color{200, 100, 0}));
  EXPECT_EQ(hand.world.modules()[2].id, ModuleId{9});
}

TEST(XmlFastPath, DeclinesWhatItDoesNotReadAndTheGeneralReaderWordsIt) {
  auto withBlocks = [](const std::string& blocks) {
    return "<world gridSize=\"9,9,4\"><blockList>" + blocks + "</blockList></world>";
  };
  const std::vector<std::string> documents = {
      withBlocks(R"(<block position="1,2,0"/><!-- a comment --><block position="2,2,0"/>)"),
      withBlocks(R"(<block position="&#49;,2,0"/>)"),
      withBlocks(R"(<block position="1,2,0"></block>)"),
      withBlocks(R"(<block position="1,2,0" master="true"/>)"),
      withBlocks(R"(<block position="1,2,0" position="2,2,0"/>)"),
      withBlocks(R"(<block color="1,2,3"/>)"),
      withBlocks(R"(<block position="1,2"/>)"),
      withBlocks(R"(<block position="1,2,0"/>text)"),
      withBlocks(R"(<cell position="1,2,0"/>)"),
      withBlocks(R"(<block position="1,2,0"orientation="2"/>)"),
      // An end tag tinyxml2 reads in a way of its own (found by the fuzzer).
      R"(<world><blockList><block position="0,0,8"/></blockList/><block position="0,0,0"/></blockList></world>)",
      withBlocks(R"(<block position="1,2,0"/></blockListing>)"),
      // A comment before the list, or the list inside another element.
      R"(<!-- --><world><blockList><block position="1,2,0"/></blockList></world>)",
      R"(<world><group><blockList><block position="1,2,0"/></blockList></group></world>)",
  };
  for (const std::string& text : documents) {
    EXPECT_FALSE(detail::scanBlockList(text).has_value()) << text;
    EXPECT_TRUE(xmlAgrees(text));
  }
}

TEST(XmlFastPath, PlacementErrorsAndSkeletonErrorsAgreeWithTheGeneralReader) {
  const std::vector<std::string> documents = {
      R"(<world><blockList><block position="1,2,0"/><block position="1,2,0"/></blockList></world>)",
      R"(<world><blockList><block id="2" position="1,2,0"/><block position="2,2,0"/></blockList></world>)",
      R"(<world gridSize="2,2,2"><blockList><block position="5,2,0"/></blockList></world>)",
      R"(<world><blockList><block position="1,2,0"/></blockList><blockList/></world>)",
      R"(<scene><blockList><block position="1,2,0"/></blockList></scene>)",
      R"(<world><blockList color="300,0,0"><block position="1,2,0"/></blockList></world>)",
      R"(<world><blockList><block position="1,2,0"/></blockList><camera a="&bad;"/></world>)",
  };
  for (const std::string& text : documents) EXPECT_TRUE(xmlAgrees(text));
}

TEST(XmlFastPath, AgreesOnEveryPrefixAndEveryChangedByte) {
  for (size_t length = 0; length <= kXml.size(); ++length) {
    ASSERT_TRUE(xmlAgrees(kXml.substr(0, length)));
  }
  const std::string replacements = "\"'<>/=&1, \nbx";
  for (size_t at = 0; at < kXml.size(); ++at) {
    std::string removed = kXml;
    removed.erase(at, 1);
    ASSERT_TRUE(xmlAgrees(removed));
    for (const char c : replacements) {
      std::string changed = kXml;
      changed[at] = c;
      ASSERT_TRUE(xmlAgrees(changed));
    }
  }
}

}  // namespace
}  // namespace datomsim::io
