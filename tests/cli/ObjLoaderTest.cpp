// prism-render's OBJ pieces that need no device: the parser (every number
// and index checked), polygon triangulation and the per-material batches.
#include "ObjBatches.h"
#include "ObjParser.h"
#include "PolygonTriangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace prism::scene_io;
using Corners = std::vector<std::array<float, 3>>;

// A regular polygon of n corners in the xy plane (convex).
Corners regularPolygon(size_t n)
{
  Corners corners(n);
  for (size_t i = 0; i < n; i++) {
    const double a = 2.0 * std::numbers::pi * double(i) / double(n);
    corners[i] = {float(std::cos(a)), float(std::sin(a)), 0.f};
  }
  return corners;
}

// A star of n corners: every other corner pulled in to radius 0.5.
Corners star(size_t n)
{
  Corners corners = regularPolygon(n);
  for (size_t i = 1; i < n; i += 2) {
    corners[i][0] *= 0.5f;
    corners[i][1] *= 0.5f;
  }
  return corners;
}

double signedArea(const std::array<float, 3> &a,
    const std::array<float, 3> &b,
    const std::array<float, 3> &c)
{
  return 0.5
         * ((double(b[0]) - a[0]) * (double(c[1]) - a[1])
             - (double(b[1]) - a[1]) * (double(c[0]) - a[0]));
}

double polygonArea(const Corners &p)
{
  double twice = 0.0;
  for (size_t i = 0; i < p.size(); i++) {
    const auto &a = p[i], &b = p[(i + 1) % p.size()];
    twice += double(a[0]) * b[1] - double(b[0]) * a[1];
  }
  return 0.5 * twice;
}

// An OBJ of one n-corner regular polygon.
std::string bigFaceObj(size_t n)
{
  std::string text;
  text.reserve(n * 40);
  char line[64];
  for (const auto &c : regularPolygon(n)) {
    std::snprintf(line, sizeof(line), "v %.7g %.7g 0\n", c[0], c[1]);
    text += line;
  }
  text += "f";
  for (size_t i = 1; i <= n; i++) {
    std::snprintf(line, sizeof(line), " %zu", i);
    text += line;
  }
  text += "\n";
  return text;
}

TEST(PolygonTriangulation, HugeConvexFaceIsAFan)
{
  const size_t n = 200'000;
  const PolygonTriangles t = triangulatePolygon(regularPolygon(n));
  ASSERT_EQ(t.triangles.size(), n - 2);
  EXPECT_FALSE(t.fannedConcave);
  EXPECT_EQ(t.triangles.back(),
      (std::array<uint32_t, 3>{0, uint32_t(n - 2), uint32_t(n - 1)}));
}

TEST(PolygonTriangulation, HugeConcaveFaceIsFannedAndFlagged)
{
  const size_t n = 200'000;
  const PolygonTriangles t = triangulatePolygon(star(n));
  EXPECT_EQ(t.triangles.size(), n - 2);
  EXPECT_TRUE(t.fannedConcave);
}

// Ear clipping covers exactly the polygon: every triangle turns the
// polygon's way and their areas add up to its area (a fan of a star would
// not: some of its triangles lie outside and turn the other way).
TEST(PolygonTriangulation, ConcaveFaceIsEarClipped)
{
  for (size_t n : {size_t(6),
           size_t(10),
           size_t(64),
           size_t(1000),
           kMaxEarClippingCorners}) {
    const Corners p = star(n);
    const PolygonTriangles t = triangulatePolygon(p);
    ASSERT_EQ(t.triangles.size(), n - 2) << n;
    EXPECT_FALSE(t.fannedConcave);
    double sum = 0.0;
    for (const auto &tri : t.triangles) {
      const double area = signedArea(p[tri[0]], p[tri[1]], p[tri[2]]);
      EXPECT_GE(area, -1e-9) << n;
      sum += area;
    }
    EXPECT_NEAR(sum, polygonArea(p), 1e-6 * polygonArea(p)) << n;
  }
}

// A U in the xz plane, wound clockwise as seen from +y. A fan from corner 0
// would cross the notch (triangles of both windings, more total area than
// the U's 5); ear clipping must cover exactly the U.
TEST(PolygonTriangulation, TiltedClockwiseConcaveFace)
{
  const Corners u = {{0, 0, 0},
      {0, 0, 2},
      {1, 0, 2},
      {1, 0, 1},
      {2, 0, 1},
      {2, 0, 2},
      {3, 0, 2},
      {3, 0, 0}};
  const PolygonTriangles t = triangulatePolygon(u);
  ASSERT_EQ(t.triangles.size(), 6u);
  double sum = 0.0;
  for (const auto &tri : t.triangles) {
    const auto &a = u[tri[0]], &b = u[tri[1]], &c = u[tri[2]];
    sum += std::fabs(0.5
                     * ((double(b[0]) - a[0]) * (double(c[2]) - a[2])
                         - (double(b[2]) - a[2]) * (double(c[0]) - a[0])));
  }
  EXPECT_NEAR(sum, 5.0, 1e-9);
}

TEST(PolygonTriangulation, DegenerateFacesStillGiveNMinus2)
{
  // Every corner on one line; repeated corners; a self-crossing bow tie.
  const Corners line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  EXPECT_EQ(triangulatePolygon(line).triangles.size(), 3u);
  const Corners repeated = {{0, 0, 0},
      {1, 0, 0},
      {1, 0, 0},
      {1, 1, 0},
      {0.5f, 0.2f, 0},
      {0, 1, 0},
      {0, 1, 0}};
  EXPECT_EQ(triangulatePolygon(repeated).triangles.size(), 5u);
  const Corners bowTie = {
      {0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}, {1, 3, 0}, {-1, 1, 0}};
  EXPECT_EQ(triangulatePolygon(bowTie).triangles.size(), 4u);
  EXPECT_TRUE(triangulatePolygon({{0, 0, 0}, {1, 0, 0}}).triangles.empty());
}

TEST(ObjParser, ReadsStatements)
{
  const ObjParseResult r = parseObj(
      "# comment\r\nmtllib a.mtl b.mtl\r\nv 0 0 0 1 0 0\nv 1 0 0\n"
      "v 1 1 0\nv 0 1 0 0.5\nvt 0 0\nvt 1\nvn 0 0 1\n"
      "o thing\ng group\ns 1\nusemtl red\nf 1/1/1 2/2/1 3/1/1 4/2/1\n"
      "usemtl blue\nf -4//1 -3//1 -2//1\nusemtl red\nf 1 2 3\n"
      "l 1 2\np 3\nf 1 2\n");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.positions.size(), 4u);
  ASSERT_EQ(r.colors.size(), 4u);
  EXPECT_EQ(r.colors[0], (std::array<float, 3>{1.f, 0.f, 0.f}));
  EXPECT_EQ(r.colors[3], (std::array<float, 3>{1.f, 1.f, 1.f}));
  EXPECT_EQ(r.uvs[1], (std::array<float, 2>{1.f, 0.f}));
  EXPECT_EQ(r.materialLibraries, (std::vector<std::string>{"a.mtl", "b.mtl"}));
  EXPECT_EQ(r.materialNames, (std::vector<std::string>{"red", "blue"}));
  ASSERT_EQ(r.faces.size(), 3u);
  EXPECT_EQ(r.faces[0].cornerCount, 4u);
  EXPECT_EQ(r.faces[0].material, 0);
  EXPECT_EQ(r.faces[1].material, 1);
  EXPECT_EQ(r.faces[2].material, 0);
  EXPECT_EQ(r.faces[1].line, 16u); // CRLF counts as one line end
  EXPECT_EQ(r.corners[1].uv, 1);
  EXPECT_EQ(r.corners[1].normal, 0);
  // Relative indices count back from the vertices read so far.
  EXPECT_EQ(r.corners[4].position, 0u);
  EXPECT_EQ(r.corners[4].uv, -1);
  EXPECT_EQ(r.corners[6].position, 2u);
  EXPECT_EQ(r.linesAndPoints, 2u);
  EXPECT_EQ(r.shortFaces, 1u);
  EXPECT_EQ(r.badValues.count, 0u);
}

// tinyobjloader read these as 0, or as a float infinity: here each is
// counted and stored as NaN for the batches to drop.
TEST(ObjParser, ValuesThatAreNotFiniteNumbers)
{
  const ObjParseResult r = parseObj(
      "v 0 0 0\nv nan 0 0\nv 0 inf 0\nv 0 0 1e39\nv 1 2\nv 1 1 x\n"
      "v -1e38 1e-50 0\nvn 0 0 -inf\nvt NaN 0\nv 0 0 0 1 nan 1\n"
      "v 0 0 0 nan\n");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.badValues.count, 8u);
  EXPECT_EQ(r.badValues.firstLine, 2u);
  EXPECT_EQ(r.badValues.firstText, "nan");
  EXPECT_TRUE(std::isnan(r.positions[1][0]));
  EXPECT_TRUE(std::isnan(r.positions[2][1]));
  EXPECT_TRUE(std::isnan(r.positions[3][2])); // 1e39 overflows a float
  EXPECT_TRUE(std::isnan(r.positions[4][2])); // missing
  EXPECT_TRUE(std::isnan(r.positions[5][2])); // not a number
  EXPECT_EQ(r.positions[6][0], -1e38f);       // finite: kept
  EXPECT_EQ(r.positions[6][1], 0.f);          // underflow is just 0
  EXPECT_TRUE(std::isnan(r.normals[0][2]));
  EXPECT_TRUE(std::isnan(r.uvs[0][0]));
  EXPECT_TRUE(std::isnan(r.colors[7][1]));
  EXPECT_EQ(r.positions[8][0], 0.f); // a NaN weight w is ignored
}

// Each of these is an error naming the index and the line (tinyobjloader's
// atoi wrapped 2^63 to -1, the last vertex, and 2^32 + 1 to vertex 1).
TEST(ObjParser, IndicesOutOfRange)
{
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::pair<const char *, const char *> cases[] = {
      {"f 1 2 9223372036854775808\n",
          "a face uses vertex 9223372036854775808 but the file has 3 (line 4)"},
      {"f 1 2 4294967297\n",
          "a face uses vertex 4294967297 but the file has 3 (line 4)"},
      {"f 1 2 99999999999999999999999\n",
          "a face uses vertex 99999999999999999999999 but the file has 3"},
      {"f 1 2 0\n", "a face uses vertex 0 but the file has 3 (line 4)"},
      {"f 1 2 -4\n", "a face uses vertex -4 but the file has 3 (line 4)"},
      {"f 1 2 4\n", "a face uses vertex 4 but the file has 3 (line 4)"},
      {"f 1 2 -9223372036854775809\n", "a face uses vertex -922337203685477"},
      {"vt 0 0\nf 1/1 2/1 3/2\n",
          "a face uses texture coordinate 2 but the file has 1"},
      {"vn 0 0 1\nf 1//1 2//1 3//2\n",
          "a face uses normal 2 but the file has 1 (line 5)"},
      {"f 1 2 x\n", "'x' is not a face corner (line 4)"},
      {"f 1 2 3/1/1/1\n", "'3/1/1/1' is not a face corner"},
      {"f 1 2 /1\n", "'/1' is not a face corner"},
      {"f 1 2 3.0\n", "'3.0' is not a face corner"},
  };
  for (const auto &[face, message] : cases) {
    const ObjParseResult r = parseObj(vertices + face);
    EXPECT_FALSE(r.ok()) << face;
    EXPECT_NE(r.error.find(message), std::string::npos)
        << face << " gave: " << r.error;
  }
  // A forward reference is fine: the vertex comes later in the file.
  const ObjParseResult forward = parseObj(vertices + "f 1 2 4\nv 1 1 1\n");
  EXPECT_TRUE(forward.ok()) << forward.error;
}

// Exporters write "f 1//1" whether or not they wrote any vn (tinyobjloader's
// own catmark_torus_creases0.obj does): a file with no normals (or no
// texture coordinates) at all has its faces used without them, and says
// how many corners named one; a file with some is held to them (above).
TEST(ObjParser, CornersNamingWhatTheFileLacks)
{
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const ObjParseResult normals = parseObj(vertices + "f 1//1 2//2 3//3\n");
  ASSERT_TRUE(normals.ok()) << normals.error;
  EXPECT_EQ(normals.cornersWithoutNormals, 3u);
  EXPECT_EQ(normals.cornersWithoutUvs, 0u);
  for (const ObjCorner &c : normals.corners)
    EXPECT_EQ(c.normal, -1);
  const ObjParseResult both = parseObj(vertices + "f 1/1/1 2/2/2 3/3/3\n");
  ASSERT_TRUE(both.ok()) << both.error;
  EXPECT_EQ(both.cornersWithoutNormals, 3u);
  EXPECT_EQ(both.cornersWithoutUvs, 3u);
  for (const ObjCorner &c : both.corners)
    EXPECT_EQ(c.uv, -1);
  // Positions are never optional.
  EXPECT_FALSE(parseObj("f 1//1 2//2 3//3\n").ok());
}

TEST(ObjParser, FacesOfMoreThan255Corners)
{
  const ObjParseResult r = parseObj(bigFaceObj(300));
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.faces.size(), 1u);
  EXPECT_EQ(r.faces[0].cornerCount, 300u);
}

// The brief's case: a 200k-corner face once took minutes (quadratic ear
// clipping); it must load with one triangle per corner but two.
TEST(ObjBatches, HugeFaceLoadsWithNMinus2Triangles)
{
  const size_t n = 200'000;
  const ObjParseResult r = parseObj(bigFaceObj(n));
  ASSERT_TRUE(r.ok()) << r.error;
  const ObjBatches b = buildObjBatches(r, {});
  ASSERT_EQ(b.byMaterial.size(), 1u);
  const ObjBatch &batch = b.byMaterial.begin()->second;
  EXPECT_EQ(batch.triangles.size(), n - 2);
  EXPECT_EQ(batch.positions.size(), n);
  EXPECT_EQ(b.fannedConcave, 0u);
}

TEST(ObjBatches, FacesUsingNonFiniteValuesAreDropped)
{
  const ObjParseResult r = parseObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 1 0\nv 1 1 1e39\nvn 0 0 inf\n"
      "vt 0 0\nvt inf 0\n"
      "f 1 2 3\nf 1 2 4\nf 2 3 5\nf 1//1 2//1 3//1\nf 1/2 2/1 3/1\n"
      "f 1/1 2/1 3/1\n");
  ASSERT_TRUE(r.ok()) << r.error;
  const ObjBatches b = buildObjBatches(r, {});
  EXPECT_EQ(b.droppedFaces, 4u);
  ASSERT_EQ(b.byMaterial.size(), 1u);
  const ObjBatch &batch = b.byMaterial.begin()->second;
  EXPECT_EQ(batch.triangles.size(), 2u);
  for (const auto &p : batch.positions)
    for (float x : p)
      EXPECT_TRUE(std::isfinite(x));
  for (const auto &uv : batch.uvs)
    for (float x : uv)
      EXPECT_TRUE(std::isfinite(x));
}

TEST(ObjBatches, MaterialsAndMergedCorners)
{
  const ObjParseResult r = parseObj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl a\nf 1 2 3 4\n"
      "usemtl missing\nf 1 2 3\n");
  ASSERT_TRUE(r.ok()) << r.error;
  // "a" is MTL material 5; "missing" is in no library.
  const ObjBatches b = buildObjBatches(r, {5, -1});
  ASSERT_EQ(b.byMaterial.size(), 2u);
  EXPECT_EQ(b.byMaterial.at(6).triangles.size(), 2u);
  EXPECT_EQ(b.byMaterial.at(6).positions.size(), 4u); // the quad's corners
  EXPECT_EQ(b.byMaterial.at(0).triangles.size(), 1u);
  EXPECT_FALSE(b.byMaterial.at(0).allNormals);
}

} // namespace
