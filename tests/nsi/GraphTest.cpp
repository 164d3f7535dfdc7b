// The node graph on its own: recursive deletion, strong links, .all
// disconnection, attribute samples.
#include "Graph.h"

#include <gtest/gtest.h>

#include <cstring>

namespace {

using prism::nsi::Graph;
using prism::nsi::Value;

class GraphTest : public ::testing::Test
{
 protected:
  Graph m_graph{[this](int level, const std::string &text) {
    m_messages.push_back({level, text});
  }};
  std::vector<std::pair<int, std::string>> m_messages;

  bool has(const std::string &handle) const
  {
    return m_graph.find(handle) != nullptr;
  }
  static Value number(float x)
  {
    Value v;
    v.type = NSITypeFloat;
    v.count = 1;
    v.bytes.resize(4);
    std::memcpy(v.bytes.data(), &x, 4);
    return v;
  }
};

TEST_F(GraphTest, RecursiveDeleteTakesWhatOnlyFedTheNode)
{
  // shader -> attr -> mesh; "shared" feeds both mesh and other.
  for (auto [h, t] : {std::pair{"mesh", "mesh"},
           {"attr", "attributes"},
           {"shader", "shader"},
           {"shared", "shader"},
           {"other", "mesh"},
           {"kept", "shader"}})
    m_graph.create(h, t);
  m_graph.connect("shader", "", "attr", "surfaceshader", 0, 0);
  m_graph.connect("attr", "", "mesh", "geometryattributes", 0, 0);
  m_graph.connect("shared", "", "mesh", "x", 0, 0);
  m_graph.connect("shared", "", "other", "x", 0, 0);
  m_graph.connect("kept", "", "mesh", "y", 0, 1); // strength 1 blocks
  m_graph.connect("mesh", "", NSI_SCENE_ROOT, "objects", 0, 0);
  m_graph.remove("mesh", true);
  EXPECT_FALSE(has("mesh"));
  EXPECT_FALSE(has("attr"));
  EXPECT_FALSE(has("shader"));
  EXPECT_TRUE(has("shared"));
  EXPECT_TRUE(has("kept"));
  EXPECT_TRUE(has("other"));
  EXPECT_TRUE(has(NSI_SCENE_ROOT));
  EXPECT_TRUE(m_graph.find(NSI_SCENE_ROOT)->inputs.empty());
  EXPECT_EQ(m_graph.find("shared")->outputs.size(), 1u);
  EXPECT_TRUE(m_messages.empty());
}

TEST_F(GraphTest, PlainDeleteKeepsSources)
{
  m_graph.create("a", "shader");
  m_graph.create("b", "attributes");
  m_graph.connect("a", "", "b", "surfaceshader", 0, 0);
  m_graph.remove("b", false);
  EXPECT_TRUE(has("a"));
  EXPECT_TRUE(m_graph.find("a")->outputs.empty());
}

TEST_F(GraphTest, DiamondIsDeletedWhole)
{
  for (const char *h : {"top", "left", "right", "bottom"})
    m_graph.create(h, "transform");
  m_graph.connect("bottom", "", "left", "objects", 0, 0);
  m_graph.connect("bottom", "", "right", "objects", 0, 0);
  m_graph.connect("left", "", "top", "objects", 0, 0);
  m_graph.connect("right", "", "top", "objects", 0, 0);
  m_graph.remove("top", true);
  for (const char *h : {"top", "left", "right", "bottom"})
    EXPECT_FALSE(has(h)) << h;
}

TEST_F(GraphTest, DisconnectAll)
{
  for (const char *h : {"a", "b", "c"})
    m_graph.create(h, "transform");
  m_graph.connect("a", "", NSI_SCENE_ROOT, "objects", 0, 0);
  m_graph.connect("b", "", NSI_SCENE_ROOT, "objects", 0, 0);
  m_graph.connect("c", "", "a", "objects", 0, 0);
  m_graph.connect("a", "", "b", "other", 0, 0);
  m_graph.disconnect(NSI_ALL_NODES, "", NSI_SCENE_ROOT, "objects");
  EXPECT_TRUE(m_graph.find(NSI_SCENE_ROOT)->inputs.empty());
  EXPECT_EQ(m_graph.find("a")->outputs.size(), 1u); // a -> b.other stays
  EXPECT_EQ(m_graph.find("a")->inputs.size(), 1u);  // c -> a stays
  m_graph.disconnect(
      "a", NSI_ALL_ATTRIBUTES, NSI_ALL_NODES, NSI_ALL_ATTRIBUTES);
  EXPECT_TRUE(m_graph.find("a")->outputs.empty());
  EXPECT_TRUE(m_graph.find("b")->inputs.empty());
  EXPECT_TRUE(m_messages.empty());
}

TEST_F(GraphTest, ConnectingTwiceKeepsOneLink)
{
  m_graph.create("a", "transform");
  m_graph.connect("a", "", NSI_SCENE_ROOT, "objects", 0, 0);
  m_graph.connect("a", "", NSI_SCENE_ROOT, "objects", 3, 0);
  ASSERT_EQ(m_graph.find(NSI_SCENE_ROOT)->inputs.size(), 1u);
  EXPECT_EQ(m_graph.find(NSI_SCENE_ROOT)->inputs[0].priority, 3);
  EXPECT_EQ(m_graph.find("a")->outputs.size(), 1u);
}

TEST_F(GraphTest, AttributeValuesAndSamples)
{
  m_graph.create("xf", "transform");
  m_graph.setAttribute("xf", "m", number(2), 0.5);
  m_graph.setAttribute("xf", "m", number(1), -0.5);
  EXPECT_EQ(
      m_graph.find("xf")->attribute("m")->number(0), 1.0); // first in time
  m_graph.setAttribute("xf", "m", number(7), std::nullopt);
  EXPECT_TRUE(m_graph.find("xf")->attributes.at("m").samples.empty());
  EXPECT_EQ(m_graph.find("xf")->attribute("m")->number(0), 7.0);
  m_graph.deleteAttribute("xf", "m");
  EXPECT_EQ(m_graph.find("xf")->attribute("m"), nullptr);
}

} // namespace
