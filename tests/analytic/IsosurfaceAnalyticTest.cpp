// Isosurfaces rendered through the public API: an unstructured field of
// hexahedra sampling the distance to the origin, whose isosurfaces are
// spheres. Orthographic depths put every covered pixel on the sphere of
// its isovalue, the coverage ends at that sphere's outline, and
// channel.primitiveId is the isovalue's index.
#include "AnalyticScene.h"

#include <cmath>

namespace {

const float kEyeZ5[3] = {0, 0, 5};
const float kLookDown[3] = {0, 0, -1};

class IsosurfaceAnalytic : public AnalyticTest
{
 protected:
  // n^3 hexahedra over [-1.5, 1.5]^3, values the distance to the origin.
  ANARISpatialField distanceField(int n)
  {
    const float h = 3.f / n;
    std::vector<float> positions, values;
    for (int z = 0; z <= n; z++)
      for (int y = 0; y <= n; y++)
        for (int x = 0; x <= n; x++) {
          const float p[3] = {-1.5f + h * x, -1.5f + h * y, -1.5f + h * z};
          positions.insert(positions.end(), p, p + 3);
          values.push_back(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
        }
    std::vector<uint32_t> index, cellIndex;
    std::vector<uint8_t> cellType;
    auto at = [n](int x, int y, int z) {
      return uint32_t((z * (n + 1) + y) * (n + 1) + x);
    };
    for (int z = 0; z < n; z++)
      for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
          cellIndex.push_back(uint32_t(index.size()));
          cellType.push_back(12); // VTK_HEXAHEDRON
          index.insert(index.end(),
              {at(x, y, z),
                  at(x + 1, y, z),
                  at(x + 1, y + 1, z),
                  at(x, y + 1, z),
                  at(x, y, z + 1),
                  at(x + 1, y, z + 1),
                  at(x + 1, y + 1, z + 1),
                  at(x, y + 1, z + 1)});
        }
    ANARISpatialField field = anariNewSpatialField(m_device, "unstructured");
    setArray(field, "vertex.position", array1D(positions, ANARI_FLOAT32_VEC3));
    setArray(field, "vertex.data", array1D(values, ANARI_FLOAT32));
    setArray(field, "index", array1D(index, ANARI_UINT32));
    setArray(field, "cell.index", array1D(cellIndex, ANARI_UINT32));
    setArray(field, "cell.type", array1D(cellType, ANARI_UINT8));
    anariCommitParameters(m_device, field);
    return field;
  }
  // The isosurfaces of `field` at `isovalues`, seen from z = 5 over
  // [-1.5, 1.5]^2; placed by `transform` (a column-major 4x4) if given.
  RenderedImage renderIsosurface(ANARISpatialField field,
      const std::vector<float> &isovalues,
      const float *transform = nullptr)
  {
    ANARIGeometry g = anariNewGeometry(m_device, "isosurface");
    anariSetParameter(m_device, g, "field", ANARI_SPATIAL_FIELD, &field);
    if (isovalues.size() == 1)
      anariSetParameter(m_device, g, "isovalue", ANARI_FLOAT32, &isovalues[0]);
    else
      setArray(g, "isovalue", array1D(isovalues, ANARI_FLOAT32));
    ANARISurface isosurface = surface(g, matte(1, 1, 1));
    ANARIWorld w = transform ? world({}) : world({isosurface});
    if (transform)
      placeInstanced(w, isosurface, transform);
    ANARICamera c = orthographic(kEyeZ5, kLookDown, 3.f);
    ANARIRenderer r = renderer("raycast");
    RenderedImage image = render(w, c, r, kPixels, kPixels);
    anariRelease(m_device, w);
    anariRelease(m_device, c);
    anariRelease(m_device, r);
    return image;
  }
  // Every pixel whose centre lies inside the sphere of `radius` around
  // (cx, cy, 0) (with a margin for the interpolated outline) shows it: its
  // depth puts the hit on the sphere, its primitiveId is `isovalueIndex`;
  // pixels outside show nothing.
  void checkSphere(const RenderedImage &image,
      float radius,
      uint32_t isovalueIndex,
      float h /* cell size */,
      float cx = 0.f,
      float cy = 0.f)
  {
    int covered = 0;
    for (uint32_t y = 0; y < kPixels; y++) {
      for (uint32_t x = 0; x < kPixels; x++) {
        const float wx = (x + 0.5f) / kPixels * 3.f - 1.5f - cx;
        const float wy = (y + 0.5f) / kPixels * 3.f - 1.5f - cy;
        const float fromAxis = std::sqrt(wx * wx + wy * wy);
        const float depth = image.depthAt(x, y);
        if (fromAxis > radius + 0.01f) {
          EXPECT_TRUE(std::isinf(depth)) << x << ' ' << y;
          continue;
        }
        if (fromAxis > radius - 0.01f)
          continue; // the outline: either way
        ASSERT_TRUE(std::isfinite(depth)) << x << ' ' << y;
        covered++;
        const float z = 5.f - depth;
        // Trilinear interpolation errs by at most h^2 / 8 times the
        // distance's second derivative (below 1 / (r - h)) per axis, and
        // the distance's gradient has length 1.
        EXPECT_NEAR(std::sqrt(fromAxis * fromAxis + z * z),
            radius,
            3.f * h * h / (8.f * (radius - h)))
            << x << ' ' << y;
        EXPECT_EQ(image.primitiveId[size_t(y) * kPixels + x], isovalueIndex);
      }
    }
    EXPECT_GT(covered, int(3.f * radius * radius / 9.f * kPixels * kPixels));
  }

  static constexpr uint32_t kPixels = 64;
};

TEST_F(IsosurfaceAnalytic, OneIsovalueIsOneSphere)
{
  ANARISpatialField field = distanceField(30);
  checkSphere(renderIsosurface(field, {0.6f}), 0.6f, 0, 0.1f);
  anariRelease(m_device, field);
  EXPECT_TRUE(problems().empty());
}

TEST_F(IsosurfaceAnalytic, TheOuterOfTwoIsovaluesHidesTheInner)
{
  ANARISpatialField field = distanceField(30);
  checkSphere(renderIsosurface(field, {0.6f, 1.1f}), 1.1f, 1, 0.1f);
  checkSphere(renderIsosurface(field, {1.1f, 0.6f}), 1.1f, 0, 0.1f);
  anariRelease(m_device, field);
  EXPECT_TRUE(problems().empty());
}

// Embree hands the isosurface rays in its object space: scaled and moved
// by an instance, the sphere scales and moves with it.
TEST_F(IsosurfaceAnalytic, InstancedIsosurfaceFollowsItsTransform)
{
  ANARISpatialField field = distanceField(30);
  const float scaleAndMove[16] = {
      1.5f, 0, 0, 0, 0, 1.5f, 0, 0, 0, 0, 1.5f, 0, 0.2f, -0.1f, 0, 1};
  checkSphere(renderIsosurface(field, {0.5f}, scaleAndMove),
      0.75f,
      0,
      0.15f,
      0.2f,
      -0.1f);
  anariRelease(m_device, field);
  EXPECT_TRUE(problems().empty());
}

} // namespace
