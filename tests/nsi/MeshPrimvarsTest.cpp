// A mesh's N, st and Cs reach GeometryData with one value per face vertex,
// whichever way NSI gave them; bad ones are reported and dropped.
#include "GeometryBuilder.h"

#include <gtest/gtest.h>

#include <cstring>

namespace {

using prism::nsi::buildMesh;
using prism::nsi::GeometryData;
using prism::nsi::Node;
using prism::nsi::Value;

Value floats(int type, const std::vector<float> &v, int flags = 0)
{
  Value value;
  value.type = type;
  value.flags = flags;
  value.count = v.size() / Value::componentsOf(type);
  if (type == NSITypeFloat && flags & NSIParamIsArray) {
    value.arraylength = 2;
    value.count = v.size() / 2;
  }
  value.bytes.resize(v.size() * 4);
  std::memcpy(value.bytes.data(), v.data(), v.size() * 4);
  return value;
}

Value ints(const std::vector<int> &v)
{
  Value value;
  value.type = NSITypeInteger;
  value.count = v.size();
  value.bytes.resize(v.size() * 4);
  std::memcpy(value.bytes.data(), v.data(), v.size() * 4);
  return value;
}

class MeshPrimvars : public ::testing::Test
{
 protected:
  // Two quads sharing an edge: points 0-5, face vertices 0 1 4 3, 1 2 5 4.
  MeshPrimvars()
  {
    set("nvertices", ints({4, 4}));
    set("P",
        floats(NSITypePoint,
            {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0}));
    set("P.indices", ints({0, 1, 4, 3, 1, 2, 5, 4}));
  }
  void set(const std::string &name, const Value &value)
  {
    m_mesh.attributes[name].value = value;
  }
  GeometryData build()
  {
    auto data = buildMesh("m", m_mesh, [this](int, const std::string &text) {
      m_messages += text + "\n";
    });
    EXPECT_TRUE(data);
    return data ? *data : GeometryData{};
  }
  Node m_mesh{"mesh", {}, {}, {}};
  std::string m_messages;
};

TEST_F(MeshPrimvars, FaceVaryingColorsFollowTheirIndices)
{
  // Three colours; the shared edge's corners differ between the faces.
  set("Cs", floats(NSITypeColor, {1, 0, 0, 0, 1, 0, 0, 0, 1}));
  set("Cs.indices", ints({0, 1, 1, 0, 2, 2, 2, 2}));
  const GeometryData data = build();
  EXPECT_EQ(m_messages, "");
  ASSERT_EQ(data.colors.size(), 8u * 3);
  EXPECT_EQ(data.colors[3 * 1 + 1], 1.f) << "face 0, corner 1: green";
  EXPECT_EQ(data.colors[3 * 4 + 2], 1.f) << "face 1, corner 0: blue";
  EXPECT_EQ(data.positions[3 * 1], data.positions[3 * 4])
      << "the same point with two colours";
}

TEST_F(MeshPrimvars, PerPointValuesAreSharedThroughPIndices)
{
  set("N",
      floats(NSITypeNormal,
          {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1}));
  const GeometryData data = build();
  EXPECT_EQ(m_messages, "");
  ASSERT_EQ(data.normals.size(), 8u * 3);
  // Point 4 is face vertex 2 and 7.
  EXPECT_EQ(data.normals[3 * 2], 1.f);
  EXPECT_EQ(data.normals[3 * 7], 1.f);
  EXPECT_EQ(data.normals[3 * 0 + 2], 1.f);
}

TEST_F(MeshPrimvars, StPerFaceVertexAndPerFaceAndConstant)
{
  set("st",
      floats(NSITypeFloat,
          {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 3, 0, 3, 1, 2, 1},
          NSIParamIsArray));
  set("Cs", floats(NSITypeColor, {1, 0, 0, 0, 1, 0}, NSIParamPerFace));
  set("N", floats(NSITypeNormal, {0, 1, 0}));
  const GeometryData data = build();
  EXPECT_EQ(m_messages, "");
  ASSERT_EQ(data.texcoords.size(), 8u * 2);
  EXPECT_EQ(data.texcoords[2 * 5], 3.f);
  ASSERT_EQ(data.colors.size(), 8u * 3);
  EXPECT_EQ(data.colors[3 * 3], 1.f) << "face 0 red";
  EXPECT_EQ(data.colors[3 * 4 + 1], 1.f) << "face 1 green";
  ASSERT_EQ(data.normals.size(), 8u * 3);
  EXPECT_EQ(data.normals[3 * 6 + 1], 1.f);
}

TEST_F(MeshPrimvars, BadDataIsReportedAndDropped)
{
  set("Cs", floats(NSITypeColor, {1, 0, 0, 0, 1, 0}));
  set("Cs.indices", ints({0, 1, 1, 0, 2, 2, 2, 2})); // 2 is out of range
  set("N", floats(NSITypeNormal, {0, 0, 1}));
  set("N.indices", ints({0, 0, 0})); // too few
  set("st", ints({1, 2, 3}));        // not pairs
  Value name;
  name.type = NSITypeString;
  name.count = 1;
  name.strings = {"red"};
  const GeometryData data = build();
  EXPECT_TRUE(data.colors.empty());
  EXPECT_TRUE(data.normals.empty());
  EXPECT_TRUE(data.texcoords.empty());
  EXPECT_NE(m_messages.find("'Cs' has index 2"), std::string::npos)
      << m_messages;
  EXPECT_NE(m_messages.find("'N' has 3 indices for 8"), std::string::npos)
      << m_messages;
  EXPECT_NE(m_messages.find("'st' is not 2 numbers"), std::string::npos)
      << m_messages;

  m_messages.clear();
  set("Cs", name); // a string where a colour belongs
  m_mesh.attributes.erase("Cs.indices");
  m_mesh.attributes.erase("N.indices");
  m_mesh.attributes.erase("st");
  const GeometryData again = build();
  EXPECT_TRUE(again.colors.empty());
  EXPECT_NE(m_messages.find("'Cs' is not 3 numbers"), std::string::npos)
      << m_messages;
}

} // namespace
