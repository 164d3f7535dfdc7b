// Catmull-Clark meshes refined through OpenSubdiv, checked against the
// limit surface's known points: a unit cube's face centres lie at
// 0.419753 = 34/81 of the way out (the regular vertex limit mask applied
// to the cube's first refinement), creases and corners keep the cage.
#include "GeometryBuilder.h"
#include "SubdivisionSurface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace {

using prism::nsi::buildMesh;
using prism::nsi::GeometryData;
using prism::nsi::Node;
using prism::nsi::Value;

// The face centre of a Catmull-Clark unit cube on its limit surface:
// 4/9 * 1/2 + 4 * 1/9 * 3/8 + 4 * 1/36 * 5/18 (face point, edge points and
// vertex points of the first refinement).
constexpr double kLimitHalfWidth = 34.0 / 81.0;

template <typename T>
Value numbers(int type, const std::vector<T> &v, size_t components = 1)
{
  Value value;
  value.type = type;
  value.count = v.size() / components;
  value.bytes.resize(v.size() * sizeof(T));
  std::memcpy(value.bytes.data(), v.data(), value.bytes.size());
  return value;
}

Value text(const std::string &s)
{
  Value value;
  value.type = NSITypeString;
  value.count = 1;
  value.strings = {s};
  return value;
}

// A unit cube about the origin: point i at (i&1, i&2, i&4) less a half,
// faces counter-clockwise seen from outside.
const std::vector<int> kCubeEdges = {
    0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7};

class Subdivision : public ::testing::Test
{
 protected:
  Subdivision()
  {
    std::vector<float> points;
    for (int i = 0; i < 8; ++i)
      points.insert(points.end(),
          {(i & 1) - 0.5f, (i & 2) / 2 - 0.5f, (i & 4) / 4 - 0.5f});
    set("P", numbers(NSITypePoint, points, 3));
    set("P.indices",
        numbers(NSITypeInteger,
            std::vector<int>{0,
                2,
                3,
                1,
                4,
                5,
                7,
                6,
                0,
                1,
                5,
                4,
                2,
                6,
                7,
                3,
                0,
                4,
                6,
                2,
                1,
                3,
                7,
                5}));
    set("nvertices", numbers(NSITypeInteger, std::vector<int>(6, 4)));
    set("subdivision.scheme", text("catmull-clark"));
  }
  void set(const std::string &name, const Value &value)
  {
    m_mesh.attributes[name].value = value;
  }
  GeometryData build(int level = 3)
  {
    auto data = buildMesh(
        "cube",
        m_mesh,
        [this](
            int, const std::string &message) { m_messages += message + "\n"; },
        {},
        level);
    EXPECT_TRUE(data.has_value()) << m_messages;
    return data.value_or(GeometryData{});
  }
  static float largest(const GeometryData &data, int axis)
  {
    float out = -INFINITY;
    for (size_t i = axis; i < data.positions.size(); i += 3)
      out = std::max(out, data.positions[i]);
    return out;
  }
  // The index of the vertex nearest `p`.
  static size_t nearest(const GeometryData &data, std::array<float, 3> p)
  {
    size_t best = 0;
    float bestDistance = INFINITY;
    for (size_t i = 0; i < data.positions.size() / 3; ++i) {
      const float d = std::hypot(data.positions[3 * i] - p[0],
          data.positions[3 * i + 1] - p[1],
          data.positions[3 * i + 2] - p[2]);
      if (d < bestDistance) {
        bestDistance = d;
        best = i;
      }
    }
    return best;
  }

  Node m_mesh;
  std::string m_messages;
};

TEST_F(Subdivision, CubeFaceCentresReachTheLimitSurface)
{
  for (int level : {1, 2, 3, 4}) {
    const GeometryData data = build(level);
    EXPECT_EQ(m_messages, "");
    // 6 * 4^level quads, two triangles each, each vertex its own.
    const size_t quads = 6 * (size_t(1) << (2 * level));
    EXPECT_EQ(data.triangles.size(), 6 * quads) << level;
    EXPECT_EQ(data.positions.size(), 12 * quads) << level;
    EXPECT_NEAR(largest(data, 0), kLimitHalfWidth, 1e-5) << level;
    EXPECT_NEAR(largest(data, 2), kLimitHalfWidth, 1e-5) << level;
    // Every triangle keeps the cage face it came from.
    EXPECT_EQ(
        *std::max_element(data.triangleFaces.begin(), data.triangleFaces.end()),
        5u);
  }
}

TEST_F(Subdivision, LimitNormalsPointOutward)
{
  const GeometryData data = build(2);
  ASSERT_EQ(data.normals.size(), data.positions.size());
  const size_t centre = nearest(data, {float(kLimitHalfWidth), 0, 0});
  EXPECT_NEAR(data.normals[3 * centre], 1, 1e-5);
  // Clockwise winding turns the faces, and their normals, inside out.
  set("clockwisewinding", numbers(NSITypeInteger, std::vector<int>{1}));
  const GeometryData flipped = build(2);
  EXPECT_NEAR(flipped.normals[3 * centre], -1, 1e-5);
  EXPECT_EQ(flipped.triangles[1], data.triangles[2]);
}

TEST_F(Subdivision, InfinitelySharpCreasesKeepTheCube)
{
  set("subdivision.creasevertices", numbers(NSITypeInteger, kCubeEdges));
  set("subdivision.creasesharpness",
      numbers(NSITypeFloat, std::vector<float>(12, 10.f)));
  const GeometryData data = build(3);
  EXPECT_EQ(m_messages, "");
  EXPECT_NEAR(largest(data, 0), 0.5, 1e-6);
  // The edges stay straight: the edge from (.5,-.5,.5) to (.5,.5,.5) has
  // its midpoint on it.
  const size_t mid = nearest(data, {0.5f, 0, 0.5f});
  EXPECT_NEAR(data.positions[3 * mid], 0.5, 1e-6);
  EXPECT_NEAR(data.positions[3 * mid + 2], 0.5, 1e-6);
}

TEST_F(Subdivision, OneSharpEdgeFoldsWhereTheOthersRound)
{
  // Only the edge from point 5 to point 7 (x = z = 0.5) is sharp.
  set("subdivision.creasevertices",
      numbers(NSITypeInteger, std::vector<int>{5, 7}));
  set("subdivision.creasesharpness",
      numbers(NSITypeFloat, std::vector<float>{10}));
  const GeometryData data = build(3);
  EXPECT_EQ(m_messages, "");
  // The normals met at an edge's midpoint, one per face vertex there: the
  // widest angle between them, in degrees.
  auto fold = [&](std::array<float, 3> p) {
    const size_t at = nearest(data, p);
    std::vector<std::array<float, 3>> normals;
    for (size_t i = 0; i < data.positions.size() / 3; ++i) {
      if (std::hypot(data.positions[3 * i] - data.positions[3 * at],
              data.positions[3 * i + 1] - data.positions[3 * at + 1],
              data.positions[3 * i + 2] - data.positions[3 * at + 2])
          < 1e-6)
        normals.push_back({data.normals[3 * i],
            data.normals[3 * i + 1],
            data.normals[3 * i + 2]});
    }
    double widest = 0;
    for (auto &a : normals)
      for (auto &b : normals)
        widest = std::max(widest,
            std::acos(std::clamp(
                double(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]), -1.0, 1.0))
                * 180 / M_PI);
    return std::pair(normals.size(), widest);
  };
  const auto [sharpCount, sharpAngle] = fold({0.5f, 0, 0.5f});
  const auto [smoothCount, smoothAngle] = fold({-0.5f, 0, 0.5f});
  EXPECT_EQ(sharpCount, 4u);
  EXPECT_EQ(smoothCount, 4u);
  EXPECT_GT(sharpAngle, 60) << "the crease folds the surface";
  EXPECT_LT(smoothAngle, 1) << "a smooth edge does not";
  // And the crease stays out nearer the cage's edge than the smooth one.
  const size_t sharp = nearest(data, {0.5f, 0, 0.5f});
  const size_t smooth = nearest(data, {-0.5f, 0, 0.5f});
  EXPECT_GT(data.positions[3 * sharp], -data.positions[3 * smooth] + 0.05f);
}

TEST_F(Subdivision, SharpCornersStayAtTheirPoints)
{
  set("subdivision.cornervertices",
      numbers(NSITypeInteger, std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  set("subdivision.cornersharpness",
      numbers(NSITypeFloat, std::vector<float>(8, 10.f)));
  const GeometryData data = build(3);
  EXPECT_EQ(m_messages, "");
  const size_t corner = nearest(data, {0.5f, 0.5f, 0.5f});
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(data.positions[3 * corner + c], 0.5, 1e-6);
  // Faces still round: the face centre is inside the cage's.
  const size_t centre = nearest(data, {0.5f, 0, 0});
  EXPECT_LT(data.positions[3 * centre], 0.48f);
  EXPECT_GT(data.positions[3 * centre], float(kLimitHalfWidth));
}

TEST_F(Subdivision, TexcoordsAndColorsAreRefined)
{
  std::vector<float> st, colors;
  for (int i = 0; i < 8; ++i) {
    st.insert(st.end(), {float(i & 1), float((i & 2) / 2)});
    colors.insert(colors.end(), {float(i & 1), 0, 1});
  }
  Value stValue = numbers(NSITypeFloat, st);
  stValue.arraylength = 2;
  stValue.flags = NSIParamIsArray;
  stValue.count = 8;
  set("st", stValue);
  set("Cs", numbers(NSITypeColor, colors, 3));
  const GeometryData data = build(2);
  EXPECT_EQ(m_messages, "");
  ASSERT_EQ(data.texcoords.size(), data.positions.size() / 3 * 2);
  ASSERT_EQ(data.colors.size(), data.positions.size());
  // Red follows x (0 at the -x face, 1 at the +x face); blue stays 1.
  const size_t right = nearest(data, {float(kLimitHalfWidth), 0, 0});
  const size_t left = nearest(data, {-float(kLimitHalfWidth), 0, 0});
  EXPECT_GT(data.colors[3 * right], 0.8f);
  EXPECT_LT(data.colors[3 * left], 0.2f);
  EXPECT_NEAR(data.colors[3 * right + 2], 1, 1e-5);
  for (float v : data.texcoords) {
    EXPECT_GE(v, -1e-5f);
    EXPECT_LE(v, 1 + 1e-5f);
  }
}

TEST_F(Subdivision, LevelZeroSchemesAndBadCreasesFallBack)
{
  EXPECT_EQ(build(0).triangles.size(), 36u) << "the cage's 12 triangles";
  set("subdivision.scheme", text("loop"));
  EXPECT_EQ(build(3).triangles.size(), 36u);
  EXPECT_NE(m_messages.find("'loop' is not supported"), std::string::npos);
  m_messages.clear();
  set("subdivision.scheme", text("catmull-clark"));
  set("subdivision.creasevertices",
      numbers(NSITypeInteger, std::vector<int>{0, 99}));
  set("subdivision.creasesharpness",
      numbers(NSITypeFloat, std::vector<float>{10}));
  set("subdivision.level", numbers(NSITypeInteger, std::vector<int>{1}));
  const GeometryData data = build(3);
  EXPECT_NE(m_messages.find("outside 'P'"), std::string::npos) << m_messages;
  EXPECT_EQ(data.triangles.size(), 6u * 4 * 6) << "the mesh's own level 1";
}

// Moving points are refined at each shutter time: the limit surface of a
// moved cage is the first one moved (the scheme is affine invariant).
TEST_F(Subdivision, MovingPointsAreRefinedAtEachTime)
{
  const Value still = *m_mesh.attributes["P"].value;
  std::vector<float> moved;
  for (int i = 0; i < 8; ++i)
    moved.insert(
        moved.end(), {(i & 1) + 0.5f, (i & 2) / 2 - 0.5f, (i & 4) / 4 - 0.5f});
  m_mesh.attributes["P"].value.reset();
  m_mesh.attributes["P"].samples = {
      {0.0, still}, {1.0, numbers(NSITypePoint, moved, 3)}};
  auto data = buildMesh(
      "cube",
      m_mesh,
      [this](int, const std::string &message) { m_messages += message; },
      {0.0, 1.0},
      2);
  ASSERT_TRUE(data.has_value()) << m_messages;
  EXPECT_EQ(m_messages, "");
  ASSERT_EQ(data->positionKeys.size(), 2u);
  ASSERT_EQ(data->positionKeys[1].size(), data->positions.size());
  EXPECT_EQ(data->positionKeys[0], data->positions);
  for (size_t i = 0; i < data->positions.size(); ++i)
    EXPECT_NEAR(data->positionKeys[1][i] - data->positions[i],
        i % 3 == 0 ? 1.f : 0.f,
        1e-5f);
}

// Topology OpenSubdiv may dislike never crashes: each mesh renders
// (refined, or its cage with a warning).
TEST_F(Subdivision, OddTopologyNeverCrashes)
{
  auto mesh = [&](std::vector<int> counts, std::vector<int> indices) {
    m_mesh.attributes.erase("P.indices");
    set("nvertices", numbers(NSITypeInteger, counts));
    set("P.indices", numbers(NSITypeInteger, indices));
    m_messages.clear();
    return build(2);
  };
  // A point repeated in one face; three faces on one edge; a lone triangle
  // and a pentagon; a crease between points that share no edge.
  EXPECT_FALSE(mesh({4}, {0, 1, 1, 2}).triangles.empty()) << m_messages;
  EXPECT_FALSE(
      mesh({4, 4, 4}, {0, 1, 3, 2, 0, 1, 5, 4, 0, 1, 7, 6}).triangles.empty())
      << m_messages;
  EXPECT_NE(m_messages.find("non-manifold cage"), std::string::npos);
  EXPECT_FALSE(mesh({3, 5}, {0, 1, 3, 4, 5, 7, 6, 2}).triangles.empty())
      << m_messages;
  set("subdivision.creasevertices",
      numbers(NSITypeInteger, std::vector<int>{0, 7}));
  set("subdivision.creasesharpness",
      numbers(NSITypeFloat, std::vector<float>{10}));
  EXPECT_FALSE(mesh({4}, {0, 1, 3, 2}).triangles.empty()) << m_messages;
  EXPECT_NE(m_messages.find("OpenSubdiv: Edge 0 specified to be sharp does "
                            "not exist"),
      std::string::npos)
      << m_messages;
  // NaN points stay NaN points: no crash, whatever is drawn.
  set("P", numbers(NSITypePoint, std::vector<float>(24, NAN), 3));
  mesh({4, 4}, {0, 1, 3, 2, 4, 5, 7, 6});
}

// A level that would make more than a million quads is lowered, warned.
TEST_F(Subdivision, LevelsPastAMillionQuadsAreLowered)
{
  using prism::nsi::refinementLevelWithin;
  // The cube's 6 faces: 24 quads after one refinement, 393,216 after
  // eight, within 2^20.
  EXPECT_EQ(refinementLevelWithin({4, 4, 4, 4, 4, 4}, 8), 8);
  // 1000 quads: 4000 after one refinement, 1,024,000 after five; a sixth
  // would pass 2^20.
  EXPECT_EQ(refinementLevelWithin(std::vector<int>(1000, 4), 8), 5);
  EXPECT_EQ(refinementLevelWithin(std::vector<int>(1000, 4), 2), 2);
  // One refinement always (a huge cage still becomes quads).
  EXPECT_EQ(refinementLevelWithin(std::vector<int>(1 << 20, 4), 3), 1);
}

TEST_F(Subdivision, ManyFacesAreRefinedFewerTimes)
{
  set("subdivision.level", numbers(NSITypeInteger, std::vector<int>{8}));
  // 1000 cubes' faces at level 8 would be 4000 * 4^7 quads: level 5.
  std::vector<int> indices;
  for (int k = 0; k < 1000; ++k)
    indices.insert(indices.end(), {0, 2, 3, 1});
  m_mesh.attributes.erase("P.indices");
  set("P.indices", numbers(NSITypeInteger, indices));
  set("nvertices", numbers(NSITypeInteger, std::vector<int>(1000, 4)));
  build(3);
  EXPECT_NE(m_messages.find("level 5 is rendered"), std::string::npos)
      << m_messages;
}

} // namespace
