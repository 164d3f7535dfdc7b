// Shared arrays read in place (spec 3.9): Embree builds over the
// application's memory when its layout is one Embree reads, so the device
// copies nothing (the geometry's "prism.copiedBytes" property stays 0), an
// edit through anariMapArray re-renders the new values, and a release
// while in use leaves the device its own copy. Layouts that need a
// conversion (wide indices, soups, misaligned or unpadded positions) are
// converted and draw the same picture as the shared ones.
#include "RenderTest.h"

#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace {

const Vec3 kOrange{0.9f, 0.5f, 0.1f};

class SharedArrays : public RenderTest
{
 protected:
  // After TearDown has released every array over it.
  ~SharedArrays() override
  {
    std::free(m_block);
  }
  void *m_block{nullptr};

  // Two triangles (a quad) at x in [left, left + 1], y in [-0.8, 0.8].
  static std::vector<Vec3> quadAt(float left)
  {
    return {{left, -0.8f, 0},
        {left + 1.f, -0.8f, 0},
        {left + 1.f, 0.8f, 0},
        {left, 0.8f, 0}};
  }
  static constexpr uint32_t kQuadIndices[6] = {0, 1, 2, 0, 2, 3};

  // A shared (application-owned, no deleter) array over `memory`.
  ANARIArray1D sharedArray(
      ANARIDataType type, const void *memory, uint64_t count)
  {
    return keep(
        anariNewArray1D(device(), memory, nullptr, nullptr, type, count));
  }
  // A world of one triangle geometry of these arrays, its geometry out.
  ANARIWorld worldOf(ANARIArray1D positions,
      ANARIArray1D indices,
      ANARIGeometry *geometryOut = nullptr)
  {
    ANARIGeometry geometry = newGeometry("triangle");
    setObject(geometry, "vertex.position", ANARI_ARRAY1D, positions);
    if (indices)
      setObject(geometry, "primitive.index", ANARI_ARRAY1D, indices);
    if (geometryOut)
      *geometryOut = geometry;
    return newWorld({newSurface(geometry, newMatte(kOrange))});
  }
  // The same quad from managed arrays the device copies: the reference.
  prism::image::Image managedQuad(float left)
  {
    const std::vector<Vec3> positions = quadAt(left);
    const std::vector<uint32_t> indices(
        std::begin(kQuadIndices), std::end(kQuadIndices));
    return draw(worldOf(newArray1D(ANARI_FLOAT32_VEC3, positions),
        newArray1D(ANARI_UINT32_VEC3, indices)));
  }
  prism::image::Image draw(ANARIWorld world)
  {
    return render(world,
        newOrthographicCamera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2.f, 1.5f),
        newRenderer("raycast"),
        48,
        32);
  }
  // Whether the orange quad covers column x of the middle row (48 x 32
  // pixels over x in [-1.5, 1.5]): red well above blue there.
  static bool orangeAt(const prism::image::Image &image, uint32_t x)
  {
    if (image.empty())
      return false;
    const auto &pixel = image.at(x, 16);
    return pixel.r > 0.1f && pixel.r > 2.f * pixel.b;
  }
  uint64_t copiedBytes(ANARIGeometry geometry)
  {
    uint64_t bytes = std::numeric_limits<uint64_t>::max();
    EXPECT_TRUE(anariGetProperty(device(),
        geometry,
        "prism.copiedBytes",
        ANARI_UINT64,
        &bytes,
        sizeof(bytes),
        ANARI_WAIT));
    return bytes;
  }
};

TEST_F(SharedArrays, TrianglesAreReadInPlaceAndEditsRenderTheNewValues)
{
  // One spare vertex after the four: Embree's 16-byte reads stay in the
  // application's allocation.
  std::vector<Vec3> positions = quadAt(-1.2f);
  positions.push_back({0, 0, 0});
  std::vector<uint32_t> indices(
      std::begin(kQuadIndices), std::end(kQuadIndices));
  ANARIArray1D sharedPositions =
      sharedArray(ANARI_FLOAT32_VEC3, positions.data(), 4);
  ANARIGeometry geometry = nullptr;
  ANARIWorld world = worldOf(sharedPositions,
      sharedArray(ANARI_UINT32_VEC3, indices.data(), 2),
      &geometry);
  const prism::image::Image before = draw(world);
  expectSameImage(before, managedQuad(-1.2f), "shared vs managed");
  EXPECT_TRUE(orangeAt(before, 12));  // x = -0.75
  EXPECT_FALSE(orangeAt(before, 36)); // x = 0.75
  EXPECT_EQ(copiedBytes(geometry), 0u);

  // The application edits its memory through map (the same memory) and
  // renders again: the quad has moved, still without a copy.
  auto *mapped = (Vec3 *)anariMapArray(device(), sharedPositions);
  ASSERT_EQ(mapped, positions.data());
  for (int v = 0; v < 4; v++)
    mapped[v][0] += 1.4f;
  anariUnmapArray(device(), sharedPositions);
  const prism::image::Image after = draw(world);
  expectSameImage(after, managedQuad(0.2f), "edited vs managed");
  EXPECT_FALSE(orangeAt(after, 12));
  EXPECT_TRUE(orangeAt(after, 36));
  EXPECT_EQ(copiedBytes(geometry), 0u);
}

TEST_F(SharedArrays, AReleasedArrayInUseIsCopiedFirst)
{
  std::vector<Vec3> positions = quadAt(-0.5f);
  positions.push_back({0, 0, 0});
  std::vector<uint32_t> indices(
      std::begin(kQuadIndices), std::end(kQuadIndices));
  ANARIArray1D sharedPositions = anariNewArray1D(
      device(), positions.data(), nullptr, nullptr, ANARI_FLOAT32_VEC3, 4);
  ANARIGeometry geometry = nullptr;
  ANARIWorld world = worldOf(sharedPositions,
      sharedArray(ANARI_UINT32_VEC3, indices.data(), 2),
      &geometry);
  expectSameImage(draw(world), managedQuad(-0.5f), "before the release");
  // Released while the geometry uses it: the application may reuse the
  // memory at once, and the picture must not change.
  anariRelease(device(), sharedPositions);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (Vec3 &p : positions)
    p = {nan, nan, nan};
  expectSameImage(draw(world), managedQuad(-0.5f), "after the release");
  EXPECT_EQ(copiedBytes(geometry), 0u); // the array's copy, not the geometry's
}

TEST_F(SharedArrays, ConvertedLayoutsDrawTheSamePicture)
{
  const prism::image::Image expected = managedQuad(-0.5f);
  ASSERT_TRUE(orangeAt(expected, 24)); // x = 0
  const std::vector<Vec3> quad = quadAt(-0.5f);

  // UINT64_VEC3 indices: narrowed into a copy of their own.
  std::vector<Vec3> positions = quad;
  positions.push_back({0, 0, 0});
  const std::vector<uint64_t> wide(
      std::begin(kQuadIndices), std::end(kQuadIndices));
  ANARIGeometry geometry = nullptr;
  ANARIWorld world =
      worldOf(sharedArray(ANARI_FLOAT32_VEC3, positions.data(), 4),
          sharedArray(ANARI_UINT64_VEC3, wide.data(), 2),
          &geometry);
  expectSameImage(draw(world), expected, "UINT64_VEC3 indices");
  EXPECT_EQ(copiedBytes(geometry), 6 * sizeof(uint32_t));

  // A soup (no indices): six vertices, the implied indices generated.
  std::vector<Vec3> soup;
  for (uint32_t i : kQuadIndices)
    soup.push_back(quad[i]);
  soup.push_back({0, 0, 0});
  world = worldOf(
      sharedArray(ANARI_FLOAT32_VEC3, soup.data(), 6), nullptr, &geometry);
  expectSameImage(draw(world), expected, "soup");
  EXPECT_EQ(copiedBytes(geometry), 6 * sizeof(uint32_t));

  // Positions ending at the very end of a page: Embree's read past the
  // last vertex could fault, so they are copied with padding.
  const size_t page = size_t(sysconf(_SC_PAGESIZE));
  m_block = std::aligned_alloc(page, 2 * page);
  ASSERT_NE(m_block, nullptr);
  auto *block = (unsigned char *)m_block;
  auto *atPageEnd = (Vec3 *)(block + page - quad.size() * sizeof(Vec3));
  std::memcpy(atPageEnd, quad.data(), quad.size() * sizeof(Vec3));
  const std::vector<uint32_t> indices(
      std::begin(kQuadIndices), std::end(kQuadIndices));
  world = worldOf(sharedArray(ANARI_FLOAT32_VEC3, atPageEnd, 4),
      sharedArray(ANARI_UINT32_VEC3, indices.data(), 2),
      &geometry);
  expectSameImage(draw(world), expected, "positions at a page's end");
  EXPECT_EQ(copiedBytes(geometry), 5 * sizeof(Vec3));

  // Positions at an odd address: Embree takes 4-byte aligned buffers only.
  auto *odd = (Vec3 *)(block + page + 1);
  std::memcpy((void *)odd, quad.data(), quad.size() * sizeof(Vec3));
  world = worldOf(sharedArray(ANARI_FLOAT32_VEC3, odd, 4),
      sharedArray(ANARI_UINT32_VEC3, indices.data(), 2),
      &geometry);
  expectSameImage(draw(world), expected, "misaligned positions");
  EXPECT_EQ(copiedBytes(geometry), 5 * sizeof(Vec3));
}

TEST_F(SharedArrays, SpheresConvertOnlyToEmbreesLayout)
{
  std::vector<Vec3> centers = {{-0.8f, 0, 0}, {0.3f, 0.2f, 0}, {0, 0, 0}};
  ANARIGeometry spheres = newGeometry("sphere");
  setObject(spheres,
      "vertex.position",
      ANARI_ARRAY1D,
      sharedArray(ANARI_FLOAT32_VEC3, centers.data(), 2));
  setFloat(spheres, "radius", 0.4f);
  ANARIWorld world = newWorld({newSurface(spheres, newMatte(kOrange))});
  const prism::image::Image shared = draw(world);
  EXPECT_TRUE(orangeAt(shared, 8)); // x = -0.8
  EXPECT_EQ(copiedBytes(spheres), 2 * 4 * sizeof(float));

  ANARIGeometry managed = newGeometry("sphere");
  centers.pop_back();
  setArray(managed, "vertex.position", ANARI_FLOAT32_VEC3, centers);
  setFloat(managed, "radius", 0.4f);
  expectSameImage(shared,
      draw(newWorld({newSurface(managed, newMatte(kOrange))})),
      "shared vs managed spheres");
}

TEST_F(SharedArrays, PackedSpheresAreReadInPlace)
{
  // PRISM_GEOMETRY_POSITION_RADIUS: centres and radii as one FLOAT32_VEC4
  // array, Embree's layout: no copy, the same picture as positions and
  // radii apart, and an edit renders the new values.
  std::vector<Vec4> packed = {{-0.8f, 0, 0, 0.4f}, {0.3f, 0.2f, 0, 0.25f}};
  ANARIArray1D shared = sharedArray(ANARI_FLOAT32_VEC4, packed.data(), 2);
  ANARIGeometry spheres = newGeometry("sphere");
  setObject(spheres, "vertex.positionRadius", ANARI_ARRAY1D, shared);
  ANARIWorld world = newWorld({newSurface(spheres, newMatte(kOrange))});
  const prism::image::Image inPlace = draw(world);
  EXPECT_EQ(copiedBytes(spheres), 0u);
  EXPECT_TRUE(orangeAt(inPlace, 8));   // x = -0.8
  EXPECT_FALSE(orangeAt(inPlace, 40)); // x = 1.0

  ANARIGeometry apart = newGeometry("sphere");
  setArray(apart,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-0.8f, 0, 0}, {0.3f, 0.2f, 0}});
  setArray(
      apart, "vertex.radius", ANARI_FLOAT32, std::vector<float>{0.4f, 0.25f});
  expectSameImage(inPlace,
      draw(newWorld({newSurface(apart, newMatte(kOrange))})),
      "packed vs apart");

  auto *mapped = (Vec4 *)anariMapArray(device(), shared);
  ASSERT_EQ(mapped, packed.data());
  mapped[1] = {1.0f, 0, 0, 0.3f};
  anariUnmapArray(device(), shared);
  const prism::image::Image edited = draw(world);
  EXPECT_TRUE(orangeAt(edited, 40));
  EXPECT_EQ(copiedBytes(spheres), 0u);

  // An array not 16-byte aligned is copied.
  const long page = sysconf(_SC_PAGESIZE);
  m_block = std::aligned_alloc(size_t(page), size_t(page));
  ASSERT_NE(m_block, nullptr);
  auto *misaligned = (Vec4 *)((char *)m_block + 8);
  std::memcpy(misaligned, packed.data(), 2 * sizeof(Vec4));
  ANARIGeometry copied = newGeometry("sphere");
  setObject(copied,
      "vertex.positionRadius",
      ANARI_ARRAY1D,
      sharedArray(ANARI_FLOAT32_VEC4, misaligned, 2));
  expectSameImage(draw(newWorld({newSurface(copied, newMatte(kOrange))})),
      edited,
      "misaligned packed spheres");
  EXPECT_EQ(copiedBytes(copied), 2 * sizeof(Vec4));

  // Indexed spheres are gathered: Embree has no index buffer for them.
  ANARIGeometry indexed = newGeometry("sphere");
  setObject(indexed, "vertex.positionRadius", ANARI_ARRAY1D, shared);
  setArray(indexed, "primitive.index", ANARI_UINT32, std::vector<uint32_t>{1});
  const prism::image::Image one =
      draw(newWorld({newSurface(indexed, newMatte(kOrange))}));
  EXPECT_EQ(copiedBytes(indexed), sizeof(Vec4));
  EXPECT_TRUE(orangeAt(one, 40));
  EXPECT_FALSE(orangeAt(one, 8));
}

TEST_F(SharedArrays, PackedCurvesAreReadInPlaceUnlessAtAPagesEnd)
{
  // A curve's segments read one vertex past their end: an application's
  // array is used in place when those bytes are in its last element's
  // page, copied when it ends a page; both draw what positions and radii
  // apart do.
  const Vec4 packed[3] = {
      {-1.2f, -0.5f, 0, 0.2f}, {0, 0.5f, 0, 0.3f}, {1.2f, -0.5f, 0, 0.2f}};
  ANARIGeometry apart = newGeometry("curve");
  setArray(apart,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-1.2f, -0.5f, 0}, {0, 0.5f, 0}, {1.2f, -0.5f, 0}});
  setArray(apart,
      "vertex.radius",
      ANARI_FLOAT32,
      std::vector<float>{0.2f, 0.3f, 0.2f});
  const prism::image::Image expected =
      draw(newWorld({newSurface(apart, newMatte(kOrange))}));
  EXPECT_TRUE(orangeAt(expected, 14)); // x = -0.6: the first segment

  // Two pages: the array at the start of the second, one ending the first
  // and one 8 bytes past a 16-byte boundary (where malloc puts blocks;
  // Embree's curve builder faulted on such an array).
  const long page = sysconf(_SC_PAGESIZE);
  m_block = std::aligned_alloc(size_t(page), 2 * size_t(page));
  ASSERT_NE(m_block, nullptr);
  auto *pageStart = (Vec4 *)((char *)m_block + page);
  auto *pageEnd = pageStart - 3;
  auto *misaligned = (Vec4 *)((char *)m_block + 1032);
  for (Vec4 *memory : {pageStart, pageEnd, misaligned})
    std::memcpy(memory, packed, sizeof(packed));
  for (Vec4 *memory : {pageStart, pageEnd, misaligned}) {
    const bool inPlace = memory == pageStart;
    ANARIGeometry curve = newGeometry("curve");
    setObject(curve,
        "vertex.positionRadius",
        ANARI_ARRAY1D,
        sharedArray(ANARI_FLOAT32_VEC4, memory, 3));
    expectSameImage(draw(newWorld({newSurface(curve, newMatte(kOrange))})),
        expected,
        inPlace ? "packed curve in place" : "packed curve copied");
    if (memory == misaligned)
      EXPECT_EQ(copiedBytes(curve), 2 * sizeof(uint32_t) + 4 * sizeof(Vec4))
          << "not 16-byte aligned";
    // Implied indices are the geometry's own either way.
    EXPECT_EQ(copiedBytes(curve),
        2 * sizeof(uint32_t) + (inPlace ? 0 : 4 * sizeof(Vec4)));
  }
}

} // namespace
