// nanovdb fields against grids built with NanoVDB's own GridBuilder: values,
// the grid's transform, background in inactive space, conservative value
// ranges, and corrupt or truncated buffers (each refused, none read past).
#include "FieldTest.h"

#include "volume/NanoVdbField.h"

#include <nanovdb/util/GridBuilder.h>

#include <cmath>
#include <random>
#include <string>

namespace prism {
namespace {

constexpr int kRampSize = 20;
constexpr float kBackground = -7.f;

float ramp(int i, int j, int k)
{
  return 0.5f * float(i) - 2.f * float(j) + 3.f * float(k) + 1.f;
}

// A dense ramp over [0, kRampSize)^3 with its index-to-world map.
template <typename ValueT = float, typename BuildT = ValueT>
nanovdb::GridHandle<> rampGrid(
    double voxelSize = 1.0, nanovdb::Vec3d origin = nanovdb::Vec3d(0.0))
{
  nanovdb::GridBuilder<ValueT, BuildT> builder{ValueT(kBackground)};
  auto accessor = builder.getAccessor();
  for (int k = 0; k < kRampSize; k++)
    for (int j = 0; j < kRampSize; j++)
      for (int i = 0; i < kRampSize; i++)
        accessor.setValue(nanovdb::Coord(i, j, k), ValueT(ramp(i, j, k)));
  return builder.template getHandle<>(voxelSize, origin);
}

class NanoVdbFieldTest : public FieldTest
{
 protected:
  NanoVdbField *nanoField(
      const uint8_t *bytes, uint64_t size, const char *filter = "linear")
  {
    auto *f = dynamic_cast<NanoVdbField *>(field("nanovdb"));
    if (size)
      set(f, "data", array(ANARI_UINT8, bytes, size));
    set(f, "filter", filter);
    commit(f);
    return f;
  }
  NanoVdbField *nanoField(
      const nanovdb::GridHandle<> &handle, const char *filter = "linear")
  {
    return nanoField(handle.data(), handle.size(), filter);
  }
  // Commits `bytes` and expects an invalid field and an error whose
  // message contains `why`.
  void expectRefused(const uint8_t *bytes, uint64_t size, const char *why)
  {
    m_messages.clear();
    auto *f = nanoField(bytes, size);
    EXPECT_FALSE(f->isValid()) << why;
    EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR, why)) << why;
    EXPECT_TRUE(std::isnan(f->sample({1.f, 1.f, 1.f})));
  }
  void fuzz(nanovdb::GridHandle<> &grid, int rounds);
  static nanovdb::TreeData<3> &treeOf(nanovdb::GridHandle<> &handle)
  {
    return *reinterpret_cast<nanovdb::TreeData<3> *>(
        handle.data() + sizeof(nanovdb::GridData));
  }
};

TEST_F(NanoVdbFieldTest, SamplesAreTheBuilderValuesForEveryFilter)
{
  auto handle = rampGrid();
  for (const char *filter : {"nearest", "linear", "cubic"}) {
    auto *f = nanoField(handle, filter);
    ASSERT_TRUE(f->isValid()) << filter;
    // Voxel centres; cubic needs all of its taps inside the ramp.
    for (int k = 1; k < kRampSize - 2; k += 3)
      for (int j = 1; j < kRampSize - 2; j += 2)
        for (int i = 1; i < kRampSize - 2; i++)
          EXPECT_NEAR(
              f->sample({float(i), float(j), float(k)}), ramp(i, j, k), 1e-4f)
              << filter << " " << i << " " << j << " " << k;
  }
  // Linear and cubic reproduce the ramp between voxels too.
  for (const char *filter : {"linear", "cubic"}) {
    auto *f = nanoField(handle, filter);
    EXPECT_NEAR(f->sample({4.5f, 7.25f, 10.75f}),
        0.5f * 4.5f - 2.f * 7.25f + 3.f * 10.75f + 1.f,
        1e-4f)
        << filter;
  }
  auto *nearest = nanoField(handle, "nearest");
  EXPECT_EQ(nearest->sample({4.5f, 7.4f, 10.6f}), ramp(5, 7, 11));
}

TEST_F(NanoVdbFieldTest, TheGridTransformIsHonoured)
{
  const double voxel = 0.25;
  const nanovdb::Vec3d origin(10.0, -3.0, 2.0);
  auto handle = rampGrid(voxel, origin);
  auto *f = nanoField(handle);
  ASSERT_TRUE(f->isValid());
  EXPECT_FLOAT_EQ(f->cellSize(), 0.25f);
  auto world = [&](float i, float j, float k) {
    return float3{float(origin[0] + voxel * i),
        float(origin[1] + voxel * j),
        float(origin[2] + voxel * k)};
  };
  EXPECT_NEAR(f->sample(world(3, 4, 5)), ramp(3, 4, 5), 1e-4f);
  EXPECT_NEAR(f->sample(world(12, 0, 19)), ramp(12, 0, 19), 1e-4f);
  // Bounds: the active voxels' cubes, [-1/2, size - 1/2] in index space.
  const box3 bounds = f->bounds();
  const float3 lower = world(-0.5f, -0.5f, -0.5f);
  const float3 upper =
      world(kRampSize - 0.5f, kRampSize - 0.5f, kRampSize - 0.5f);
  for (int axis = 0; axis < 3; axis++) {
    EXPECT_FLOAT_EQ(bounds.lower[axis], lower[axis]);
    EXPECT_FLOAT_EQ(bounds.upper[axis], upper[axis]);
  }
  EXPECT_FALSE(std::isnan(f->sample(bounds.lower)));
  EXPECT_FALSE(std::isnan(f->sample(bounds.upper)));
  EXPECT_TRUE(std::isnan(f->sample(bounds.upper + 0.01f)));
  EXPECT_TRUE(std::isnan(f->sample(bounds.lower - 0.01f)));
  EXPECT_TRUE(std::isnan(f->sample(world(0, 0, 0) - 1.f)));
}

TEST_F(NanoVdbFieldTest, RotatedMapsAreHonoured)
{
  // object = (-s j, s i, s k) + t: a quarter turn about z, then a shift.
  const double s = 2.0;
  const double toObject[3][3] = {{0, -s, 0}, {s, 0, 0}, {0, 0, s}};
  const double toIndex[3][3] = {{0, 1 / s, 0}, {-1 / s, 0, 0}, {0, 0, 1 / s}};
  // Map::set takes the transposes (OpenVDB's row-vector convention).
  double mat[3][3], inverse[3][3];
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {
      mat[r][c] = toObject[c][r];
      inverse[r][c] = toIndex[c][r];
    }
  nanovdb::Map map;
  map.set(mat, inverse, nanovdb::Vec3d(5.0, 0.0, -1.0), 1.0);
  nanovdb::GridBuilder<float> builder(kBackground);
  auto accessor = builder.getAccessor();
  for (int k = 0; k < kRampSize; k++)
    for (int j = 0; j < kRampSize; j++)
      for (int i = 0; i < kRampSize; i++)
        accessor.setValue(nanovdb::Coord(i, j, k), ramp(i, j, k));
  auto handle = builder.getHandle<>(map);
  auto *f = nanoField(handle);
  ASSERT_TRUE(f->isValid());
  EXPECT_FLOAT_EQ(f->cellSize(), 2.f);
  auto object = [&](float i, float j, float k) {
    return float3{float(5.0 - s * j), float(s * i), float(-1.0 + s * k)};
  };
  EXPECT_NEAR(f->sample(object(3, 7, 2)), ramp(3, 7, 2), 1e-4f);
  EXPECT_NEAR(f->sample(object(15, 1, 9)), ramp(15, 1, 9), 1e-4f);
  const box3 bounds = f->bounds();
  EXPECT_FLOAT_EQ(bounds.lower.x, 5.f - 2.f * 19.5f);
  EXPECT_FLOAT_EQ(bounds.upper.x, 5.f + 2.f * 0.5f);
  EXPECT_FLOAT_EQ(bounds.lower.y, -1.f);
  EXPECT_FLOAT_EQ(bounds.upper.y, 39.f);
  EXPECT_FALSE(std::isnan(f->sample(bounds.lower)));
  EXPECT_FALSE(std::isnan(f->sample(bounds.upper)));
  expectValueRangesCoverSamples(*f, 23, "rotated");
}

TEST_F(NanoVdbFieldTest, InactiveSpaceReadsTheBackground)
{
  nanovdb::GridBuilder<float> builder(kBackground);
  auto accessor = builder.getAccessor();
  accessor.setValue(nanovdb::Coord(0, 0, 0), 1.f);
  accessor.setValue(nanovdb::Coord(300, 40, 2), 2.f);
  auto handle = builder.getHandle<>();
  auto *f = nanoField(handle, "nearest");
  ASSERT_TRUE(f->isValid());
  EXPECT_EQ(f->sample({0.f, 0.f, 0.f}), 1.f);
  EXPECT_EQ(f->sample({300.f, 40.f, 2.f}), 2.f);
  EXPECT_EQ(f->sample({150.f, 20.f, 1.f}), kBackground);
  float lo, hi;
  f->valueRange(f->bounds(), lo, hi);
  EXPECT_LE(lo, kBackground);
  EXPECT_GE(hi, 2.f);
}

TEST_F(NanoVdbFieldTest, ValueRangeCoversEverySampleOfEveryFilter)
{
  auto handle = rampGrid(0.5, nanovdb::Vec3d(1.0, 2.0, 3.0));
  for (const char *filter : {"nearest", "linear", "cubic"})
    expectValueRangesCoverSamples(*nanoField(handle, filter), 5, filter);
}

TEST_F(NanoVdbFieldTest, ValueRangeIsLocalAndCoversSparseGrids)
{
  // Two clusters a thousand voxels apart: low values near the origin,
  // high ones far along x.
  nanovdb::GridBuilder<float> builder(0.f);
  auto accessor = builder.getAccessor();
  for (int k = 0; k < 8; k++)
    for (int j = 0; j < 8; j++)
      for (int i = 0; i < 8; i++) {
        accessor.setValue(nanovdb::Coord(i, j, k), 1.f + 0.01f * float(i));
        accessor.setValue(nanovdb::Coord(1000 + i, j, k), 50.f + float(j));
      }
  auto handle = builder.getHandle<>();
  for (const char *filter : {"nearest", "linear", "cubic"}) {
    auto *f = nanoField(handle, filter);
    ASSERT_TRUE(f->isValid());
    float lo, hi;
    f->valueRange({{0.f, 0.f, 0.f}, {7.f, 7.f, 7.f}}, lo, hi);
    EXPECT_LT(hi, 50.f) << filter;
    if (std::string(filter) == "nearest") {
      EXPECT_GE(lo, 1.f) << filter; // rounds to the cluster's voxels only
    } else {
      EXPECT_LE(lo, 0.f) << filter; // interpolates to the background at 8
    }
    f->valueRange({{1000.f, 0.f, 0.f}, {1007.f, 7.f, 7.f}}, lo, hi);
    EXPECT_GE(hi, 57.f) << filter;
    expectValueRangesCoverSamples(*f, 9, filter);
  }
}

TEST_F(NanoVdbFieldTest, DoubleAndQuantisedGridsSample)
{
  auto doubles = rampGrid<double>();
  auto *f = nanoField(doubles);
  ASSERT_TRUE(f->isValid());
  EXPECT_NEAR(f->sample({3.f, 4.f, 5.f}), ramp(3, 4, 5), 1e-5f);

  // 8-bit quantisation of the ramp's range (about 100) per leaf.
  auto fp8 = rampGrid<float, nanovdb::Fp8>();
  auto *quantised = nanoField(fp8);
  ASSERT_TRUE(quantised->isValid());
  EXPECT_NEAR(quantised->sample({3.f, 4.f, 5.f}), ramp(3, 4, 5), 0.2f);
  float lo, hi;
  quantised->valueRange(quantised->bounds(), lo, hi);
  EXPECT_LE(lo, quantised->sample({3.f, 4.f, 5.f}));
}

TEST_F(NanoVdbFieldTest, TheArrayMayBeFreedAfterCommit)
{
  auto handle = rampGrid();
  auto bytes = std::make_unique<std::vector<uint8_t>>(
      handle.data(), handle.data() + handle.size());
  ANARIArray1D array = m_device.newArray1D(
      bytes->data(), nullptr, nullptr, ANARI_UINT8, bytes->size());
  auto *f = field("nanovdb");
  set(f, "data", m_device.lookup(array));
  commit(f);
  m_device.release(array);
  std::fill(bytes->begin(), bytes->end(), 0xff);
  bytes.reset();
  ASSERT_TRUE(f->isValid());
  EXPECT_NEAR(f->sample({2.f, 3.f, 4.f}), ramp(2, 3, 4), 1e-4f);
}

TEST_F(NanoVdbFieldTest, WrongParametersAreReported)
{
  m_messages.clear();
  auto *missing = nanoField(nullptr, 0);
  EXPECT_FALSE(missing->isValid());
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR, "missing 'data'"));

  const float floats[4] = {};
  auto *wrongType = dynamic_cast<NanoVdbField *>(field("nanovdb"));
  set(wrongType, "data", array(ANARI_FLOAT32, floats, 4));
  m_messages.clear();
  commit(wrongType);
  EXPECT_FALSE(wrongType->isValid());
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR, "element type"));

  auto handle = rampGrid();
  m_messages.clear();
  auto *f = nanoField(handle, "trilinear");
  EXPECT_TRUE(f->isValid());
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING, "trilinear"));
}

TEST_F(NanoVdbFieldTest, TruncatedBuffersAreRefused)
{
  auto handle = rampGrid();
  const uint64_t size = handle.size();
  const uint64_t header = sizeof(nanovdb::GridData);
  for (uint64_t length : {uint64_t(1),
           uint64_t(16),
           header - 1,
           header,
           header + 32,
           size / 2,
           size - 1}) {
    expectRefused(handle.data(),
        length,
        length < header ? "smaller than a NanoVDB grid header"
                        : "does not fit the buffer");
  }
  EXPECT_TRUE(nanoField(handle)->isValid());
}

TEST_F(NanoVdbFieldTest, CorruptHeadersAreRefused)
{
  auto corrupt = [&](const char *why, auto &&change) {
    auto handle = rampGrid();
    change(*reinterpret_cast<nanovdb::GridData *>(handle.data()));
    expectRefused(handle.data(), handle.size(), why);
  };
  corrupt("magic number", [](nanovdb::GridData &g) { g.mMagic ^= 1; });
  corrupt("major version 31",
      [](nanovdb::GridData &g) { g.mVersion = nanovdb::Version(31, 0, 0); });
  corrupt("does not fit", [](nanovdb::GridData &g) { g.mGridSize += 32; });
  corrupt("does not fit", [](nanovdb::GridData &g) { g.mGridSize = 100; });
  corrupt("grid class",
      [](nanovdb::GridData &g) { g.mGridClass = nanovdb::GridClass(999); });
  corrupt("map (index to world)", [](nanovdb::GridData &g) {
    for (double &v : g.mMap.mMatD)
      v = 0.0;
  });
  corrupt("map (index to world)", [](nanovdb::GridData &g) {
    g.mMap.mVecD[1] = std::numeric_limits<double>::quiet_NaN();
  });
  corrupt("grid type",
      [](nanovdb::GridData &g) { g.mGridType = nanovdb::GridType(999); });
  corrupt("grid type",
      [](nanovdb::GridData &g) { g.mGridType = nanovdb::GridType::Vec3f; });
  EXPECT_TRUE(
      reported(ANARI_SEVERITY_ERROR, "grid type Vec3f is not supported"));
}

TEST_F(NanoVdbFieldTest, NodeOffsetsOutsideTheGridAreRefused)
{
  using Root = nanovdb::NanoRoot<float>::DataType;
  using Upper = nanovdb::NanoUpper<float>::DataType;
  using Lower = nanovdb::NanoLower<float>::DataType;
  auto corrupt = [&](const char *why, auto &&change) {
    auto handle = rampGrid();
    auto &tree = treeOf(handle);
    change(tree, (uint8_t *)&tree);
    expectRefused(handle.data(), handle.size(), why);
  };
  corrupt("root node", [](nanovdb::TreeData<3> &t, uint8_t *) {
    t.mNodeOffset[3] = uint64_t(1) << 40;
  });
  corrupt("root node",
      [](nanovdb::TreeData<3> &t, uint8_t *) { t.mNodeOffset[3] += 4; });
  corrupt("node array", [](nanovdb::TreeData<3> &t, uint8_t *) {
    t.mNodeCount[0] = 0xffffffffu;
  });
  corrupt("node array", [](nanovdb::TreeData<3> &t, uint8_t *) {
    t.mNodeOffset[2] = ~uint64_t(0) - 31;
  });
  corrupt("tile table", [](nanovdb::TreeData<3> &t, uint8_t *tree) {
    ((Root *)(tree + t.mNodeOffset[3]))->mTableSize = 1u << 30;
  });
  corrupt("root tile's child", [](nanovdb::TreeData<3> &t, uint8_t *tree) {
    ((Root *)(tree + t.mNodeOffset[3]))->tile(0)->child = int64_t(1) << 50;
  });
  corrupt("root tile's child", [](nanovdb::TreeData<3> &t, uint8_t *tree) {
    ((Root *)(tree + t.mNodeOffset[3]))->tile(0)->child = -(int64_t(1) << 12);
  });
  corrupt("root tile's child", [](nanovdb::TreeData<3> &t, uint8_t *tree) {
    ((Root *)(tree + t.mNodeOffset[3]))->tile(0)->child += 32;
  });
  corrupt("upper node's child", [](nanovdb::TreeData<3> &t, uint8_t *tree) {
    auto *upper = (Upper *)(tree + t.mNodeOffset[2]);
    upper->mTable[*upper->mChildMask.beginOn()].child = int64_t(1) << 40;
  });
  corrupt("lower node's child", [](nanovdb::TreeData<3> &t, uint8_t *tree) {
    auto *lower = (Lower *)(tree + t.mNodeOffset[1]);
    lower->mTable[*lower->mChildMask.beginOn()].child = -int64_t(1) << 20;
  });
  corrupt("lower node's child", [](nanovdb::TreeData<3> &t, uint8_t *tree) {
    auto *lower = (Lower *)(tree + t.mNodeOffset[1]);
    lower->mTable[*lower->mChildMask.beginOn()].child = 0;
  });
}

// Flips bits of `grid` (header, tree and root, node masks and child
// tables, or anywhere) `rounds` times over; every commit must either refuse
// the grid with an error or give a field that samples without reading
// outside it (run under AddressSanitizer to see the latter).
void NanoVdbFieldTest::fuzz(nanovdb::GridHandle<> &grid, int rounds)
{
  const std::vector<uint8_t> original(grid.data(), grid.data() + grid.size());
  const auto &tree = treeOf(grid);
  const uint64_t treeAt = sizeof(nanovdb::GridData);
  const uint64_t regions[][2] = {{0, 2048},
      {treeAt + tree.mNodeOffset[2], sizeof(nanovdb::NanoUpper<float>)},
      {treeAt + tree.mNodeOffset[1], sizeof(nanovdb::NanoLower<float>)},
      {treeAt + tree.mNodeOffset[0], 2048},
      {0, original.size()}};
  std::mt19937 random(13);
  int refused = 0;
  for (int round = 0; round < rounds; round++) {
    std::memcpy(grid.data(), original.data(), original.size());
    const int flips = 1 + round % 8;
    for (int n = 0; n < flips; n++) {
      const auto &region = regions[random() % 5];
      const uint64_t at = (region[0] + random() % region[1]) % original.size();
      grid.data()[at] ^= uint8_t(1u << (random() % 8));
    }
    m_messages.clear();
    const char *filters[] = {"nearest", "linear", "cubic"};
    auto *f = nanoField(grid, filters[round % 3]);
    if (!f->isValid()) {
      refused++;
      EXPECT_TRUE(reportedError());
      continue;
    }
    const box3 bounds = f->bounds();
    float lo, hi;
    f->valueRange(bounds, lo, hi);
    for (int s = 0; s < 20; s++) {
      float3 p;
      for (int axis = 0; axis < 3; axis++)
        p[axis] = bounds.lower[axis]
                  + (bounds.upper[axis] - bounds.lower[axis])
                        * float(random() % 1000) / 999.f;
      (void)f->sample(p);
      f->valueRange({p, p + 1.f}, lo, hi);
    }
  }
  EXPECT_GT(refused, 0);
}

TEST_F(NanoVdbFieldTest, RandomlyCorruptedGridsNeverCrash)
{
  auto grid = rampGrid();
  fuzz(grid, 300);
  auto fp8 = rampGrid<float, nanovdb::Fp8>();
  fuzz(fp8, 150);
  auto fpN = rampGrid<float, nanovdb::FpN>();
  fuzz(fpN, 150);
}

TEST_F(NanoVdbFieldTest, QuantisedGridsOfVariableWidthSample)
{
  auto fpN = rampGrid<float, nanovdb::FpN>();
  auto *f = nanoField(fpN);
  ASSERT_TRUE(f->isValid());
  // FpN picks each leaf's bit width to stay within the default tolerance.
  EXPECT_NEAR(f->sample({3.f, 4.f, 5.f}), ramp(3, 4, 5), 0.1f);
  EXPECT_NEAR(f->sample({13.f, 14.f, 15.f}), ramp(13, 14, 15), 0.1f);
}

} // namespace
} // namespace prism
