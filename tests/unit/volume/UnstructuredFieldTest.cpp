// The unstructured spatial field against fields with known values: linear
// fields reproduced exactly by every cell type (trilinear ones by boxes),
// cell values, NaN outside the mesh, continuity across shared faces,
// conservative value ranges, every kind of malformed mesh reported, and
// the application's arrays not needed after commit.
#include "MeshTestFixture.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <random>

namespace prism {
namespace {

using testing::hexahedronGrid;
using testing::kHexahedron;
using testing::kPyramid;
using testing::kTetra;
using testing::kWedge;
using testing::Mesh;

// The reference cells, unit sized, in VTK's vertex order.
Mesh referenceCell(uint8_t type)
{
  Mesh mesh;
  switch (type) {
  case kTetra:
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.addCell(type, {0, 1, 2, 3});
    break;
  case kHexahedron:
    mesh.positions = {{0, 0, 0},
        {1, 0, 0},
        {1, 1, 0},
        {0, 1, 0},
        {0, 0, 1},
        {1, 0, 1},
        {1, 1, 1},
        {0, 1, 1}};
    mesh.addCell(type, {0, 1, 2, 3, 4, 5, 6, 7});
    break;
  case kWedge:
    mesh.positions = {
        {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    mesh.addCell(type, {0, 1, 2, 3, 4, 5});
    break;
  case kPyramid:
    mesh.positions = {
        {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1}};
    mesh.addCell(type, {0, 1, 2, 3, 4});
    break;
  }
  return mesh;
}

// A point of the cell from parametric coordinates (VTK's shape functions,
// written out here independently of the device's).
float3 cellPoint(uint8_t type, const std::vector<float3> &v, float3 p)
{
  const float r = p.x, s = p.y, t = p.z;
  switch (type) {
  case kTetra:
    return (1 - r - s - t) * v[0] + r * v[1] + s * v[2] + t * v[3];
  case kWedge:
    return (1 - t) * ((1 - r - s) * v[0] + r * v[1] + s * v[2])
           + t * ((1 - r - s) * v[3] + r * v[4] + s * v[5]);
  case kPyramid:
    return (1 - t)
               * ((1 - r) * (1 - s) * v[0] + r * (1 - s) * v[1] + r * s * v[2]
                   + (1 - r) * s * v[3])
           + t * v[4];
  default:
    return (1 - t)
               * ((1 - r) * (1 - s) * v[0] + r * (1 - s) * v[1] + r * s * v[2]
                   + (1 - r) * s * v[3])
           + t
                 * ((1 - r) * (1 - s) * v[4] + r * (1 - s) * v[5] + r * s * v[6]
                     + (1 - r) * s * v[7]);
  }
}

// Random parametric coordinates strictly inside the cell type's domain.
float3 randomParametric(uint8_t type, std::mt19937 &rng)
{
  std::uniform_real_distribution<float> u(0.02f, 0.98f);
  for (;;) {
    const float3 p{u(rng), u(rng), u(rng)};
    if (type == kTetra && p.x + p.y + p.z > 0.98f)
      continue;
    if (type == kWedge && p.x + p.y > 0.98f)
      continue;
    return p;
  }
}

// A hexahedron [0,1]^3 with a wedge on its y = 1 face, a pyramid on its
// x = 1 face and a tetrahedron on one of the pyramid's triangles: every
// cell type, each sharing a face with another.
Mesh mixedMesh()
{
  Mesh mesh;
  mesh.positions = {{0, 0, 0},
      {1, 0, 0},
      {1, 1, 0},
      {0, 1, 0},
      {0, 0, 1},
      {1, 0, 1},
      {1, 1, 1},
      {0, 1, 1},
      {0.5f, 2, 0}, // 8, 9: the wedge's third edge
      {0.5f, 2, 1},
      {1.5f, 0.5f, 0.5f},   // 10: the pyramid's apex
      {1.5f, 0.5f, -0.5f}}; // 11: the tetrahedron's last vertex
  mesh.addCell(kHexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  mesh.addCell(kWedge, {3, 2, 8, 7, 6, 9});
  mesh.addCell(kPyramid, {1, 2, 6, 5, 10});
  mesh.addCell(kTetra, {1, 2, 10, 11});
  return mesh;
}

float nonlinear(float3 p)
{
  return p.x * p.x + 2.f * p.y * p.z + p.z - 0.5f * p.x * p.y * p.z;
}

class UnstructuredFieldTest : public testing::MeshTestFixture
{};

TEST_F(UnstructuredFieldTest, EveryCellTypeReproducesLinearFields)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> jitter(-0.15f, 0.15f);
  auto linear = [](float3 p) {
    return 0.5f + 2.f * p.x - 3.f * p.y + 1.5f * p.z;
  };
  for (uint8_t type : {kTetra, kHexahedron, kWedge, kPyramid}) {
    for (int trial = 0; trial < 20; trial++) {
      Mesh mesh = referenceCell(type);
      // Distorted cells (non-planar hexahedron faces included).
      for (float3 &p : mesh.positions)
        p = 2.f * p + float3{jitter(rng), jitter(rng), jitter(rng)};
      mesh.setVertexData(linear);
      UnstructuredField *f = field(mesh);
      ASSERT_TRUE(f->isValid()) << int(type);
      for (int i = 0; i < 50; i++) {
        const float3 p =
            cellPoint(type, mesh.positions, randomParametric(type, rng));
        EXPECT_NEAR(f->sample(p), linear(p), 2e-5f)
            << "type " << int(type) << " at " << p.x << ' ' << p.y << ' '
            << p.z;
      }
    }
  }
  EXPECT_TRUE(m_errors.empty());
}

TEST_F(UnstructuredFieldTest, BoxHexahedronReproducesTrilinearFields)
{
  Mesh mesh = referenceCell(kHexahedron);
  for (float3 &p : mesh.positions)
    p = float3{1, 0, -1} + p * float3{2, 2, 1.5f};
  auto trilinear = [](float3 p) {
    return 1.f + 0.5f * p.x - p.y + 2.f * p.z + 0.75f * p.x * p.y
           - 0.5f * p.y * p.z + 0.25f * p.x * p.z + 0.3f * p.x * p.y * p.z;
  };
  mesh.setVertexData(trilinear);
  UnstructuredField *f = field(mesh);
  ASSERT_TRUE(f->isValid());
  std::mt19937 rng(3);
  for (int i = 0; i < 500; i++) {
    const float3 p = cellPoint(
        kHexahedron, mesh.positions, randomParametric(kHexahedron, rng));
    EXPECT_NEAR(f->sample(p), trilinear(p), 2e-5f);
  }
}

TEST_F(UnstructuredFieldTest, CellDataIsTheCellsConstant)
{
  Mesh mesh = mixedMesh();
  mesh.cellData = {3.f, -1.f, 7.f, 0.25f};
  UnstructuredField *f = field(mesh);
  ASSERT_TRUE(f->isValid());
  std::mt19937 rng(11);
  for (size_t c = 0; c < mesh.cellType.size(); c++) {
    std::vector<float3> corners;
    const int count = mesh.cellType[c] == kHexahedron ? 8
                      : mesh.cellType[c] == kWedge    ? 6
                      : mesh.cellType[c] == kPyramid  ? 5
                                                      : 4;
    for (int k = 0; k < count; k++)
      corners.push_back(mesh.positions[mesh.index[mesh.cellIndex[c] + k]]);
    for (int i = 0; i < 20; i++) {
      const float3 p = cellPoint(
          mesh.cellType[c], corners, randomParametric(mesh.cellType[c], rng));
      EXPECT_EQ(f->sample(p), mesh.cellData[c]) << "cell " << c;
    }
  }
  float lo, hi;
  f->valueRange(f->bounds(), lo, hi);
  EXPECT_EQ(lo, -1.f);
  EXPECT_EQ(hi, 7.f);
}

TEST_F(UnstructuredFieldTest, CellDataDecodesFixedPoint)
{
  Mesh mesh = referenceCell(kTetra);
  auto *f = make<UnstructuredField>();
  set(f,
      "vertex.position",
      ANARI_ARRAY1D,
      array(ANARI_FLOAT32_VEC3, mesh.positions));
  set(f, "index", ANARI_ARRAY1D, array(ANARI_UINT32, mesh.index));
  set(f, "cell.index", ANARI_ARRAY1D, array(ANARI_UINT32, mesh.cellIndex));
  set(f, "cell.type", ANARI_ARRAY1D, array(ANARI_UINT8, mesh.cellType));
  set(f,
      "cell.data",
      ANARI_ARRAY1D,
      array(ANARI_UFIXED16, std::vector<uint16_t>{32768}));
  commit(f);
  ASSERT_TRUE(f->isValid());
  EXPECT_FLOAT_EQ(f->sample({0.1f, 0.1f, 0.1f}), 32768.f / 65535.f);
}

TEST_F(UnstructuredFieldTest, NaNOutsideEveryCell)
{
  Mesh mesh = mixedMesh();
  mesh.setVertexData(nonlinear);
  UnstructuredField *f = field(mesh);
  ASSERT_TRUE(f->isValid());
  const box3 b = f->bounds();
  EXPECT_EQ(b.lower.x, 0.f);
  EXPECT_EQ(b.upper.x, 1.5f);
  EXPECT_EQ(b.lower.z, -0.5f);
  EXPECT_EQ(b.upper.y, 2.f);
  // Outside the bounds, and inside them but in no cell.
  for (float3 p : {float3{-1, 0.5f, 0.5f},
           float3{0.5f, 0.5f, 5},
           float3{0.2f, 1.9f, 0.5f},
           float3{1.4f, 0.1f, 0.5f},
           float3{1.4f, 1.5f, 0.5f},
           float3{0.5f, 0.5f, -0.3f}})
    EXPECT_TRUE(std::isnan(f->sample(p))) << p.x << ' ' << p.y << ' ' << p.z;
  EXPECT_FALSE(std::isnan(f->sample({0.5f, 0.5f, 0.5f})));
}

TEST_F(UnstructuredFieldTest, MixedMeshIsContinuousAcrossSharedFaces)
{
  Mesh mesh = mixedMesh();
  mesh.setVertexData(nonlinear);
  UnstructuredField *f = field(mesh);
  ASSERT_TRUE(f->isValid());
  const std::vector<float3> &v = mesh.positions;
  struct Face
  {
    std::vector<float3> corners; // a quad or a triangle
    float3 normal;
  };
  const Face faces[] = {
      {{v[3], v[2], v[6], v[7]}, {0, 1, 0}}, // hexahedron | wedge
      {{v[1], v[2], v[6], v[5]}, {1, 0, 0}}, // hexahedron | pyramid
      {{v[1], v[2], v[10]}, {1, 0, -1}},     // pyramid | tetrahedron
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.01f, 0.99f);
  constexpr float kStep = 1e-4f;
  for (const Face &face : faces) {
    const float3 n = normalize(face.normal);
    for (int i = 0; i < 200; i++) {
      float a = u(rng), b = u(rng);
      float3 p;
      if (face.corners.size() == 4) {
        p = (1 - b) * ((1 - a) * face.corners[0] + a * face.corners[1])
            + b * ((1 - a) * face.corners[3] + a * face.corners[2]);
      } else {
        if (a + b > 1.f) {
          a = 1.f - a;
          b = 1.f - b;
        }
        p = (1 - a - b) * face.corners[0] + a * face.corners[1]
            + b * face.corners[2];
      }
      const float onFace = f->sample(p);
      const float before = f->sample(p - kStep * n);
      const float after = f->sample(p + kStep * n);
      ASSERT_FALSE(
          std::isnan(onFace) || std::isnan(before) || std::isnan(after));
      // The gradient is below 10 everywhere in the mesh.
      EXPECT_NEAR(before, onFace, 10.f * kStep + 1e-5f);
      EXPECT_NEAR(after, onFace, 10.f * kStep + 1e-5f);
    }
  }
}

TEST_F(UnstructuredFieldTest, ValueRangeIsNeverNarrowerThanSamples)
{
  std::mt19937 rng(13);
  Mesh mesh = hexahedronGrid(6, 0.2f, rng);
  std::uniform_real_distribution<float> value(-5.f, 5.f);
  mesh.vertexData.resize(mesh.positions.size());
  for (float &v : mesh.vertexData)
    v = value(rng);
  UnstructuredField *f = field(mesh);
  ASSERT_TRUE(f->isValid());
  std::uniform_real_distribution<float> coordinate(-0.5f, 6.5f);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  int sampled = 0;
  for (int region = 0; region < 200; region++) {
    float3 a{coordinate(rng), coordinate(rng), coordinate(rng)};
    float3 b = a + 2.f * float3{unit(rng), unit(rng), unit(rng)};
    const box3 box{a, b};
    float lo, hi;
    f->valueRange(box, lo, hi);
    for (int i = 0; i < 50; i++) {
      const float3 p = a + float3{unit(rng), unit(rng), unit(rng)} * (b - a);
      const float s = f->sample(p);
      if (std::isnan(s))
        continue;
      sampled++;
      EXPECT_GE(s, lo);
      EXPECT_LE(s, hi);
    }
  }
  EXPECT_GT(sampled, 5000);
  // A region holding no cell has an empty range.
  float lo, hi;
  f->valueRange({{20, 20, 20}, {21, 21, 21}}, lo, hi);
  EXPECT_GT(lo, hi);
  EXPECT_GT(f->cellSize(), 0.8f);
  EXPECT_LT(f->cellSize(), 1.5f); // jittered cells have wider bounds
}

TEST_F(UnstructuredFieldTest, GridOfHexahedraSamplesLinearFieldEverywhere)
{
  std::mt19937 rng(17);
  Mesh mesh = hexahedronGrid(10, 0.25f, rng);
  auto linear = [](float3 p) {
    return p.x - 0.5f * p.y + 0.25f * p.z;
  };
  mesh.setVertexData(linear);
  UnstructuredField *f = field(mesh);
  ASSERT_TRUE(f->isValid());
  std::uniform_real_distribution<float> coordinate(0.3f, 9.7f);
  for (int i = 0; i < 5000; i++) {
    const float3 p{coordinate(rng), coordinate(rng), coordinate(rng)};
    ASSERT_NEAR(f->sample(p), linear(p), 1e-4f);
  }
}

// Run by hand (--gtest_also_run_disabled_tests): build and sample times of
// a million cells.
TEST_F(UnstructuredFieldTest, DISABLED_MillionCellTimings)
{
  std::mt19937 rng(19);
  Mesh mesh = hexahedronGrid(100, 0.2f, rng);
  mesh.setVertexData([](float3 p) { return p.x + p.y; });
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  UnstructuredField *f = field(mesh);
  const auto built = Clock::now();
  std::uniform_real_distribution<float> coordinate(0.3f, 99.7f);
  constexpr size_t kSteps = 350; // a quarter cell apart: 87 cells
  std::vector<float3> scattered(1000000), marched(kSteps * 2800);
  for (float3 &p : scattered)
    p = {coordinate(rng), coordinate(rng), coordinate(rng)};
  // Rays sampled as a ray marcher does.
  for (size_t i = 0; i < marched.size(); i += kSteps) {
    std::uniform_real_distribution<float> start(0.3f, 80.f);
    const float3 origin{start(rng), start(rng), 0.3f};
    const float3 step = 0.25f * normalize(float3{0.1f, 0.2f, 1.f});
    for (size_t k = 0; k < kSteps; k++)
      marched[i + k] = origin + float(k) * step;
  }
  auto timePerSample = [&](const std::vector<float3> &points) {
    const auto begin = Clock::now();
    float sum = 0.f;
    for (const float3 &p : points)
      sum += f->sample(p);
    const auto end = Clock::now();
    EXPECT_FALSE(std::isnan(sum));
    return std::chrono::duration<double, std::nano>(end - begin).count()
           / points.size();
  };
  std::printf("build %.3f s, sample %.1f ns scattered, %.1f ns marched\n",
      std::chrono::duration<double>(built - start).count(),
      timePerSample(scattered),
      timePerSample(marched));
}

// ---------------------------------------------------------------------------
// Malformed meshes: each reported as an error naming the problem, leaving
// the field invalid; the same field then takes a good mesh.

struct MalformedCase
{
  const char *name;
  std::function<void(Mesh &)> breakMesh;
  const char *expected; // part of the error message
};

class MalformedMesh : public UnstructuredFieldTest,
                      public ::testing::WithParamInterface<MalformedCase>
{};

TEST_P(MalformedMesh, IsReportedAndLeavesTheFieldInvalid)
{
  Mesh good = mixedMesh();
  good.setVertexData(nonlinear);
  Mesh bad = good;
  GetParam().breakMesh(bad);
  auto *f = make<UnstructuredField>();
  commitMesh(f, bad);
  EXPECT_FALSE(f->isValid());
  EXPECT_TRUE(reported({GetParam().expected})) << [&] {
    std::string all;
    for (const std::string &m : m_errors)
      all += m + "\n";
    return all;
  }();
  commitMesh(f, good);
  EXPECT_TRUE(f->isValid());
  EXPECT_NEAR(
      f->sample({0.5f, 0.5f, 0.5f}), nonlinear({0.5f, 0.5f, 0.5f}), 0.3f);
}

const float kInf = std::numeric_limits<float>::infinity();

INSTANTIATE_TEST_SUITE_P(UnstructuredFieldTest,
    MalformedMesh,
    ::testing::Values(MalformedCase{"NoPositions",
                          [](Mesh &m) { m.positions.clear(); },
                          "'vertex.position' is not set"},
        MalformedCase{
            "NoIndex", [](Mesh &m) { m.index.clear(); }, "'index' is not set"},
        MalformedCase{"NoCellIndex",
            [](Mesh &m) { m.cellIndex.clear(); },
            "'cell.index' is not set"},
        MalformedCase{"NoCellType",
            [](Mesh &m) { m.cellType.clear(); },
            "'cell.type' is not set"},
        MalformedCase{"NoData",
            [](Mesh &m) { m.vertexData.clear(); },
            "neither 'vertex.data' nor 'cell.data'"},
        MalformedCase{"CellTypeCount",
            [](Mesh &m) { m.cellType.pop_back(); },
            "'cell.type' has 3 elements but 'cell.index' has 4"},
        MalformedCase{"VertexDataCount",
            [](Mesh &m) { m.vertexData.pop_back(); },
            "'vertex.data' has 11 elements but there are 12 vertices"},
        MalformedCase{"CellDataCount",
            [](Mesh &m) {
              m.vertexData.clear();
              m.cellData = {1.f, 2.f, 3.f};
            },
            "'cell.data' has 3 elements but there are 4 cells"},
        MalformedCase{"UnknownCellType",
            [](Mesh &m) { m.cellType[2] = 11; },
            "'cell.type' 2 is 11"},
        MalformedCase{"OffsetOutOfRange",
            [](Mesh &m) { m.cellIndex[1] = 1000; },
            "'cell.index' 1 is 1000"},
        MalformedCase{"OffsetLeavesNoRoom",
            [](Mesh &m) { m.cellIndex[3] = uint32_t(m.index.size()) - 2; },
            "needs 4 indices"},
        MalformedCase{"OffsetOverflows",
            [](Mesh &m) { m.cellIndex[0] = 0xfffffffeu; },
            "'cell.index' 0 is 4294967294"},
        MalformedCase{"VertexIndexOutOfRange",
            [](Mesh &m) { m.index[5] = 12; },
            "is 12 but there are 12 vertices"},
        MalformedCase{"NaNPosition",
            [](Mesh &m) { m.positions[4].y = std::nanf(""); },
            "'vertex.position' 4 is not finite"},
        MalformedCase{"InfinitePosition",
            [](Mesh &m) { m.positions[9].z = kInf; },
            "'vertex.position' 9 is not finite"}),
    [](const ::testing::TestParamInfo<MalformedCase> &info) {
      return std::string(info.param.name);
    });

// Random small meshes, mostly malformed: each commit either gives a field
// that samples without reading out of range, or reports an error.
TEST_F(UnstructuredFieldTest, RandomMeshesAreSampledOrReported)
{
  std::mt19937 rng(29);
  // A random integer in [0, n) (0 when n is 0).
  auto below = [&](int n) {
    return n > 0 ? int(rng() % uint32_t(n)) : 0;
  };
  std::uniform_real_distribution<float> coordinate(-1.f, 3.f);
  int valid = 0;
  for (int trial = 0; trial < 300; trial++) {
    Mesh mesh;
    const int vertices = below(14);
    for (int i = 0; i < vertices; i++)
      mesh.positions.push_back(
          {coordinate(rng), coordinate(rng), coordinate(rng)});
    if (below(10) == 0 && vertices > 0)
      mesh.positions[below(vertices)].y = std::nanf("");
    const int cells = below(4);
    const uint8_t types[] = {kTetra, kHexahedron, kWedge, kPyramid, 11};
    for (int c = 0; c < cells; c++) {
      mesh.cellType.push_back(types[below(below(20) == 0 ? 5 : 4)]);
      mesh.cellIndex.push_back(
          uint32_t(below(10) == 0 ? below(40) : mesh.index.size()));
      for (int k = 0; k < 8; k++)
        mesh.index.push_back(uint32_t(below(vertices + (below(10) == 0))));
    }
    if (below(2))
      mesh.vertexData.resize(
          std::max(0, vertices - (below(10) == 0 ? 1 : 0)), 1.f);
    else
      mesh.cellData.resize(cells + (below(10) == 0 ? 1 : 0), 2.f);
    const size_t errorsBefore = m_errors.size();
    UnstructuredField *f = field(mesh);
    if (!f->isValid()) {
      EXPECT_GT(m_errors.size(), errorsBefore) << "trial " << trial;
      continue;
    }
    valid++;
    for (int i = 0; i < 20; i++) {
      const float v =
          f->sample({coordinate(rng), coordinate(rng), coordinate(rng)});
      EXPECT_TRUE(std::isnan(v) || (v >= 0.f && v <= 2.f));
    }
  }
  EXPECT_GT(valid, 10);
}

TEST_F(UnstructuredFieldTest, WrongElementTypesAreErrors)
{
  Mesh mesh = mixedMesh();
  mesh.setVertexData(nonlinear);
  auto *f = field(mesh);
  ASSERT_TRUE(f->isValid());
  std::vector<float> asFloats(mesh.index.begin(), mesh.index.end());
  set(f, "index", ANARI_ARRAY1D, array(ANARI_FLOAT32, asFloats));
  commit(f);
  EXPECT_FALSE(f->isValid());
  EXPECT_TRUE(reported({"'index' has element type ANARI_FLOAT32"}));
}

// Shared arrays of application memory: released and overwritten right
// after commit, the field samples from its own copies.
TEST_F(UnstructuredFieldTest, ArraysMayBeFreedRightAfterCommit)
{
  Mesh mesh = mixedMesh();
  mesh.setVertexData(nonlinear);
  Mesh application = mesh;
  auto *f = make<UnstructuredField>();
  auto share = [&](const char *name, ANARIDataType type, auto &values) {
    ANARIObject handle = m_device.newArray1D(
        values.data(), nullptr, nullptr, type, values.size());
    set(f, name, ANARI_ARRAY1D, m_device.lookup(handle));
    return handle;
  };
  const ANARIObject handles[] = {
      share("vertex.position", ANARI_FLOAT32_VEC3, application.positions),
      share("index", ANARI_UINT32, application.index),
      share("cell.index", ANARI_UINT32, application.cellIndex),
      share("cell.type", ANARI_UINT8, application.cellType),
      share("vertex.data", ANARI_FLOAT32, application.vertexData)};
  commit(f);
  ASSERT_TRUE(f->isValid());
  for (ANARIObject handle : handles)
    m_device.release(handle);
  std::memset(application.positions.data(),
      0xff,
      application.positions.size() * sizeof(float3));
  std::memset(application.index.data(), 0xff, application.index.size() * 4);
  std::memset(application.cellType.data(), 0xff, application.cellType.size());
  std::memset(
      application.vertexData.data(), 0xff, application.vertexData.size() * 4);
  std::mt19937 rng(23);
  for (int i = 0; i < 200; i++) {
    const float3 p = cellPoint(kHexahedron,
        {mesh.positions.begin(), mesh.positions.begin() + 8},
        randomParametric(kHexahedron, rng));
    EXPECT_NEAR(
        f->sample(p),
        [&] {
          // Trilinear interpolation of the vertex values in the unit cube.
          float value = 0.f;
          for (int k = 0; k < 8; k++) {
            const float3 c = mesh.positions[k];
            value += (c.x ? p.x : 1 - p.x) * (c.y ? p.y : 1 - p.y)
                     * (c.z ? p.z : 1 - p.z) * mesh.vertexData[k];
          }
          return value;
        }(),
        1e-5f);
  }
}

TEST_F(UnstructuredFieldTest, DeviceCreatesTheSubtype)
{
  ANARISpatialField handle = m_device.newSpatialField("unstructured");
  ASSERT_NE(handle, nullptr);
  EXPECT_NE(
      dynamic_cast<UnstructuredField *>(m_device.lookup(handle)), nullptr);
  m_device.release(handle);
}

} // namespace
} // namespace prism
