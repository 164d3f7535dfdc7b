// The node graph on its own: recursive deletion, strong links, .all
// disconnection, attribute samples.
#include "Graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <set>

namespace {

using prism::nsi::Graph;
using prism::nsi::Input;
using prism::nsi::Node;
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

namespace {

// Whether `from` reaches `to` along connections, by brute force.
bool reachesByWalking(
    const Graph &graph, const std::string &from, const std::string &to)
{
  std::vector<std::string> todo{from};
  std::set<std::string> seen;
  while (!todo.empty()) {
    const std::string at = todo.back();
    todo.pop_back();
    if (at == to)
      return true;
    if (!seen.insert(at).second)
      continue;
    for (auto &output : graph.find(at)->outputs)
      todo.push_back(output.to);
  }
  return false;
}

std::string numbered(const char *prefix, unsigned number)
{
  std::string text = prefix;
  return text.append(std::to_string(number));
}

// Connections refused as cycles so far.
size_t cyclesReported(const std::vector<std::pair<int, std::string>> &messages)
{
  return std::count_if(messages.begin(), messages.end(), [](auto &m) {
    return m.second.find("close a cycle") != std::string::npos
           || m.second.find("closed a cycle") != std::string::npos;
  });
}

// Whether every connection's two sides name each other.
bool sidesAgree(const Graph &graph)
{
  size_t inputs = 0, outputs = 0;
  for (auto &[handle, node] : graph.nodes()) {
    inputs += node.inputs.size();
    for (auto &output : node.outputs) {
      ++outputs;
      const Node *target = graph.find(output.to);
      if (!target || output.input >= target->inputs.size())
        return false;
      const Input &input = target->inputs[output.input];
      if (input.from != handle || input.fromAttr != output.fromAttr
          || input.toAttr != output.toAttr
          || &graph.find(input.from)->outputs[input.output] != &output)
        return false;
    }
  }
  return inputs == outputs;
}

// Whether every connection climbs the nodes' order (what the cycle checks
// keep).
bool ordersClimb(const Graph &graph)
{
  for (auto &[handle, node] : graph.nodes()) {
    for (auto &output : node.outputs) {
      if (node.order >= graph.find(output.to)->order)
        return false;
    }
  }
  return true;
}

} // namespace

// 50,000 levels each way (parents first; leaves first, connected from the
// leaf): every connect is cheap (the cycle check once walked the whole
// chain: 5,000 levels took 29 s), the link closing the chain into a loop is
// the one reported and removed (at once, or when the render starts), and a
// recursive delete takes the chain without recursing (the old delete
// overflowed the stack). The ctest TIMEOUT guards against the old
// quadratic build.
TEST_F(GraphTest, FiftyThousandDeepChainsBuildAndRefuseTheirCycle)
{
  constexpr int kDepth = 50000;
  for (const bool parentsFirst : {true, false}) {
    const std::string prefix = parentsFirst ? "p" : "l";
    auto name = [&](int level) {
      std::string text = prefix;
      return text.append(std::to_string(level));
    };
    for (int i = 0; i < kDepth; ++i)
      m_graph.create(name(parentsFirst ? i : kDepth - 1 - i), "transform");
    m_graph.connect(name(0), "", NSI_SCENE_ROOT, "objects", 0, 0);
    for (int i = 1; i < kDepth; ++i) {
      const int level = parentsFirst ? i : kDepth - i;
      m_graph.connect(name(level), "", name(level - 1), "objects", 0, 0);
    }
    EXPECT_TRUE(m_messages.empty());
    m_graph.connect(name(0), "", name(kDepth - 1), "objects", 0, 0);
    m_graph.checkCycles(); // what the render does first
    EXPECT_EQ(cyclesReported(m_messages), 1u);
    EXPECT_TRUE(m_graph.find(name(kDepth - 1))->inputs.empty());
    EXPECT_EQ(m_graph.find(name(0))->outputs.size(), 1u);
    EXPECT_TRUE(ordersClimb(m_graph));
    m_messages.clear();
    m_graph.remove(name(0), true);
    EXPECT_FALSE(has(name(0)));
    EXPECT_FALSE(has(name(kDepth - 1)));
  }
  EXPECT_EQ(m_graph.nodes().size(), 2u); // .root and .global
}

// 300,000 nodes on .root: connecting one more no longer scans .root's
// inputs (quadratic before; the ctest TIMEOUT catches that), and
// connecting again still updates rather than duplicates.
TEST_F(GraphTest, FlatSceneConnectsWithoutScanningTheRoot)
{
  constexpr int kNodes = 300000;
  for (int i = 0; i < kNodes; ++i) {
    std::string handle = "m";
    handle.append(std::to_string(i));
    m_graph.create(handle, "mesh");
    m_graph.connect(handle, "", NSI_SCENE_ROOT, "objects", 0, 0);
  }
  m_graph.connect("m7", "", NSI_SCENE_ROOT, "objects", 3, 0);
  const Node &root = *m_graph.find(NSI_SCENE_ROOT);
  EXPECT_EQ(root.inputs.size(), size_t(kNodes));
  EXPECT_EQ(root.inputs[7].priority, 3);
  EXPECT_EQ(m_graph.find("m7")->outputs.size(), 1u);
  EXPECT_TRUE(m_messages.empty());
}

// The incremental order refuses exactly the connections a walk says close
// a cycle, over random graphs whose orders need constant repair.
TEST_F(GraphTest, CycleChecksAgreeWithAWalkOnRandomGraphs)
{
  std::mt19937 random(27);
  constexpr int kNodes = 40;
  for (int i = 0; i < kNodes; ++i)
    m_graph.create(numbered("n", i), "transform");
  size_t refused = 0;
  for (int edge = 0; edge < 2000; ++edge) {
    const std::string from = numbered("n", random() % kNodes);
    const std::string to = numbered("n", random() % kNodes);
    const std::string attr = numbered("a", random() % 3);
    if (edge % 7 == 6) {
      m_graph.disconnect(from, NSI_ALL_NODES, to, NSI_ALL_NODES);
      continue;
    }
    if (edge % 97 == 96) { // a node goes, and comes back unconnected
      m_graph.remove(from, false);
      m_graph.create(from, "transform");
      continue;
    }
    const bool closes = reachesByWalking(m_graph, to, from);
    m_graph.connect(from, "", to, attr, 0, 0);
    refused += closes;
    ASSERT_EQ(cyclesReported(m_messages), refused)
        << from << " -> " << to << " at connection " << edge;
  }
  EXPECT_GT(refused, 100u); // the test met many cycles
  EXPECT_TRUE(ordersClimb(m_graph));
  EXPECT_TRUE(sidesAgree(m_graph));
}

// Deleting each of 300,000 meshes on .root, one by one: a removal no
// longer scans .root's inputs (quadratic before; the ctest TIMEOUT catches
// that), and what stays is still listed in connection order.
TEST_F(GraphTest, FlatSceneDeletesWithoutScanningTheRoot)
{
  constexpr int kNodes = 300000;
  for (int i = 0; i < kNodes; ++i) {
    const std::string handle = numbered("m", unsigned(i));
    m_graph.create(handle, "mesh");
    m_graph.connect(handle, "", NSI_SCENE_ROOT, "objects", 0, 0);
  }
  for (int i = 0; i < kNodes; ++i) {
    if (i % 100000 != 5)
      m_graph.remove(numbered("m", unsigned(i)), false);
  }
  m_graph.disconnect("m100005", "", NSI_SCENE_ROOT, "objects");
  const auto left = m_graph.find(NSI_SCENE_ROOT)->inputsOf("objects");
  ASSERT_EQ(left.size(), 2u);
  EXPECT_EQ(left[0]->from, "m5");
  EXPECT_EQ(left[1]->from, "m200005");
  EXPECT_TRUE(sidesAgree(m_graph));
  EXPECT_TRUE(m_messages.empty());
}
