// Isosurfaces of a field whose level sets are spheres: rays through the
// pixel centres of a pinhole camera land on the sphere of the isovalue's
// radius with the sphere's normal, several isovalues report their index as
// the primitive, and rays that miss every sphere miss. Once on an analytic
// test field, once on an unstructured mesh sampling the same distances.
#include "../volume/MeshTestFixture.h"
#include "geometry/Isosurface.h"
#include "rt/Context.h"
#include "rt/Scene.h"

#include <cmath>
#include <limits>
#include <optional>

namespace prism {
namespace {

const float3 kCentre{0.1f, -0.2f, 0.05f};

// The distance to kCentre, defined in a box around it.
class DistanceField : public SpatialField
{
 public:
  explicit DistanceField(DeviceState &device) : SpatialField(device, "test") {}
  box3 bounds() const override
  {
    return {kCentre - float3{2, 2, 2}, kCentre + float3{2, 2, 2}};
  }
  float sample(const float3 &p) const override
  {
    return contains(bounds(), p) ? length(p - kCentre)
                                 : std::numeric_limits<float>::quiet_NaN();
  }
  void valueRange(const box3 &region, float &lo, float &hi) const override
  {
    const box3 r = intersect(region, bounds());
    lo = std::numeric_limits<float>::infinity();
    hi = -lo;
    if (isEmpty(r))
      return;
    lo = length(clamp(kCentre, r.lower, r.upper) - kCentre);
    hi = length(max(abs(r.lower - kCentre), abs(r.upper - kCentre)));
  }
  float cellSize() const override
  {
    return 0.05f;
  }

 protected:
  bool readField() override
  {
    return true;
  }
};

// The nearer intersection of the ray with the sphere of `radius` around
// kCentre beyond tMin, if any (direction normalised).
std::optional<float> sphereDistance(
    float3 origin, float3 direction, float radius, float tMin = 0.f)
{
  const float3 oc = origin - kCentre;
  const double b = dot(oc, direction);
  const double c = double(dot(oc, oc)) - double(radius) * radius;
  const double discriminant = b * b - c;
  if (discriminant < 0.0)
    return std::nullopt;
  const double root = std::sqrt(discriminant);
  for (double t : {-b - root, -b + root}) {
    if (t > tMin)
      return float(t);
  }
  return std::nullopt;
}

// The distance of the ray's line from kCentre.
float missDistance(float3 origin, float3 direction)
{
  const float3 oc = kCentre - origin;
  return length(oc - dot(oc, direction) * direction);
}

class IsosurfaceTest : public testing::MeshTestFixture
{
 protected:
  IsosurfaceTest()
      : m_context([this](const std::string &m) { m_errors.push_back(m); }),
        m_scene(m_context)
  {}

  Isosurface *isosurface(SpatialField *field, std::vector<float> isovalues)
  {
    auto *geometry = make<Isosurface>();
    set(geometry, "field", ANARI_SPATIAL_FIELD, field);
    if (isovalues.size() == 1)
      set(geometry, "isovalue", ANARI_FLOAT32, &isovalues[0]);
    else
      set(geometry, "isovalue", ANARI_ARRAY1D, array(ANARI_FLOAT32, isovalues));
    commit(geometry);
    m_scene.clear();
    geometry->addTo(m_scene, 0);
    m_scene.commit();
    return geometry;
  }

  // Rays from a pinhole camera through kPixels^2 pixel centres: each that
  // passes well inside the sphere of `radius` hits it where the sphere is
  // (distance along the ray, or with `radialDepth` distance from the
  // centre: an interpolated field's error grows along grazing rays), with
  // the sphere's normal; each that passes well outside misses.
  void checkPinholeView(const Isosurface &geometry,
      float radius,
      uint32_t isovalueIndex,
      float depthTolerance,
      float normalTolerance,
      bool radialDepth = false)
  {
    const float3 eye{0.6f, -0.4f, 4.f};
    const float3 forward = normalize(kCentre - eye);
    const float3 right = normalize(cross(forward, float3{0, 1, 0}));
    const float3 up = cross(right, forward);
    constexpr int kPixels = 40;
    int hits = 0, misses = 0;
    for (int y = 0; y < kPixels; y++) {
      for (int x = 0; x < kPixels; x++) {
        // The image plane spans +-0.4 at distance 1: the spheres and more.
        const float sx = 0.8f * ((x + 0.5f) / kPixels - 0.5f);
        const float sy = 0.8f * ((y + 0.5f) / kPixels - 0.5f);
        const float3 direction = normalize(forward + sx * right + sy * up);
        const float passing = missDistance(eye, direction);
        rt::Hit hit;
        const bool found =
            m_scene.intersect(eye, direction, 0.f, 1e30f, hit, 0.5f);
        if (passing > radius * 1.001f) {
          EXPECT_FALSE(found) << x << ' ' << y;
          misses++;
          continue;
        }
        if (passing > radius * 0.999f)
          continue; // grazing: either way
        const std::optional<float> expected =
            sphereDistance(eye, direction, radius);
        ASSERT_TRUE(expected && found) << x << ' ' << y;
        hits++;
        const float3 position = eye + hit.t * direction;
        if (radialDepth) // off the sphere by at most the tolerance
          EXPECT_NEAR(
              length(position - kCentre), radius, depthTolerance * radius)
              << x << ' ' << y;
        else
          EXPECT_NEAR(hit.t, *expected, depthTolerance * radius)
              << x << ' ' << y;
        EXPECT_EQ(hit.primitiveId, isovalueIndex);
        const float3 sphereNormal = normalize(position - kCentre);
        EXPECT_LT(length(normalize(hit.geometricNormal) - sphereNormal),
            normalTolerance);
        AttributeValues attributes;
        const float3 shading = geometry.attributesAt(hit, position, attributes);
        EXPECT_LT(length(shading - sphereNormal), normalTolerance);
        EXPECT_EQ(attributes.primitiveId, isovalueIndex);
      }
    }
    EXPECT_GT(hits, 200);
    EXPECT_GT(misses, 200);
  }

  // The first hit of a ray, or nothing.
  std::optional<rt::Hit> trace(float3 origin, float3 direction)
  {
    rt::Hit hit;
    if (!m_scene.intersect(origin, direction, 0.f, 1e30f, hit, 0.5f))
      return std::nullopt;
    return hit;
  }

  rt::Context m_context;
  rt::Scene m_scene;
};

TEST_F(IsosurfaceTest, SphereOfTheIsovalueSeenThroughPixelCentres)
{
  auto *field = make<DistanceField>();
  commit(field);
  Isosurface *geometry = isosurface(field, {0.8f});
  ASSERT_TRUE(geometry->isValid());
  EXPECT_EQ(geometry->primitiveCount(), 1u);
  checkPinholeView(*geometry, 0.8f, 0, 1e-3f, 1e-2f);
  EXPECT_TRUE(m_errors.empty());
}

TEST_F(IsosurfaceTest, TwoIsovaluesReportTheirIndices)
{
  auto *field = make<DistanceField>();
  commit(field);
  Isosurface *geometry = isosurface(field, {0.5f, 1.2f});
  ASSERT_TRUE(geometry->isValid());
  EXPECT_EQ(geometry->primitiveCount(), 2u);
  // From outside: the outer sphere (isovalue 1).
  checkPinholeView(*geometry, 1.2f, 1, 1e-3f, 1e-2f);
  // From between the spheres: inwards the inner one, outwards the outer.
  const float3 between = kCentre + float3{0, 0, 0.8f};
  auto inwards = trace(between, {0, 0, -1});
  ASSERT_TRUE(inwards);
  EXPECT_EQ(inwards->primitiveId, 0u);
  EXPECT_NEAR(inwards->t, 0.3f, 1e-3f * 0.5f);
  // The normal points to increasing values: away from the centre.
  EXPECT_GT(normalize(inwards->geometricNormal).z, 0.99f);
  auto outwards = trace(between, {0, 0, 1});
  ASSERT_TRUE(outwards);
  EXPECT_EQ(outwards->primitiveId, 1u);
  EXPECT_NEAR(outwards->t, 0.4f, 1e-3f * 1.2f);
  EXPECT_GT(normalize(outwards->geometricNormal).z, 0.99f);
}

TEST_F(IsosurfaceTest, RaysMissingEverySurfaceMiss)
{
  auto *field = make<DistanceField>();
  commit(field);
  isosurface(field, {0.8f});
  // Past the field, through its box but outside the sphere, and away.
  EXPECT_FALSE(trace({5, 5, 5}, {0, 1, 0}));
  EXPECT_FALSE(trace(kCentre + float3{-3, 1.5f, 0}, {1, 0, 0}));
  EXPECT_FALSE(trace(kCentre + float3{0, 0, 3}, {0, 0, 1}));
  // No value in the field reaches the isovalue: no surface anywhere.
  isosurface(field, {10.f});
  EXPECT_FALSE(trace(kCentre + float3{0, 0, 3}, {0, 0, -1}));
}

TEST_F(IsosurfaceTest, MissingOrInvalidInputIsReported)
{
  auto *geometry = make<Isosurface>();
  const float isovalue = 1.f;
  set(geometry, "isovalue", ANARI_FLOAT32, &isovalue);
  commit(geometry);
  EXPECT_FALSE(geometry->isValid());
  EXPECT_TRUE(reported({"'field' is not set"}));

  auto *broken = make<UnstructuredField>(); // committed without arrays
  commit(broken);
  set(geometry, "field", ANARI_SPATIAL_FIELD, broken);
  commit(geometry);
  EXPECT_FALSE(geometry->isValid());
  EXPECT_TRUE(reported({"not a valid spatial field"}));

  auto *field = make<DistanceField>();
  commit(field);
  set(geometry, "field", ANARI_SPATIAL_FIELD, field);
  geometry->unstageParameter("isovalue");
  commit(geometry);
  EXPECT_FALSE(geometry->isValid());
  EXPECT_TRUE(reported({"'isovalue' is not set"}));

  const int wrong = 1;
  set(geometry, "isovalue", ANARI_INT32, &wrong);
  commit(geometry);
  EXPECT_FALSE(geometry->isValid());

  set(geometry, "isovalue", ANARI_FLOAT32, &isovalue);
  commit(geometry);
  EXPECT_TRUE(geometry->isValid());
}

// A grid of hexahedra sampling the distance: the isosurface of the
// interpolated field, within the interpolation's error of the sphere.
TEST_F(IsosurfaceTest, WorksOnAnUnstructuredField)
{
  std::mt19937 rng(1);
  // 40 cells per side over [-2, 2]^3 around kCentre.
  testing::Mesh mesh = testing::hexahedronGrid(40, 0.f, rng);
  for (float3 &p : mesh.positions)
    p = kCentre - float3{2, 2, 2} + 0.1f * p;
  mesh.setVertexData([](float3 p) { return length(p - kCentre); });
  UnstructuredField *field = this->field(mesh);
  ASSERT_TRUE(field->isValid());
  Isosurface *geometry = isosurface(field, {0.6f, 1.3f});
  ASSERT_TRUE(geometry->isValid());
  // Trilinear interpolation of the distance errs by up to ~h^2 / (8 r)
  // per axis; its gradient is piecewise, so normals are looser too.
  checkPinholeView(*geometry, 1.3f, 1, 2e-3f, 5e-2f, true);
  auto inwards = trace(kCentre + float3{0, 0, 1.f}, {0, 0, -1});
  ASSERT_TRUE(inwards);
  EXPECT_EQ(inwards->primitiveId, 0u);
  EXPECT_NEAR(inwards->t, 0.4f, 1e-2f);
}

TEST_F(IsosurfaceTest, DeviceCreatesTheSubtype)
{
  ANARIGeometry handle = m_device.newGeometry("isosurface");
  ASSERT_NE(handle, nullptr);
  EXPECT_NE(dynamic_cast<Isosurface *>(m_device.lookup(handle)), nullptr);
  m_device.release(handle);
}

} // namespace
} // namespace prism
