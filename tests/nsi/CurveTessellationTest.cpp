// Curves to round linear segments: where the tessellated curve runs, what
// radii it carries and that segments never join two curves.
#include "CurveTessellation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace {

using prism::nsi::buildCurves;
using prism::nsi::GeometryData;
using prism::nsi::Node;
using prism::nsi::Value;

Value floats(int type, std::vector<float> values, size_t count)
{
  Value v;
  v.type = type;
  v.count = count;
  v.bytes.resize(values.size() * 4);
  std::memcpy(v.bytes.data(), values.data(), v.bytes.size());
  return v;
}

Value ints(std::vector<int> values)
{
  Value v;
  v.type = NSITypeInteger;
  v.count = values.size();
  v.bytes.resize(values.size() * 4);
  std::memcpy(v.bytes.data(), values.data(), v.bytes.size());
  return v;
}

Value text(const char *s)
{
  Value v;
  v.type = NSITypeString;
  v.count = 1;
  v.strings = {s};
  return v;
}

class CurveTessellation : public ::testing::Test
{
 protected:
  void set(const char *name, Value value)
  {
    m_node.attributes[name].value = std::move(value);
  }
  std::optional<GeometryData> build()
  {
    return buildCurves("c", m_node, [this](int, const std::string &m) {
      m_messages += m + "\n";
    });
  }
  // Whether the tessellation passes within `tolerance` of (x, y, z).
  static bool passesThrough(
      const GeometryData &d, float x, float y, float z, float tolerance = 1e-5f)
  {
    for (size_t i = 0; i < d.positions.size(); i += 3) {
      if (std::abs(d.positions[i] - x) < tolerance
          && std::abs(d.positions[i + 1] - y) < tolerance
          && std::abs(d.positions[i + 2] - z) < tolerance)
        return true;
    }
    return false;
  }

  void SetUp() override
  {
    m_node.type = "curves";
  }

  Node m_node;
  std::string m_messages;
};

TEST_F(CurveTessellation, CatmullRomPassesThroughInnerPoints)
{
  set("nvertices", ints({4}));
  set("P", floats(NSITypePoint, {0, 0, 0, 1, 1, 0, 2, 0, 0, 3, 1, 0}, 4));
  set("width", floats(NSITypeFloat, {0.5f}, 1));
  auto d = build();
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->curves);
  EXPECT_TRUE(passesThrough(*d, 1, 1, 0));
  EXPECT_TRUE(passesThrough(*d, 2, 0, 0));
  EXPECT_FALSE(passesThrough(*d, 0, 0, 0)); // one span: p1 to p2 only
  EXPECT_EQ(d->segmentStarts.size(), 8u);
  for (float r : d->radii)
    EXPECT_EQ(r, 0.25f);
  EXPECT_EQ(m_messages, "");
}

TEST_F(CurveTessellation, ExtrapolateReachesTheEnds)
{
  for (const char *basis : {"catmull-rom", "b-spline"}) {
    set("basis", text(basis));
    set("extrapolate", ints({1}));
    set("nvertices", ints({4}));
    set("P", floats(NSITypePoint, {0, 0, 0, 1, 1, 0, 2, 0, 0, 3, 1, 0}, 4));
    auto d = build();
    ASSERT_TRUE(d) << basis;
    EXPECT_TRUE(passesThrough(*d, 0, 0, 0)) << basis;
    EXPECT_TRUE(passesThrough(*d, 3, 1, 0)) << basis;
    EXPECT_EQ(d->segmentStarts.size(), 3u * 8u) << basis; // 6 points: 3 spans
  }
  EXPECT_EQ(m_messages, "");
}

TEST_F(CurveTessellation, LinearCurvesKeepTheirPointsAndDoNotJoin)
{
  m_node.type = "linearcurves";
  set("nvertices", ints({2, 3}));
  set("P",
      floats(NSITypePoint, {0, 0, 0, 1, 0, 0, 5, 0, 0, 6, 0, 0, 7, 1, 0}, 5));
  set("width", floats(NSITypeFloat, {1, 2, 3, 4, 5}, 5));
  auto d = build();
  ASSERT_TRUE(d);
  EXPECT_EQ(d->positions.size(), 15u);
  EXPECT_EQ(d->segmentStarts, (std::vector<uint32_t>{0, 2, 3}));
  EXPECT_EQ(d->radii, (std::vector<float>{0.5f, 1, 1.5f, 2, 2.5f}));
}

TEST_F(CurveTessellation, BadInputIsReported)
{
  set("nvertices", ints({3}));
  set("P", floats(NSITypePoint, {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0}, 4));
  EXPECT_FALSE(build());
  EXPECT_NE(m_messages.find("'nvertices' adds up to 3 but 'P' has 4"),
      std::string::npos)
      << m_messages;
  m_messages.clear();
  set("nvertices", ints({1}));
  EXPECT_FALSE(build());
  EXPECT_NE(m_messages.find("'nvertices' holds 1"), std::string::npos)
      << m_messages;
  m_messages.clear();
  // A cubic curve needs 4 points (without extrapolation).
  set("nvertices", ints({2, 2}));
  EXPECT_FALSE(build());
  EXPECT_NE(m_messages.find("fewer than 4 vertices"), std::string::npos)
      << m_messages;
}

} // namespace
