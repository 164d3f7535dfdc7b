// Lights against analytic answers: inverse-square falloff, the brightness
// precedence of each subtype, the spot profile, Lambert's polygon formula
// for the quad, the sphere and ring in closed form, a uniform environment's
// pi L, photometric tables, placement by instance transforms, and the
// agreement of sample() with radianceAlong() that MIS relies on.
#include "Device.h"
#include "array/Array.h"
#include "light/Directional.h"
#include "light/Distribution2D.h"
#include "light/Hdri.h"
#include "light/Point.h"
#include "light/Quad.h"
#include "light/Ring.h"
#include "light/Sampling.h"
#include "light/Spot.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace prism {
namespace {

using light::kPi;
constexpr double kPiD = 3.14159265358979323846;
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// A rotation of `angle` about the unit `axis` plus a translation.
mat3x4 rotation(float3 axis, float angle, float3 translation = {0, 0, 0})
{
  const float c = std::cos(angle), s = std::sin(angle);
  auto column = [&](float3 e) {
    // Rodrigues: v c + (k x v) s + k (k.v)(1 - c).
    return e * c + cross(axis, e) * s + axis * (dot(axis, e) * (1.f - c));
  };
  return {
      {column({1, 0, 0}), column({0, 1, 0}), column({0, 0, 1}), translation}};
}

mat3x4 scaling(float s, float3 translation = {0, 0, 0})
{
  return {{{s, 0, 0}, {0, s, 0}, {0, 0, s}, translation}};
}

// A sample of `light` from `point`: by sampleFacing() for a receiver
// facing `facing`, or sample() where that is zero.
LightSample sampleOf(const PlacedLight &light,
    const float3 &point,
    const float3 &facing,
    const float2 &u)
{
  return lengthSquared(facing) > 0.f ? light.sampleFacing(point, facing, u)
                                     : light.sample(point, u);
}

// Irradiance at `point` on a plane of unit `normal`, estimated from
// n x n jittered strata of sample(), or sampleFacing() when `facing`
// (exact for delta lights).
double irradiance(const PlacedLight &light,
    float3 point,
    float3 normal,
    int n = 256,
    unsigned seed = 7,
    float3 facing = {0, 0, 0})
{
  if (light.isDelta()) {
    const LightSample s = light.sample(point, {0.5f, 0.5f});
    return s.radiance.x * std::max(0.f, dot(normal, s.direction));
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(0.f, 1.f);
  double sum = 0.0;
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      const float2 u{std::min((i + jitter(rng)) / n, kOneMinusEpsilon),
          std::min((j + jitter(rng)) / n, kOneMinusEpsilon)};
      const LightSample s = sampleOf(light, point, facing, u);
      if (s.pdf > 0.f)
        sum += s.radiance.x * std::max(0.f, dot(normal, s.direction)) / s.pdf;
    }
  }
  return sum / (double(n) * n);
}

// Irradiance on a plane facing `normal` from an environment light,
// integrated over `sub` x `sub` cells of each of its width x height
// texels through the hdri's documented mapping (theta = pi t from `up`,
// phi = 2 pi (s - 0.5) from `forward` towards the right).
double integratedIrradiance(const PlacedLight &light,
    float3 up,
    float3 forward,
    float3 normal,
    uint64_t width,
    uint64_t height,
    int sub = 8)
{
  const float3 right = cross(forward, up);
  const uint64_t columns = width * sub, rows = height * sub;
  double sum = 0.0;
  for (uint64_t b = 0; b < rows; b++) {
    const float theta = float(kPiD * (b + 0.5) / rows);
    for (uint64_t a = 0; a < columns; a++) {
      const float phi = float(2.0 * kPiD * ((a + 0.5) / columns - 0.5));
      const float3 w = normalize(
          (forward * std::cos(phi) + right * std::sin(phi)) * std::sin(theta)
          + up * std::cos(theta));
      float distance, pdf;
      sum += light.radianceAlong({0, 0, 0}, w, distance, pdf).x
             * std::max(0.f, dot(w, normal)) * std::sin(theta);
    }
  }
  return sum * 2.0 * kPiD * kPiD / (double(columns) * rows);
}

// Integral of radianceAlong()'s pdf (radianceAlongFacing()'s for a
// receiver facing `facing`) over the cone around the unit `axis` with
// 1 - cos(half angle) = capHeight (2: the whole sphere), by the midpoint
// rule on an n x n grid uniform in solid angle.
double pdfIntegral(const PlacedLight &light,
    float3 point,
    float3 axis,
    float capHeight,
    int n = 1000,
    float3 facing = {0, 0, 0})
{
  const LocalFrame frame = LocalFrame::around(axis);
  double sum = 0.0;
  for (int i = 0; i < n; i++) {
    // sin from the cap height keeps tiny cones resolved in float.
    const float h = (i + 0.5f) / n * capHeight;
    const float cosTheta = 1.f - h;
    const float sinTheta = std::sqrt(std::max(0.f, h * (2.f - h)));
    for (int j = 0; j < n; j++) {
      const float phi = 2.f * kPi * (j + 0.5f) / n;
      const float3 direction = normalize(frame.toWorld(
          {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta}));
      float distance = 0.f, pdf = 0.f;
      light.radianceAlongFacing(point, facing, direction, distance, pdf);
      sum += pdf;
    }
  }
  return sum * 2.0 * kPiD * capHeight / (double(n) * n);
}

// How many of n x n samples from `point` (by sampleFacing() for a
// receiver facing `facing`) disagree with radianceAlong() (Facing) in
// pdf, radiance or distance (relative 1e-3), or land outside the light's
// bounds (which rays use to skip it); `checked` counts the rest.
int inconsistentSamples(const PlacedLight &light,
    float3 point,
    int &checked,
    int n = 64,
    float3 facing = {0, 0, 0})
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.f, kOneMinusEpsilon);
  int bad = 0;
  checked = 0;
  auto near = [](float a, float b) {
    return std::abs(a - b) <= 1e-3f * std::max(std::abs(a), std::abs(b))
           || (std::isinf(a) && a == b);
  };
  for (int k = 0; k < n * n; k++) {
    const LightSample s =
        sampleOf(light, point, facing, {uniform(rng), uniform(rng)});
    if (!(s.pdf > 0.f))
      continue;
    float distance = 0.f, pdf = 0.f;
    const float3 radiance =
        light.radianceAlongFacing(point, facing, s.direction, distance, pdf);
    LightBounds bounds;
    const bool bounded = light.bounds(bounds);
    const float fromCenter =
        length(point + s.direction * s.distance - bounds.center);
    const bool inside = !bounded || fromCenter <= bounds.radius * 1.0001f;
    const bool ok = near(pdf, s.pdf) && near(radiance.x, s.radiance.x)
                    && near(distance, s.distance) && inside;
    if (!ok && bad++ == 0) {
      ADD_FAILURE() << "sample pdf " << s.pdf << " radiance " << s.radiance.x
                    << " distance " << s.distance << " vs radianceAlong pdf "
                    << pdf << " radiance " << radiance.x << " distance "
                    << distance << "; " << fromCenter
                    << " from the bounds' center (radius " << bounds.radius
                    << ")";
    }
    checked++;
  }
  return bad;
}

// A width x height image brightening along its width, with one texel of
// 500 right of the centre and a third of the way down: a density far
// from uniform.
std::vector<float3> gradientWithHotSpot(uint64_t width, uint64_t height)
{
  std::vector<float3> texels(width * height);
  for (uint64_t j = 0; j < height; j++) {
    for (uint64_t i = 0; i < width; i++) {
      const float v = 0.1f + float(i) / float(width)
                      + (i == width / 2 + 6 && j == height / 3 ? 500.f : 0.f);
      texels[i + j * width] = {v, 0.5f * v, 0.2f};
    }
  }
  return texels;
}

// Lambert's formula: irradiance from a uniform polygon of radiance L,
// E = L/2 |sum_i angle_i n_i . normal| over its edges seen from `point`.
double polygonIrradiance(const std::vector<float3> &corners,
    float3 point,
    float3 normal,
    double radiance)
{
  double3 sum{0, 0, 0};
  for (size_t i = 0; i < corners.size(); i++) {
    const double3 a = normalize(vecCast<double>(corners[i] - point));
    const double3 b =
        normalize(vecCast<double>(corners[(i + 1) % corners.size()] - point));
    const double3 c = cross(a, b);
    sum = sum + normalize(c) * std::atan2(length(c), dot(a, b));
  }
  return radiance * 0.5 * std::abs(dot(sum, vecCast<double>(normal)));
}

class LightTest : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    ANARIStatusCallback callback = [](const void *user,
                                       ANARIDevice,
                                       ANARIObject,
                                       ANARIDataType,
                                       ANARIStatusSeverity,
                                       ANARIStatusCode,
                                       const char *message) {
      ((std::vector<std::string> *)user)->push_back(message);
    };
    const auto device = (ANARIObject)m_device.this_device();
    m_device.setParameter(
        device, "statusCallback", ANARI_STATUS_CALLBACK, &callback);
    m_device.setParameter(
        device, "statusCallbackUserData", ANARI_VOID_POINTER, &m_messages);
  }
  void TearDown() override
  {
    for (ANARIObject array : m_arrays)
      m_device.release(array);
  }

  template <typename T>
  static void set(Object &object, const char *name, ANARIDataType type, T value)
  {
    object.stageParameter(name, Parameter::make(type, &value, nullptr));
  }
  static void setFloat(Object &object, const char *name, float value)
  {
    set(object, name, ANARI_FLOAT32, value);
  }
  static void setVec3(Object &object, const char *name, float3 value)
  {
    set(object, name, ANARI_FLOAT32_VEC3, value);
  }
  static void setString(Object &object, const char *name, const char *value)
  {
    object.stageParameter(name, Parameter::make(ANARI_STRING, value, nullptr));
  }
  static void setArray(Object &object, const char *name, Array *array)
  {
    const ANARIDataType type =
        array->dimensions() == 1 ? ANARI_ARRAY1D : ANARI_ARRAY2D;
    object.stageParameter(name, Parameter::make(type, array, array));
  }
  static void commit(Object &object)
  {
    object.snapshotForCommit();
    object.applyCommit();
    object.finalize();
  }
  // `texels` (width x height) as an hdri's radiance, with `up` and the
  // image's center towards `direction`; not committed.
  void stageHdri(light::Hdri &light,
      const std::vector<float3> &texels,
      uint64_t width,
      uint64_t height,
      float3 up,
      float3 direction)
  {
    setArray(light,
        "radiance",
        array(ANARI_FLOAT32_VEC3, texels.data(), width, height));
    setVec3(light, "up", up);
    setVec3(light, "direction", direction);
  }
  // The same, up +z, its center towards +y, committed.
  void commitHdri(light::Hdri &light,
      const std::vector<float3> &texels,
      uint64_t width,
      uint64_t height)
  {
    stageHdri(light, texels, width, height, {0, 0, 1}, {0, 1, 0});
    commit(light);
  }
  // A managed array holding a copy of `values`.
  Array *array(
      ANARIDataType type, const void *values, uint64_t n1, uint64_t n2 = 0)
  {
    ANARIObject handle = n2 ? (ANARIObject)m_device.newArray2D(
                             nullptr, nullptr, nullptr, type, n1, n2)
                            : (ANARIObject)m_device.newArray1D(
                                nullptr, nullptr, nullptr, type, n1);
    auto *result = (Array *)m_device.lookup(handle);
    std::memcpy(
        result->map(), values, result->capacity() * anari::sizeOf(type));
    result->unmap();
    m_arrays.push_back(handle);
    return result;
  }
  // Whether a reported message contains every one of `parts`.
  bool reported(std::initializer_list<const char *> parts) const
  {
    for (const std::string &message : m_messages) {
      bool all = true;
      for (const char *part : parts)
        all = all && message.find(part) != std::string::npos;
      if (all)
        return true;
    }
    return false;
  }
  static std::unique_ptr<PlacedLight> place(
      const Light &light, const mat3x4 &worldFromObject = kIdentityMat3x4)
  {
    auto placed = light.place(worldFromObject);
    EXPECT_TRUE(placed) << "light not placed";
    return placed;
  }

  std::vector<std::string> m_messages;
  Device m_device{nullptr};
  std::vector<ANARIObject> m_arrays;
};

// ---------------------------------------------------------------------------
// Parameters every light shares

TEST_F(LightTest, ColorFiltersAndVisibleControlsCameraVisibility)
{
  light::Point light(m_device);
  setFloat(light, "intensity", 2.f);
  setVec3(light, "color", {0.5f, 0.25f, 1.f});
  set(light, "visible", ANARI_BOOL, uint8_t(0));
  commit(light);
  EXPECT_TRUE(light.isValid());
  EXPECT_FALSE(light.visible());
  const auto placed = place(light);
  EXPECT_FALSE(placed->visibleToCamera);
  const LightSample s = placed->sample({0, 0, -1}, {0.5f, 0.5f});
  EXPECT_FLOAT_EQ(s.radiance.x, 1.f);
  EXPECT_FLOAT_EQ(s.radiance.y, 0.5f);
  EXPECT_FLOAT_EQ(s.radiance.z, 2.f);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

// A color above the definitions' advisory maximum (1, 1, 1) is HDR input:
// taken as set, without a warning; NaN or negative makes the light invalid.
TEST_F(LightTest, HdrColorIsTakenAsSet)
{
  light::Point light(m_device);
  setFloat(light, "intensity", 1.f);
  setVec3(light, "color", {4.f, 2.f, 0.5f});
  commit(light);
  EXPECT_TRUE(light.isValid());
  const LightSample s = place(light)->sample({0, 0, -1}, {0.5f, 0.5f});
  EXPECT_FLOAT_EQ(s.radiance.x, 4.f);
  EXPECT_FLOAT_EQ(s.radiance.y, 2.f);
  EXPECT_FLOAT_EQ(s.radiance.z, 0.5f);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
  for (float bad : {std::nanf(""), -0.5f}) {
    light::Point invalid(m_device);
    setVec3(invalid, "color", {1.f, bad, 1.f});
    commit(invalid);
    EXPECT_FALSE(invalid.isValid()) << bad;
  }
  EXPECT_TRUE(reported({"'color'", "must be finite and >= 0"}));
}

TEST_F(LightTest, DefaultsAreVisibleAndWhite)
{
  light::Directional light(m_device);
  commit(light);
  EXPECT_TRUE(light.visible());
  EXPECT_EQ(light.color(), (float3{1, 1, 1}));
  EXPECT_TRUE(place(light)->visibleToCamera);
}

TEST_F(LightTest, FactoryCreatesEverySubtype)
{
  for (const char *subtype :
      {"directional", "hdri", "point", "quad", "ring", "spot"}) {
    Light *light = createLight(m_device, subtype);
    ASSERT_TRUE(light) << subtype;
    EXPECT_EQ(light->subtype(), subtype);
    EXPECT_EQ(light->type(), ANARI_LIGHT);
    light->releaseInternal();
  }
  EXPECT_EQ(createLight(m_device, "area"), nullptr);
}

// ---------------------------------------------------------------------------
// Point and sphere

TEST_F(LightTest, PointIrradianceFallsWithInverseSquare)
{
  light::Point light(m_device);
  setVec3(light, "position", {1, 2, 3});
  setFloat(light, "intensity", 3.f);
  commit(light);
  const auto placed = place(light);
  EXPECT_TRUE(placed->isDelta());
  EXPECT_FALSE(placed->isInfinite());
  for (float d : {0.5f, 1.f, 2.f, 10.f, 1000.f}) {
    const float3 point = float3{1, 2, 3} + normalize(float3{1, -2, 2}) * d;
    const LightSample s = placed->sample(point, {0.3f, 0.7f});
    EXPECT_TRUE(s.delta);
    EXPECT_EQ(s.pdf, 1.f);
    EXPECT_NEAR(s.distance, d, 1e-5f * d);
    EXPECT_NEAR(s.radiance.x, 3.f / (d * d), 1e-5f * 3.f / (d * d));
    EXPECT_NEAR(dot(s.direction, -normalize(float3{1, -2, 2})), 1.f, 1e-6f);
    float distance = 0.f, pdf = 1.f;
    EXPECT_EQ(placed->radianceAlong(point, s.direction, distance, pdf).x, 0.f);
    EXPECT_EQ(pdf, 0.f);
  }
  EXPECT_NEAR(placed->power().x, 4.f * kPi * 3.f, 1e-4f);
}

// PRISM_LIGHT_DECAY: the intensity reaches distance d as I / d^decay; 2
// is the inverse square exactly, 0 keeps I at any distance, and a decay
// above the declared [0, 4] is clamped to 4 with a warning; below it or
// not a number it is reported and leaves the light invalid.
TEST_F(LightTest, PointAndSpotDecay)
{
  for (const char *subtype : {"point", "spot"}) {
    for (float decay : {0.f, 1.f, 2.f, 3.f}) {
      std::unique_ptr<Light> light;
      if (std::string(subtype) == "point")
        light = std::make_unique<light::Point>(m_device);
      else
        light = std::make_unique<light::Spot>(m_device);
      setVec3(*light, "position", {0, 0, 0});
      setFloat(*light, "intensity", 3.f);
      if (std::string(subtype) == "spot")
        setVec3(*light, "direction", {0, 0, -1});
      setFloat(*light, "decay", decay);
      commit(*light);
      const auto placed = place(*light);
      ASSERT_TRUE(placed) << subtype;
      for (float d : {0.5f, 2.f, 10.f}) {
        const LightSample s = placed->sample({0, 0, -d}, {0.3f, 0.7f});
        const float expected = 3.f / std::pow(d, decay);
        EXPECT_NEAR(s.radiance.x, expected, 1e-5f * expected)
            << subtype << " decay " << decay << " at " << d;
      }
    }
  }
  light::Point clamped(m_device);
  setFloat(clamped, "intensity", 1.f);
  setFloat(clamped, "decay", 7.f);
  commit(clamped);
  EXPECT_TRUE(reported({"'decay' (7) must be in [0, 4]", "clamped to 4"}));
  const LightSample s = place(clamped)->sample({0, 0, -2.f}, {0.3f, 0.7f});
  EXPECT_NEAR(s.radiance.x, 1.f / 16.f, 1e-6f);
  // Not a number, or negative: reported, and the light is invalid.
  for (float bad : {std::nanf(""), -1.f}) {
    light::Point invalid(m_device);
    setFloat(invalid, "decay", bad);
    commit(invalid);
    EXPECT_FALSE(invalid.place(kIdentityMat3x4)) << bad;
  }
  EXPECT_TRUE(
      reported({"'decay' (-1) must be in [0, 4]", "the light is invalid"}));
  EXPECT_TRUE(reported({"'decay' (nan) is not a number"}));
}

TEST_F(LightTest, PointPowerIsIntensityOverFourPi)
{
  light::Point light(m_device);
  setFloat(light, "power", 10.f);
  commit(light);
  EXPECT_NEAR(light.intensity(), 10.f / (4.f * kPi), 1e-6f);
  const LightSample s = place(light)->sample({0, 0, 2}, {0, 0});
  EXPECT_NEAR(s.radiance.x * 4.f, 10.f / (4.f * kPi), 1e-6f);
  EXPECT_NEAR(place(light)->power().x, 10.f, 1e-5f);
}

TEST_F(LightTest, PointPrecedenceIsIntensityPowerRadiance)
{
  light::Point light(m_device);
  setFloat(light, "radius", 0.5f);
  setFloat(light, "radiance", 5.f);
  commit(light);
  EXPECT_NEAR(light.intensity(), 5.f * kPi * 0.25f, 1e-5f); // L pi r^2
  setFloat(light, "power", 8.f);
  commit(light);
  EXPECT_NEAR(light.intensity(), 8.f / (4.f * kPi), 1e-6f);
  setFloat(light, "intensity", 2.f);
  commit(light);
  EXPECT_EQ(light.intensity(), 2.f);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(LightTest, PointRadianceWithoutRadiusEmitsNothing)
{
  light::Point light(m_device);
  setFloat(light, "radiance", 5.f);
  commit(light);
  EXPECT_TRUE(light.isValid());
  EXPECT_EQ(place(light)->sample({0, 0, 1}, {0, 0}).radiance.x, 0.f);
}

TEST_F(LightTest, SphereLightGivesTheSameIrradianceAsAPoint)
{
  // A uniform sphere of intensity I gives exactly I / d^2 on a plane facing
  // its center (pi L sin^2 with L = I / (pi r^2), sin = r / d).
  light::Point light(m_device);
  setVec3(light, "position", {0, 0, 3});
  setFloat(light, "radius", 0.5f);
  setFloat(light, "intensity", 4.f);
  commit(light);
  const auto placed = place(light);
  EXPECT_FALSE(placed->isDelta());
  for (float d : {1.f, 3.f, 20.f}) {
    const float3 point{0, 0, 3 - d};
    EXPECT_NEAR(irradiance(*placed, point, {0, 0, 1}),
        4.0 / (d * d),
        1e-3 * 4.0 / (d * d))
        << d;
  }
  // Tilted receiver: the cap is symmetric, so E = I / d^2 cos(tilt) while
  // the whole cap is above the horizon.
  const float3 tilted = normalize(float3{0.3f, 0, 1});
  EXPECT_NEAR(irradiance(*placed, {0, 0, 0}, tilted),
      4.0 / 9.0 * tilted.z,
      1e-3 * 4.0 / 9.0);
  EXPECT_NEAR(placed->power().x, 4.f * kPi * 4.f, 1e-3f);
}

TEST_F(LightTest, SpherePdfMatchesRadianceAlongAndIntegratesToOne)
{
  light::Point light(m_device);
  setVec3(light, "position", {1, 0, 0});
  setFloat(light, "radius", 0.3f);
  commit(light);
  const auto placed = place(light);
  for (float3 point :
      {float3{0, 0, 0}, float3{-2, 1, 0.5f}, float3{1, 0, 0.35f}}) {
    int checked = 0;
    EXPECT_EQ(inconsistentSamples(*placed, point, checked), 0);
    EXPECT_GT(checked, 4000);
    // Over a cone half again as high as the one the sphere subtends.
    const float3 offset = float3{1, 0, 0} - point;
    const float sin2 = 0.09f / lengthSquared(offset);
    const float cap = std::min(2.f, 1.5f * (1.f - std::sqrt(1.f - sin2)));
    EXPECT_NEAR(
        pdfIntegral(*placed, point, normalize(offset), cap, 2000), 1.0, 5e-3);
  }
  // Inside the sphere nothing is seen (it emits outwards).
  EXPECT_EQ(placed->sample({1, 0, 0.1f}, {0.5f, 0.5f}).pdf, 0.f);
}

TEST_F(LightTest, RimSamplesAreSeenByRadianceAlong)
{
  // u -> 1 puts samples on the rim of a cone or the edge of a quad, where
  // rounding must not push them outside what radianceAlong() sees.
  light::Directional sun(m_device);
  setVec3(sun, "direction", {1, 2, -3});
  setFloat(sun, "angularDiameter", 0.00925f);
  light::Directional wide(m_device);
  setFloat(wide, "angularDiameter", 1.f);
  light::Point sphere(m_device);
  setVec3(sphere, "position", {3, 4, 5});
  setFloat(sphere, "radius", 0.01f);
  light::Quad quad(m_device);
  setVec3(quad, "position", {-1, -2, 3});
  setVec3(quad, "edge1", {2, 0.5f, 0});
  setVec3(quad, "edge2", {0, 1.5f, 0.2f});
  setString(quad, "side", "both");
  for (Light *light :
      std::initializer_list<Light *>{&sun, &wide, &sphere, &quad}) {
    commit(*light);
    const auto placed = place(*light);
    // Near, and far enough for the quad to be sampled by area.
    for (float3 point : {float3{0.1f, 0.2f, 0.3f}, float3{300, -200, 900}}) {
      int misses = 0;
      for (int k = 0; k < 4000; k++) {
        const float v = k / 4000.f;
        for (float2 u : {float2{kOneMinusEpsilon, v},
                 float2{v, kOneMinusEpsilon},
                 float2{0.f, v},
                 float2{v, 0.f}}) {
          const LightSample s = placed->sample(point, u);
          float distance = 0.f, pdf = 0.f;
          placed->radianceAlong(point, s.direction, distance, pdf);
          misses += s.pdf > 0.f && !(std::abs(pdf - s.pdf) <= 1e-3f * s.pdf);
        }
      }
      EXPECT_EQ(misses, 0) << light->subtype() << " from " << point.x;
    }
  }
}

// ---------------------------------------------------------------------------
// Spot

TEST_F(LightTest, SpotIsFullInsideTheCoreZeroOutsideSmoothstepBetween)
{
  light::Spot light(m_device);
  setVec3(light, "position", {0, 0, 0});
  setVec3(light, "direction", {0, 0, -2});
  setFloat(light, "openingAngle", 1.f);  // half angle 0.5
  setFloat(light, "falloffAngle", 0.2f); // core half angle 0.3
  setFloat(light, "intensity", 5.f);
  commit(light);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
  const auto placed = place(light);
  EXPECT_TRUE(placed->isDelta());
  auto intensityAt = [&](float theta) {
    const float d = 2.f;
    const float3 point{d * std::sin(theta), 0, -d * std::cos(theta)};
    return placed->sample(point, {0, 0}).radiance.x * d * d;
  };
  auto smoothstep = [](float t) {
    return t * t * (3 - 2 * t);
  };
  EXPECT_NEAR(intensityAt(0.f), 5.f, 1e-5f);
  EXPECT_NEAR(intensityAt(0.2f), 5.f, 1e-5f);
  EXPECT_NEAR(intensityAt(0.299f), 5.f, 1e-5f);
  EXPECT_NEAR(intensityAt(0.35f), 5.f * smoothstep(0.75f), 1e-4f);
  EXPECT_NEAR(intensityAt(0.4f), 2.5f, 1e-4f);
  EXPECT_NEAR(intensityAt(0.45f), 5.f * smoothstep(0.25f), 1e-4f);
  EXPECT_NEAR(intensityAt(0.501f), 0.f, 1e-6f);
  EXPECT_EQ(intensityAt(0.7f), 0.f);
  EXPECT_EQ(intensityAt(3.f), 0.f);
}

TEST_F(LightTest, SpotPowerIsTheCosineWeightedIntegral)
{
  // Without falloff the spec's approximation is exact:
  // P = pi (1 - cos^2(openingAngle / 2)) I.
  light::Spot sharp(m_device);
  setFloat(sharp, "openingAngle", 1.f);
  setFloat(sharp, "falloffAngle", 0.f);
  setFloat(sharp, "power", 7.f);
  commit(sharp);
  const float c = std::cos(0.5f);
  EXPECT_NEAR(sharp.intensity(), 7.f / (kPi * (1.f - c * c)), 1e-4f);

  // With falloff: P = 2 pi integral of I profile cos sin dtheta, summed
  // here independently by the midpoint rule.
  light::Spot soft(m_device);
  setFloat(soft, "openingAngle", 1.2f);
  setFloat(soft, "falloffAngle", 0.25f);
  setFloat(soft, "power", 7.f);
  commit(soft);
  const auto placed = place(soft);
  const int n = 200000;
  double power = 0.0;
  for (int i = 0; i < n; i++) {
    const double theta = (i + 0.5) / n * kPiD;
    const float3 point{float(std::sin(theta)), 0, -float(std::cos(theta))};
    const double intensity = placed->sample(point, {0, 0}).radiance.x;
    power += intensity * std::max(0.0, std::cos(theta)) * std::sin(theta);
  }
  power *= 2.0 * kPiD * kPiD / n;
  EXPECT_NEAR(power, 7.0, 1e-3);

  // Intensity takes precedence over power.
  setFloat(soft, "intensity", 3.f);
  commit(soft);
  EXPECT_EQ(soft.intensity(), 3.f);
}

TEST_F(LightTest, SpotFalloffWiderThanHalfTheOpeningIsClamped)
{
  light::Spot light(m_device);
  setFloat(light, "openingAngle", 0.4f);
  setFloat(light, "falloffAngle", 0.5f);
  commit(light);
  EXPECT_TRUE(light.isValid());
  EXPECT_TRUE(reported({"falloffAngle", "half"}));
  EXPECT_NEAR(light.falloff().innerAngle(), 0.f, 1e-6f);
}

// ---------------------------------------------------------------------------
// Directional

TEST_F(LightTest, DirectionalIrradianceOnAFacingPlane)
{
  light::Directional light(m_device);
  setVec3(light, "direction", {0, -1, 0});
  setFloat(light, "irradiance", 3.f);
  commit(light);
  const auto placed = place(light);
  EXPECT_TRUE(placed->isDelta());
  EXPECT_TRUE(placed->isInfinite());
  const LightSample s = placed->sample({5, 6, 7}, {0.2f, 0.9f});
  EXPECT_EQ(s.direction, (float3{0, 1, 0}));
  EXPECT_TRUE(std::isinf(s.distance));
  EXPECT_EQ(irradiance(*placed, {0, 0, 0}, {0, 1, 0}), 3.0);
  const float3 tilted = normalize(float3{1, 1, 0});
  EXPECT_NEAR(irradiance(*placed, {0, 0, 0}, tilted), 3.0 * tilted.y, 1e-6);
}

TEST_F(LightTest, DirectionalDiskKeepsIrradianceAndMatchesRadiance)
{
  // irradiance E with an angular diameter: same E on a facing plane, from
  // a disk of radiance E / (pi sin^2(diameter / 2)).
  light::Directional light(m_device);
  setVec3(light, "direction", {1, 1, -1});
  setFloat(light, "angularDiameter", 0.1f);
  setFloat(light, "irradiance", 3.f);
  commit(light);
  const auto placed = place(light);
  EXPECT_FALSE(placed->isDelta());
  const float3 facing = -normalize(float3{1, 1, -1});
  EXPECT_NEAR(irradiance(*placed, {0, 0, 0}, facing), 3.0, 3e-4);
  const float solidAngle = 2.f * kPi * (1.f - std::cos(0.05f));
  // E = L x solid angle x cos for a small disk (to 0.1% at 0.1 rad).
  EXPECT_NEAR(light.radiance() * solidAngle, 3.f, 3e-3f);

  int checked = 0;
  EXPECT_EQ(inconsistentSamples(*placed, {0, 0, 0}, checked), 0);
  EXPECT_GT(checked, 4000);
  EXPECT_NEAR(
      pdfIntegral(*placed, {0, 0, 0}, facing, 0.0025f, 2000), 1.0, 5e-3);
}

TEST_F(LightTest, DirectionalRadianceOfTheSun)
{
  // The sun: 0.00925 rad; radiance L gives E = pi L sin^2, ~ L x solid angle.
  light::Directional light(m_device);
  setFloat(light, "angularDiameter", 0.00925f);
  setFloat(light, "radiance", 1e6f);
  commit(light);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
  const double solidAngle = 2.0 * kPiD * (1.0 - std::cos(0.00925 / 2));
  EXPECT_NEAR(light.irradiance(), 1e6 * solidAngle, 1e-4 * 1e6 * solidAngle);
  const auto placed = place(light);
  EXPECT_NEAR(irradiance(*placed, {0, 0, 0}, {0, 0, 1}),
      light.irradiance(),
      1e-3 * light.irradiance());

  // Irradiance takes precedence over radiance.
  setFloat(light, "irradiance", 2.f);
  commit(light);
  EXPECT_EQ(light.irradiance(), 2.f);
  // Radiance from a zero-size disk emits nothing (spec 5.7.1).
  light::Directional point(m_device);
  setFloat(point, "radiance", 1e6f);
  commit(point);
  EXPECT_EQ(place(point)->sample({0, 0, 0}, {0, 0}).radiance.x, 0.f);
}

// ---------------------------------------------------------------------------
// Quad

struct QuadCase
{
  float3 point;
  float3 normal;
};

TEST_F(LightTest, QuadIrradianceMatchesLambertsFormula)
{
  // 2 x 1 rectangle at z = 2; edge2 x edge1 = -z, so it faces the origin.
  const float3 corner{-1.f, -0.5f, 2.f}, edge1{2, 0, 0}, edge2{0, 1, 0};
  light::Quad light(m_device);
  setVec3(light, "position", corner);
  setVec3(light, "edge1", edge1);
  setVec3(light, "edge2", edge2);
  setFloat(light, "intensity", 4.f); // radiance 4 / area 2 = 2
  commit(light);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
  const auto placed = place(light);
  const std::vector<float3> corners = {
      corner, corner + edge1, corner + edge1 + edge2, corner + edge2};
  for (const QuadCase &c : {QuadCase{{0.3f, -0.2f, 0}, {0, 0, 1}},
           QuadCase{{0.3f, -0.2f, 1.5f}, {0, 0, 1}},
           QuadCase{{-2.f, 1.f, -1.f}, normalize(float3{-0.5f, 0.3f, 1})},
           QuadCase{{5.f, 2.f, -3.f}, normalize(float3{-1, -0.5f, 1})},
           // Far enough for the quad to be sampled by area.
           QuadCase{
               {100.f, 300.f, -900.f}, normalize(float3{-0.1f, -0.3f, 1})}}) {
    const double expected = polygonIrradiance(corners, c.point, c.normal, 2.0);
    EXPECT_NEAR(
        irradiance(*placed, c.point, c.normal), expected, 1e-2 * expected)
        << c.point.x << ", " << c.point.y << ", " << c.point.z;
  }
  EXPECT_NEAR(placed->power().x, 4.f * kPi, 1e-4f);
}

TEST_F(LightTest, QuadPdfMatchesRadianceAlongAndIntegratesToOne)
{
  const float3 corner{-1.f, -0.5f, 2.f}, edge1{2, 0, 0.5f}, edge2{0.3f, 1, 0};
  light::Quad light(m_device);
  setVec3(light, "position", corner);
  setVec3(light, "edge1", edge1);
  setVec3(light, "edge2", edge2);
  setString(light, "side", "both");
  commit(light);
  const auto placed = place(light);
  const float3 center = corner + edge1 * 0.5f + edge2 * 0.5f;
  for (float3 point : {float3{0, 0, 0},
           float3{0.2f, 0.1f, 2.3f},
           float3{3, -2, 1},
           float3{200, 100, -700}}) {
    int checked = 0;
    EXPECT_EQ(inconsistentSamples(*placed, point, checked), 0);
    EXPECT_GT(checked, 4000);
    // A cone around the quad's center holding all of it.
    const float3 axis = normalize(center - point);
    float cap = 0.f;
    for (float3 p :
        {corner, corner + edge1, corner + edge2, corner + edge1 + edge2})
      cap = std::max(cap, 1.f - dot(axis, normalize(p - point)));
    cap = std::min(2.f, cap * 1.5f + 1e-6f);
    EXPECT_NEAR(pdfIntegral(*placed, point, axis, cap, 2000), 1.0, 5e-3)
        << point.x << ", " << point.y << ", " << point.z;
  }
}

TEST_F(LightTest, QuadSidesAndBrightnessPrecedence)
{
  auto make = [&](light::Quad &light, const char *side) {
    setVec3(light, "position", {-0.5f, -0.5f, 0});
    setString(light, "side", side);
  };
  // Default edges (x, y): the front side, edge2 x edge1, faces -z.
  light::Quad front(m_device), back(m_device), both(m_device);
  make(front, "front");
  make(back, "back");
  make(both, "both");
  for (light::Quad *light : {&front, &back, &both}) {
    setFloat(*light, "radiance", 3.f);
    commit(*light);
  }
  const float3 below{0, 0, -1}, above{0, 0, 1};
  auto fromBelow = [&](const Light &l) {
    return irradiance(*place(l), below, {0, 0, 1}, 64);
  };
  auto fromAbove = [&](const Light &l) {
    return irradiance(*place(l), above, {0, 0, -1}, 64);
  };
  EXPECT_GT(fromBelow(front), 0.0);
  EXPECT_EQ(fromAbove(front), 0.0);
  EXPECT_EQ(fromBelow(back), 0.0);
  EXPECT_GT(fromAbove(back), 0.0);
  EXPECT_NEAR(fromAbove(both), fromBelow(front), 1e-3 * fromBelow(front));
  EXPECT_NEAR(fromBelow(both), fromBelow(front), 1e-6);
  EXPECT_NEAR(place(both)->power().x, 2.f * kPi * 3.f, 1e-4f); // 2 pi L A

  // Power P of a one-sided Lambertian quad: intensity P / pi, radiance
  // P / (pi A); intensity beats power beats radiance.
  setFloat(front, "power", 6.f);
  setVec3(front, "edge1", {2, 0, 0});
  commit(front);
  float distance = 0, pdf = 0;
  EXPECT_NEAR(
      place(front)->radianceAlong({0, 0, -1}, {0, 0, 1}, distance, pdf).x,
      6.f / (kPi * 2.f),
      1e-5f);
  setFloat(front, "intensity", 1.f);
  commit(front);
  EXPECT_NEAR(
      place(front)->radianceAlong({0, 0, -1}, {0, 0, 1}, distance, pdf).x,
      0.5f,
      1e-6f);
}

TEST_F(LightTest, QuadIntensityDistributionScalesFarFieldIntensity)
{
  // A 1 cm quad seen from 10 m: irradiance facing it is I(w) / d^2.
  const float size = 0.01f, d = 10.f;
  const float3 edge1{size, 0, 0}, edge2{0, size, 0};
  auto farIntensity = [&](const PlacedLight &placed, float3 towards) {
    const float3 point = normalize(towards) * d;
    return irradiance(placed, point, -normalize(towards), 16) * d * d;
  };
  // Front normal edge2 x edge1 = -z is gamma 0; C0 along edge1 (+x), and
  // C = 90 degrees along z x x = -y.
  const float3 axis{0, 0, -1}, c0{1, 0, 0}, c90{0, -1, 0};
  auto towards = [&](float gamma, float c) {
    return axis * std::cos(gamma)
           + (c0 * std::cos(c) + c90 * std::sin(c)) * std::sin(gamma);
  };

  // 1D and isotropic, both sides: intensity I in every direction.
  {
    const float values[2] = {1.f, 1.f};
    light::Quad light(m_device);
    setVec3(light, "position", {-size / 2, -size / 2, 0});
    setVec3(light, "edge1", edge1);
    setVec3(light, "edge2", edge2);
    setString(light, "side", "both");
    setFloat(light, "power", 8.f); // I = P / (4 pi)
    setArray(light, "intensityDistribution", array(ANARI_FLOAT32, values, 2));
    commit(light);
    EXPECT_TRUE(light.isValid());
    const auto placed = place(light);
    for (float gamma : {0.f, 0.5f, 1.f, 2.f, 2.8f}) {
      EXPECT_NEAR(farIntensity(*placed, towards(gamma, 0.3f)),
          8.0 / (4.0 * kPiD),
          2e-3 * 8.0 / (4.0 * kPiD))
          << gamma;
    }
    EXPECT_NEAR(placed->power().x, 8.f, 1e-4f);
  }
  // 2D: rows at C = 0, 90, 180, 270 degrees, constant along gamma.
  {
    const float values[8] = {1, 1, 2, 2, 3, 3, 4, 4};
    light::Quad light(m_device);
    setVec3(light, "position", {-size / 2, -size / 2, 0});
    setVec3(light, "edge1", edge1);
    setVec3(light, "edge2", edge2);
    setFloat(light, "intensity", 2.f);
    setArray(
        light, "intensityDistribution", array(ANARI_FLOAT32, values, 2, 4));
    commit(light);
    EXPECT_TRUE(light.isValid());
    const auto placed = place(light);
    const float gamma = 1.f;
    EXPECT_NEAR(farIntensity(*placed, towards(gamma, 0.f)), 2.0, 4e-3);
    EXPECT_NEAR(farIntensity(*placed, towards(gamma, 0.5f * kPi)), 4.0, 8e-3);
    EXPECT_NEAR(farIntensity(*placed, towards(gamma, 0.25f * kPi)), 3.0, 6e-3);
    EXPECT_NEAR(farIntensity(*placed, towards(gamma, 1.5f * kPi)), 8.0, 2e-2);
    EXPECT_NEAR(farIntensity(*placed, towards(gamma, 1.75f * kPi)), 5.0, 1e-2);
    // Front side only: nothing behind.
    EXPECT_EQ(farIntensity(*placed, towards(2.f, 0.f)), 0.0);
  }
}

// ---------------------------------------------------------------------------
// Ring

TEST_F(LightTest, RingWithoutRadiusIsALambertianSpot)
{
  light::Ring light(m_device);
  setVec3(light, "direction", {0, 0, -1});
  setFloat(light, "intensity", 2.f);
  setFloat(light, "openingAngle", 2.f);
  setFloat(light, "falloffAngle", 0.2f);
  commit(light);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
  const auto placed = place(light);
  EXPECT_TRUE(placed->isDelta());
  auto intensityAt = [&](float theta) {
    const float3 point{3 * std::sin(theta), 0, -3 * std::cos(theta)};
    return placed->sample(point, {0, 0}).radiance.x * 9.f;
  };
  EXPECT_NEAR(intensityAt(0.f), 2.f, 1e-5f);
  EXPECT_NEAR(intensityAt(0.5f), 2.f * std::cos(0.5f), 1e-5f);
  EXPECT_NEAR(intensityAt(0.9f), 2.f * std::cos(0.9f) * 0.5f, 1e-4f);
  EXPECT_EQ(intensityAt(1.2f), 0.f);
}

TEST_F(LightTest, BoundsHoldEveryPointRaysCanFindWhereverPlaced)
{
  // Rays skip a light whose bounding sphere they pass, so every sampled
  // point (which radianceAlong() must find) lies inside it, also under a
  // rotating, scaling instance; lights at infinity have no bounds.
  const mat3x4 moves[] = {kIdentityMat3x4,
      rotation(normalize(float3{1, 2, 3}), 1.1f, {4, -2, 7}),
      scaling(3.f, {-1, 0, 2})};
  light::Quad quad(m_device);
  setVec3(quad, "position", {-1.f, -0.5f, 2.f});
  setVec3(quad, "edge1", {2, 0, 0.5f});
  setVec3(quad, "edge2", {0.3f, 1, 0});
  setString(quad, "side", "both");
  commit(quad);
  light::Point sphere(m_device);
  setVec3(sphere, "position", {1, 0, 0});
  setFloat(sphere, "radius", 0.3f);
  commit(sphere);
  light::Ring ring(m_device);
  setVec3(ring, "position", {0, 1, 0});
  setVec3(ring, "direction", {0, -1, 0});
  setFloat(ring, "radius", 0.8f);
  setFloat(ring, "falloffAngle", 0.f);
  commit(ring);
  for (const Light *light :
      {(const Light *)&quad, (const Light *)&sphere, (const Light *)&ring}) {
    for (const mat3x4 &move : moves) {
      const auto placed = place(*light, move);
      LightBounds bounds;
      EXPECT_TRUE(placed->bounds(bounds)) << light->subtype();
      int total = 0;
      for (float3 point : {float3{0, -3, 0}, float3{5, 4, -3}}) {
        int checked = 0;
        EXPECT_EQ(inconsistentSamples(*placed, point, checked, 32), 0)
            << light->subtype();
        total += checked;
      }
      EXPECT_GT(total, 500) << light->subtype();
    }
  }
  light::Directional sun(m_device);
  setFloat(sun, "angularDiameter", 0.1f);
  commit(sun);
  LightBounds none;
  EXPECT_FALSE(place(sun)->bounds(none));
}

TEST_F(LightTest, RingIrradianceOnTheAxisIsTheAnnulusFormula)
{
  // A uniform annulus of radiance L, radii r < R, at distance d on its
  // axis: E = pi L (R^2 / (R^2 + d^2) - r^2 / (r^2 + d^2)).
  const float R = 1.f, r = 0.4f;
  light::Ring light(m_device);
  setVec3(light, "position", {0, 0, 0});
  setVec3(light, "direction", {0, 0, -1});
  setFloat(light, "radius", R);
  setFloat(light, "innerRadius", r);
  setFloat(light, "radiance", 3.f);
  setFloat(light, "falloffAngle", 0.f); // the whole hemisphere at full
  commit(light);
  const auto placed = place(light);
  for (float d : {0.5f, 2.f, 10.f}) {
    const double expected =
        kPiD * 3.0 * (R * R / (R * R + d * d) - r * r / (r * r + d * d));
    EXPECT_NEAR(
        irradiance(*placed, {0, 0, -d}, {0, 0, 1}), expected, 1e-2 * expected)
        << d;
  }
  int checked = 0;
  EXPECT_EQ(inconsistentSamples(*placed, {0.3f, 0.2f, -1.f}, checked), 0);
  EXPECT_GT(checked, 4000);
  EXPECT_NEAR(pdfIntegral(*placed, {0.3f, 0.2f, -1.f}, {0, 0, 1}, 1.f, 2000),
      1.0,
      5e-3);
  // Power: pi L A, the area pi (R^2 - r^2).
  EXPECT_NEAR(placed->power().x, kPi * 3.f * kPi * (R * R - r * r), 1e-3f);
}

TEST_F(LightTest, RingPowerNormalisesTheCone)
{
  light::Ring light(m_device);
  setFloat(light, "radius", 0.5f);
  setFloat(light, "power", 5.f);
  setFloat(light, "falloffAngle", 0.f);
  commit(light);
  // Lambertian over a hemisphere: intensity P / pi along the axis.
  const auto placed = place(light);
  EXPECT_NEAR(placed->power().x, 5.f, 1e-4f);
  const float d = 200.f;
  EXPECT_NEAR(
      irradiance(*placed, {0, 0, -d}, {0, 0, 1}, 32) * d * d, 5.0 / kPiD, 1e-3);
}

// ---------------------------------------------------------------------------
// Hdri

TEST_F(LightTest, UniformHdriGivesPiLOnEveryPlane)
{
  const uint64_t width = 64, height = 32;
  std::vector<float3> texels(width * height, float3{2.f, 2.f, 2.f});
  light::Hdri light(m_device);
  setArray(light,
      "radiance",
      array(ANARI_FLOAT32_VEC3, texels.data(), width, height));
  commit(light);
  EXPECT_TRUE(light.isValid());
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
  const auto placed = place(light);
  EXPECT_TRUE(placed->isInfinite());
  for (float3 normal : {float3{0, 0, 1},
           float3{1, 0, 0},
           float3{0, 0, -1},
           normalize(float3{1, 2, -3})}) {
    EXPECT_NEAR(
        irradiance(*placed, {0, 0, 0}, normal), 2.0 * kPiD, 1e-2 * 2.0 * kPiD);
  }
  EXPECT_NEAR(placed->power().x, 4.f * kPi * 2.f, 1e-3f);
}

TEST_F(LightTest, HdriPdfMatchesRadianceAlongAndIntegratesToOne)
{
  // A gradient with a hot spot: a density far from uniform.
  const uint64_t width = 48, height = 24;
  const std::vector<float3> texels = gradientWithHotSpot(width, height);
  light::Hdri light(m_device);
  stageHdri(light, texels, width, height, {0, 1, 0}, {0, 0, -1});
  setFloat(light, "scale", 0.5f);
  commit(light);
  const mat3x4 turn = rotation(normalize(float3{1, 1, 0}), 0.7f);
  const auto placed = place(light, turn);
  int checked = 0;
  EXPECT_EQ(inconsistentSamples(*placed, {0, 0, 0}, checked), 0);
  EXPECT_GT(checked, 4000);
  EXPECT_NEAR(pdfIntegral(*placed, {0, 0, 0}, {0, 0, 1}, 2.f, 2000), 1.0, 5e-3);

  // Importance sampling still integrates the environment.
  const float3 up = transformDirection(turn, {0, 1, 0});
  const float3 forward = transformDirection(turn, {0, 0, -1});
  const float3 normal = normalize(float3{0.2f, 1, 0.4f});
  const double expected =
      integratedIrradiance(*placed, up, forward, normal, width, height);
  EXPECT_NEAR(
      irradiance(*placed, {0, 0, 0}, normal), expected, 1e-2 * expected);
}

// One bright texel in a black image: the filter spreads it over its
// neighbours, where the texel itself is black; sampling finds that light
// too (a density built from the texels alone would have none there and
// fall short by about a quarter).
TEST_F(LightTest, HdriSamplesTheLightItsFilterSpreads)
{
  const uint64_t width = 16, height = 8;
  std::vector<float3> texels(width * height, float3{0, 0, 0});
  texels[5 + 3 * width] = {100, 100, 100};
  light::Hdri light(m_device);
  commitHdri(light, texels, width, height);
  const auto placed = place(light);
  int checked = 0;
  EXPECT_EQ(inconsistentSamples(*placed, {0, 0, 0}, checked), 0);
  for (const float3 normal :
      {float3{0, 0, 1}, normalize(float3{-1, 0.3f, 0.2f})}) {
    const double expected = integratedIrradiance(
        *placed, {0, 0, 1}, {0, 1, 0}, normal, width, height, 32);
    EXPECT_GT(expected, 0.0);
    EXPECT_NEAR(
        irradiance(*placed, {0, 0, 0}, normal), expected, 1e-2 * expected);
  }
}

// A receiver facing one way samples towards its side, and its samples
// agree with radianceAlongFacing(), whose density integrates to one and
// whose estimates integrate the image, on a density far from uniform and
// an image smaller than the cells would be (so cells are texels).
TEST_F(LightTest, HdriSamplesTowardsTheSideAReceiverFaces)
{
  for (const uint64_t width : {uint64_t(48), uint64_t(80)}) {
    const uint64_t height = width / 2;
    const std::vector<float3> texels = gradientWithHotSpot(width, height);
    light::Hdri light(m_device);
    stageHdri(light, texels, width, height, {0, 1, 0}, {0, 0, -1});
    commit(light);
    const mat3x4 turn = rotation(normalize(float3{1, 1, 0}), 0.7f);
    const auto placed = place(light, turn);
    const float3 up = transformDirection(turn, {0, 1, 0});
    const float3 forward = transformDirection(turn, {0, 0, -1});
    for (const float3 normal : {up,
             up * -1.f,
             normalize(float3{0.2f, 1, 0.4f}),
             normalize(float3{-1, 0.3f, -0.5f})}) {
      int checked = 0;
      EXPECT_EQ(inconsistentSamples(*placed, {0, 0, 0}, checked, 64, normal), 0)
          << width;
      EXPECT_GT(checked, 4000);
      EXPECT_NEAR(pdfIntegral(*placed, {0, 0, 0}, {0, 0, 1}, 2.f, 1000, normal),
          1.0,
          5e-3)
          << width;
      const double expected =
          integratedIrradiance(*placed, up, forward, normal, width, height);
      EXPECT_NEAR(irradiance(*placed, {0, 0, 0}, normal, 256, 7, normal),
          expected,
          1e-2 * expected)
          << width;
    }
  }
}

// Under a uniform sky, half of what a receiver samples by the image alone
// lies below its horizon. Facing an axis of the light's frame, only half
// the tenth it still samples by the image does (5 %); facing between
// axes, the axes' lobes reach below too (about 18 % here). With no side
// (a zero normal) it samples as sample() does, and so it does with a NaN
// or infinite normal, and radianceAlongFacing() gives sample()'s pdf.
TEST_F(LightTest, HdriFacingSamplesStayAboveTheHorizon)
{
  const uint64_t width = 64, height = 32;
  std::vector<float3> texels(width * height, float3{1, 1, 1});
  light::Hdri light(m_device);
  commitHdri(light, texels, width, height);
  const auto placed = place(light);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(0.f, kOneMinusEpsilon);
  const std::pair<float3, double> cases[] = {{{0, 0, 1}, 0.06},
      {{1, 0, 0}, 0.06},
      {normalize(float3{1, -2, 0.5f}), 0.2}};
  for (const auto &[normal, mostBelow] : cases) {
    int below = 0, belowFacing = 0, differ = 0;
    const int n = 20000;
    for (int k = 0; k < n; k++) {
      const float2 u{uniform(rng), uniform(rng)};
      below += dot(placed->sample({0, 0, 0}, u).direction, normal) <= 0.f;
      belowFacing +=
          dot(placed->sampleFacing({0, 0, 0}, normal, u).direction, normal)
          <= 0.f;
      const LightSample a = placed->sample({0, 0, 0}, u);
      for (const float3 none : {float3{0, 0, 0},
               float3{std::nanf(""), 0, 1},
               float3{INFINITY, 0, 0},
               float3{1e30f, 1e30f, 0}}) {
        const LightSample b = placed->sampleFacing({0, 0, 0}, none, u);
        float distance = 0.f, pdf = 0.f;
        placed->radianceAlongFacing(
            {0, 0, 0}, none, a.direction, distance, pdf);
        differ += a.pdf != b.pdf || a.direction.x != b.direction.x
                  || a.direction.y != b.direction.y || pdf != a.pdf;
      }
    }
    EXPECT_NEAR(double(below) / n, 0.5, 0.02);
    EXPECT_LT(double(belowFacing) / n, mostBelow) << normal.x << normal.y;
    EXPECT_EQ(differ, 0);
  }
}

// A one-texel image, and a sky black above the horizon (no axis facing
// up has anything to sample): facing receivers still get samples that
// agree with radianceAlongFacing() and integrate the image (and a density
// that integrates to one: not checked on the one texel, whose density
// per steradian is 1 / sin(theta), too steep at the poles for the grid).
TEST_F(LightTest, HdriFacingHandlesTinyAndOneSidedImages)
{
  struct Image
  {
    uint64_t width, height;
    std::vector<float3> texels;
  };
  std::vector<Image> images = {{1, 1, {float3{3, 2, 1}}}, {16, 8, {}}};
  images[1].texels.assign(16 * 8, float3{0, 0, 0});
  for (uint64_t i = 4 * 16; i < 8 * 16; i++)
    images[1].texels[i] = {1.f + float(i % 5), 1, 1}; // the lower half
  for (const Image &image : images) {
    light::Hdri light(m_device);
    commitHdri(light, image.texels, image.width, image.height);
    const auto placed = place(light);
    for (const float3 normal : {float3{0, 0, 1}, float3{0, 0, -1}}) {
      int checked = 0;
      EXPECT_EQ(
          inconsistentSamples(*placed, {0, 0, 0}, checked, 32, normal), 0);
      EXPECT_GT(checked, 500);
      const double expected = integratedIrradiance(*placed,
          {0, 0, 1},
          {0, 1, 0},
          normal,
          image.width,
          image.height,
          512 / int(image.width)); // fine: the horizon's grazing light
      EXPECT_NEAR(irradiance(*placed, {0, 0, 0}, normal, 256, 7, normal),
          expected,
          1e-2 * expected)
          << image.width << " " << normal.z;
      if (image.width > 1) {
        EXPECT_NEAR(
            pdfIntegral(*placed, {0, 0, 0}, {0, 0, 1}, 2.f, 2000, normal),
            1.0,
            5e-3)
            << normal.z;
      }
    }
  }
}

TEST_F(LightTest, HdriMapsTheImageCenterToDirectionAndRowZeroToUp)
{
  const uint64_t width = 8, height = 4;
  std::vector<float3> texels(width * height, float3{0, 0, 0});
  texels[4 + 2 * width] = {7, 7, 7}; // just right of and below the center
  for (uint64_t i = 0; i < width; i++)
    texels[i] = {1, 1, 1};           // row 0
  texels[6 + 2 * width] = {3, 3, 3}; // s = 0.8125: right of the center
  texels[0 + 1 * width] = {8, 8, 8}; // the first and last columns meet
  light::Hdri light(m_device);
  commitHdri(light, texels, width, height);
  float distance, pdf;
  // Image coordinates (s, t) as a direction: theta = pi t from up (+z),
  // phi = 2 pi (s - 0.5) from direction (+y) towards the right, which for
  // a viewer looking along +y with +z up is +x.
  auto towards = [](float s, float t) {
    const float theta = kPi * t, phi = 2.f * kPi * (s - 0.5f);
    return float3{std::sin(phi) * std::sin(theta),
        std::cos(phi) * std::sin(theta),
        std::cos(theta)};
  };
  auto radiance = [&](const PlacedLight &placed, float3 w) {
    return placed.radianceAlong({0, 0, 0}, w, distance, pdf).x;
  };
  // Texel (i, j)'s centre is at ((i + 0.5) / width, (j + 0.5) / height).
  auto centre = [&](uint64_t i, uint64_t j) {
    return towards((i + 0.5f) / width, (j + 0.5f) / height);
  };
  const auto placed = place(light);
  // At a texel's centre the filter gives the texel itself.
  EXPECT_NEAR(radiance(*placed, centre(4, 2)), 7.f, 1e-4f);
  EXPECT_TRUE(std::isinf(distance));
  EXPECT_NEAR(radiance(*placed, centre(6, 2)), 3.f, 1e-4f);
  EXPECT_NEAR(radiance(*placed, centre(2, 0)), 1.f, 1e-4f);
  EXPECT_NEAR(radiance(*placed, centre(1, 2)), 0.f, 1e-4f);
  // Halfway between centres, the mean of the two (bilinear); around `up`
  // the image wraps: column 0 meets column 7.
  EXPECT_NEAR(
      radiance(*placed, towards(4.5f / width, 2.f / height)), 3.5f, 1e-4f);
  EXPECT_NEAR(radiance(*placed, towards(0.f, 1.5f / height)), 4.f, 1e-4f);
  EXPECT_NEAR(radiance(*placed, towards(1.f, 1.5f / height)), 4.f, 1e-4f);
  // Above row 0's centres the first row holds.
  EXPECT_NEAR(radiance(*placed, towards(0.3f, 0.05f / height)), 1.f, 1e-4f);
  // A NaN direction (a degenerate ray) reads some texel, finitely.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(std::isfinite(radiance(*placed, {nan, 0, 1})));
  // An instance rotating a quarter turn about z carries all of it along.
  const auto turned = place(light, rotation({0, 0, 1}, 0.5f * kPi));
  const float3 c = centre(4, 2);
  EXPECT_NEAR(radiance(*turned, {-c.y, c.x, c.z}), 7.f, 1e-4f);
  EXPECT_NEAR(radiance(*turned, {c.y, -c.x, c.z}), 0.f, 1e-4f);
}

// ---------------------------------------------------------------------------
// Placement by instance transforms

TEST_F(LightTest, TransformsMovePositionsAndDirectionsNotIntensity)
{
  const mat3x4 move = rotation(normalize(float3{1, 2, 3}), 1.1f, {4, -2, 7});

  light::Point point(m_device);
  setVec3(point, "position", {1, 0, 0});
  setFloat(point, "intensity", 2.f);
  commit(point);
  const float3 moved = transformPoint(move, {1, 0, 0});
  const LightSample s =
      place(point, move)->sample(moved + float3{0, 0, 2}, {0, 0});
  EXPECT_NEAR(s.distance, 2.f, 1e-5f);
  EXPECT_NEAR(s.radiance.x, 0.5f, 1e-5f);
  // A scaled instance keeps the intensity: still I / d^2 from the new spot.
  const mat3x4 grow = scaling(3.f, {1, 1, 1});
  const LightSample g = place(point, grow)->sample({4, 1, 3}, {0, 0});
  EXPECT_NEAR(g.distance, 2.f, 1e-5f);
  EXPECT_NEAR(g.radiance.x, 0.5f, 1e-5f);

  light::Directional directional(m_device);
  setVec3(directional, "direction", {0, 0, -1});
  commit(directional);
  const LightSample d = place(directional, move)->sample({0, 0, 0}, {0, 0});
  const float3 expected = -transformDirection(move, {0, 0, -1});
  EXPECT_NEAR(dot(d.direction, expected), 1.f, 1e-6f);

  light::Spot spot(m_device);
  setVec3(spot, "direction", {0, 0, -1});
  setFloat(spot, "openingAngle", 0.5f);
  commit(spot);
  const auto placedSpot = place(spot, move);
  const float3 origin = transformPoint(move, {0, 0, 0});
  const float3 axis = transformDirection(move, {0, 0, -1});
  EXPECT_NEAR(
      placedSpot->sample(origin + axis * 2.f, {0, 0}).radiance.x, 0.25f, 1e-5f);
  EXPECT_EQ(placedSpot->sample(origin - axis * 2.f, {0, 0}).radiance.x, 0.f);

  // A moved quad against Lambert's formula at its moved corners.
  const float3 corner{-1.f, -0.5f, 2.f}, edge1{2, 0, 0}, edge2{0, 1, 0};
  light::Quad quad(m_device);
  setVec3(quad, "position", corner);
  setVec3(quad, "edge1", edge1);
  setVec3(quad, "edge2", edge2);
  setFloat(quad, "radiance", 1.5f);
  commit(quad);
  std::vector<float3> corners;
  for (float3 p :
      {corner, corner + edge1, corner + edge1 + edge2, corner + edge2})
    corners.push_back(transformPoint(move, p));
  const float3 receiver = transformPoint(move, {0.2f, 0.1f, 0.5f});
  const float3 normal = transformDirection(move, {0, 0, 1});
  const double expectedE = polygonIrradiance(corners, receiver, normal, 1.5);
  EXPECT_NEAR(irradiance(*place(quad, move), receiver, normal),
      expectedE,
      1e-2 * expectedE);
  // Scaled: intensity given stays the intensity; the radiance drops with
  // the grown area.
  setFloat(quad, "intensity", 4.f);
  commit(quad);
  float distance, pdf;
  const auto big = place(quad, scaling(2.f));
  EXPECT_NEAR(big->radianceAlong({0, 0, 0}, {0, 0, 1}, distance, pdf).x,
      4.f / 8.f,
      1e-6f);
  EXPECT_NEAR(distance, 4.f, 1e-5f);
}

// ---------------------------------------------------------------------------
// Invalid input: reported, invalid, never placed, never a crash

TEST_F(LightTest, HdriWithoutImageIsInvalid)
{
  light::Hdri light(m_device);
  commit(light);
  EXPECT_FALSE(light.isValid());
  EXPECT_TRUE(reported({"hdri", "'radiance'", "not set"}));
  EXPECT_EQ(light.place(kIdentityMat3x4), nullptr);

  const float values[4] = {1, 2, 3, 4};
  light::Hdri wrongType(m_device);
  setArray(wrongType, "radiance", array(ANARI_FLOAT32, values, 2, 2));
  commit(wrongType);
  EXPECT_FALSE(wrongType.isValid());
  EXPECT_TRUE(reported({"'radiance'", "ANARI_FLOAT32"}));
}

TEST_F(LightTest, HdriNegativeTexelsAreReportedAndZeroed)
{
  const float3 texels[2] = {{1, -1, 1}, {2, 2, 2}};
  light::Hdri light(m_device);
  setArray(light, "radiance", array(ANARI_FLOAT32_VEC3, texels, 2, 1));
  commit(light);
  EXPECT_TRUE(light.isValid());
  EXPECT_TRUE(reported({"'radiance'", "negative"}));
  float distance, pdf;
  // Texel 0 (s < 0.5) is left of the center (+x) for a viewer with +z up:
  // +y.
  EXPECT_EQ(
      place(light)->radianceAlong({0, 0, 0}, {0, 1, 0}, distance, pdf).y, 0.f);
  EXPECT_EQ(
      place(light)->radianceAlong({0, 0, 0}, {0, 1, 0}, distance, pdf).x, 1.f);

  // A finite texel the scale takes past the largest float: the same.
  const float3 huge[2] = {{3e38f, 1, 1}, {2, 2, 2}};
  light::Hdri scaled(m_device);
  setArray(scaled, "radiance", array(ANARI_FLOAT32_VEC3, huge, 2, 1));
  setFloat(scaled, "scale", 10.f);
  commit(scaled);
  EXPECT_TRUE(reported({"'radiance'", "non-finite"}));
  const auto placed = place(scaled);
  for (const float3 w : {float3{0, 1, 0}, float3{0, -1, 0}, float3{1, 0, 0}}) {
    const float3 r = placed->radianceAlong({0, 0, 0}, w, distance, pdf);
    EXPECT_TRUE(std::isfinite(r.x) && std::isfinite(pdf));
  }
}

TEST_F(LightTest, QuadWithDegenerateEdgesIsInvalid)
{
  light::Quad zero(m_device);
  setVec3(zero, "edge1", {0, 0, 0});
  commit(zero);
  EXPECT_FALSE(zero.isValid());
  EXPECT_TRUE(reported({"quad", "non-zero length"}));
  EXPECT_EQ(zero.place(kIdentityMat3x4), nullptr);

  light::Quad parallel(m_device);
  setVec3(parallel, "edge1", {1, 1, 0});
  setVec3(parallel, "edge2", {2, 2, 0});
  commit(parallel);
  EXPECT_FALSE(parallel.isValid());
  EXPECT_TRUE(reported({"parallel"}));

  // Recovers when fixed.
  setVec3(parallel, "edge2", {0, 0, 1});
  commit(parallel);
  EXPECT_TRUE(parallel.isValid());
}

TEST_F(LightTest, NegativeValuesAreInvalid)
{
  light::Point point(m_device);
  setFloat(point, "intensity", -1.f);
  commit(point);
  EXPECT_FALSE(point.isValid());
  EXPECT_TRUE(reported({"point", "'intensity'", ">= 0"}));

  light::Point radius(m_device);
  setFloat(radius, "radius", -0.1f);
  commit(radius);
  EXPECT_FALSE(radius.isValid());

  light::Spot spot(m_device);
  setFloat(spot, "openingAngle", -1.f);
  commit(spot);
  EXPECT_FALSE(spot.isValid());
  EXPECT_TRUE(reported({"spot", "'openingAngle'"}));

  light::Directional directional(m_device);
  setFloat(directional, "irradiance", -2.f);
  commit(directional);
  EXPECT_FALSE(directional.isValid());

  light::Hdri hdri(m_device);
  const float3 texel{1, 1, 1};
  setArray(hdri, "radiance", array(ANARI_FLOAT32_VEC3, &texel, 1, 1));
  setFloat(hdri, "scale", -1.f);
  commit(hdri);
  EXPECT_FALSE(hdri.isValid());

  light::Quad color(m_device);
  setVec3(color, "color", {1, -0.5f, 1});
  commit(color);
  EXPECT_FALSE(color.isValid());
  EXPECT_TRUE(reported({"'color'"}));

  light::Quad power(m_device);
  setFloat(power, "power", -3.f);
  commit(power);
  EXPECT_FALSE(power.isValid());
  EXPECT_TRUE(reported({"'power'"}));
}

TEST_F(LightTest, InvalidGeometryAndDirectionsAreReported)
{
  light::Directional directional(m_device);
  setVec3(directional, "direction", {0, 0, 0});
  commit(directional);
  EXPECT_FALSE(directional.isValid());
  EXPECT_TRUE(reported({"directional", "'direction'"}));

  light::Ring ring(m_device);
  setFloat(ring, "radius", 1.f);
  setFloat(ring, "innerRadius", 1.5f);
  commit(ring);
  EXPECT_FALSE(ring.isValid());
  EXPECT_TRUE(reported({"ring", "'innerRadius'"}));
  EXPECT_EQ(ring.place(kIdentityMat3x4), nullptr);

  light::Point nan(m_device);
  setVec3(nan, "position", {0, std::nanf(""), 0});
  commit(nan);
  EXPECT_FALSE(nan.isValid());
}

TEST_F(LightTest, UnusableIntensityDistributionsAreInvalid)
{
  const float one = 1.f;
  light::Quad single(m_device);
  setArray(single, "intensityDistribution", array(ANARI_FLOAT32, &one, 1));
  commit(single);
  EXPECT_FALSE(single.isValid());
  EXPECT_TRUE(reported({"'intensityDistribution'", "two values"}));

  const float negative[3] = {1.f, -1.f, 0.5f};
  light::Ring ring(m_device);
  setArray(ring, "intensityDistribution", array(ANARI_FLOAT32, negative, 3));
  commit(ring);
  EXPECT_FALSE(ring.isValid());
  EXPECT_TRUE(reported({"ring", "negative"}));

  const int32_t integers[2] = {1, 2};
  light::Quad wrongType(m_device);
  setArray(wrongType, "intensityDistribution", array(ANARI_INT32, integers, 2));
  commit(wrongType);
  EXPECT_FALSE(wrongType.isValid());
  EXPECT_TRUE(reported({"'intensityDistribution'", "ANARI_INT32"}));
}

TEST_F(LightTest, ParametersOfTheWrongTypeAreIgnoredWithAWarning)
{
  light::Point light(m_device);
  set(light, "intensity", ANARI_FLOAT64, 5.0);
  setFloat(light, "power", 4.f * kPi);
  commit(light);
  EXPECT_TRUE(light.isValid());
  EXPECT_TRUE(reported({"'intensity'", "ANARI_FLOAT64"}));
  // The ignored intensity does not count as set: power is used.
  EXPECT_NEAR(light.intensity(), 1.f, 1e-6f);
}

// ---------------------------------------------------------------------------
// Sampling building blocks

TEST_F(LightTest, Distribution2DSamplesItsOwnDensity)
{
  const float weights[6] = {1, 0, 3, 2, 0.5f, 0};
  const light::Distribution2D distribution(weights, 3, 2);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(0.f, kOneMinusEpsilon);
  for (int k = 0; k < 1000; k++) {
    float pdf = 0.f;
    const float2 p = distribution.sample({uniform(rng), uniform(rng)}, pdf);
    EXPECT_GT(pdf, 0.f);
    EXPECT_NEAR(distribution.pdf(p), pdf, 1e-5f * pdf);
  }
  // Cells of weight w hold density w / mean(weights) = w * 6 / 6.5.
  EXPECT_NEAR(distribution.pdf({0.5f, 0.75f}), 0.5f * 6.f / 6.5f, 1e-6f);
  EXPECT_EQ(distribution.pdf({0.5f, 0.25f}), 0.f);
}

TEST_F(LightTest, SphericalTriangleSamplesAreUniform)
{
  // An octant: solid angle pi / 2, and by symmetry each coordinate of a
  // uniform direction in it has mean 1/2 (the centroid of the octant).
  const double3 a{1, 0, 0}, b{0, 1, 0}, c{0, 0, 1};
  const double area = light::sphericalTriangleArea(a, b, c);
  EXPECT_NEAR(area, kPiD / 2, 1e-12);
  const int n = 200;
  double3 mean{0, 0, 0};
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      const double3 w = light::sampleSphericalTriangle(
          a, b, c, area, {(i + 0.5f) / n, (j + 0.5f) / n});
      EXPECT_NEAR(length(w), 1.0, 1e-9);
      EXPECT_GE(minComponent(w), -1e-9);
      mean = mean + w;
    }
  }
  mean = mean / double(n * n);
  EXPECT_NEAR(mean.x, 0.5, 1e-3);
  EXPECT_NEAR(mean.y, 0.5, 1e-3);
  EXPECT_NEAR(mean.z, 0.5, 1e-3);
}

} // namespace
} // namespace prism
