// transferFunction1D volumes with known answers: a homogeneous slab lets
// exp(-sigma d) of the light behind through (raycast and path tracer, in
// world space under instance transforms), its emission is 1 - exp(-sigma d),
// shadows through it dim a lit plane by the same factor, the path tracer
// converges to the reference marcher at a tenth of its step, and bad
// volumes are reported without harming the frame.
#include "AnalyticScene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace {

const float kEye[3] = {0.5f, 0.5f, 5.f};
const float kDown[3] = {0.f, 0.f, -1.f};

class VolumeTest : public AnalyticTest
{
 protected:
  // A structuredRegular field over [0, 1] x [0, 1] x [0, depth] with
  // nx x ny x nz samples, value(x, y, z) at each.
  ANARISpatialField field(uint32_t nx,
      uint32_t ny,
      uint32_t nz,
      float depth,
      const std::function<float(float, float, float)> &value)
  {
    ANARIArray3D data = anariNewArray3D(
        m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32, nx, ny, nz);
    auto *v = (float *)anariMapArray(m_device, data);
    const float sx = 1.f / float(nx - 1), sy = 1.f / float(ny - 1),
                sz = depth / float(nz - 1);
    for (uint32_t z = 0; z < nz; z++)
      for (uint32_t y = 0; y < ny; y++)
        for (uint32_t x = 0; x < nx; x++)
          v[(size_t(z) * ny + y) * nx + x] =
              value(float(x) * sx, float(y) * sy, float(z) * sz);
    anariUnmapArray(m_device, data);
    ANARISpatialField f = anariNewSpatialField(m_device, "structuredRegular");
    const float spacing[3] = {sx, sy, sz};
    anariSetParameter(m_device, f, "data", ANARI_ARRAY3D, &data);
    anariSetParameter(m_device, f, "spacing", ANARI_FLOAT32_VEC3, spacing);
    anariRelease(m_device, data);
    anariCommitParameters(m_device, f);
    return f;
  }
  // A transferFunction1D volume of `f` (released): values [0, 1] map to
  // `color` and opacities from `opacities` (evenly over the range).
  ANARIVolume volume(ANARISpatialField f,
      const float color[3],
      const std::vector<float> &opacities,
      float unitDistance = 1.f,
      uint32_t id = ~0u)
  {
    ANARIVolume v = anariNewVolume(m_device, "transferFunction1D");
    anariSetParameter(m_device, v, "value", ANARI_SPATIAL_FIELD, &f);
    anariRelease(m_device, f);
    anariSetParameter(m_device, v, "color", ANARI_FLOAT32_VEC3, color);
    if (opacities.size() == 1) {
      anariSetParameter(m_device, v, "opacity", ANARI_FLOAT32, &opacities[0]);
    } else {
      ANARIArray1D o = array1D(opacities, ANARI_FLOAT32);
      anariSetParameter(m_device, v, "opacity", ANARI_ARRAY1D, &o);
      anariRelease(m_device, o);
    }
    anariSetParameter(
        m_device, v, "unitDistance", ANARI_FLOAT32, &unitDistance);
    if (id != ~0u)
      anariSetParameter(m_device, v, "id", ANARI_UINT32, &id);
    anariCommitParameters(m_device, v);
    return v;
  }
  // A world of `v` (released), optionally in an instance with `transform`
  // (column-major 3x4), and of `surfaces` (released).
  ANARIWorld volumeWorld(ANARIVolume v,
      const float *transform = nullptr,
      const std::vector<ANARISurface> &surfaces = {})
  {
    ANARIWorld w = world(surfaces);
    ANARIArray1D volumes =
        anariNewArray1D(m_device, &v, nullptr, nullptr, ANARI_VOLUME, 1);
    if (!transform) {
      setArray(w, "volume", volumes);
    } else {
      ANARIGroup g = anariNewGroup(m_device);
      setArray(g, "volume", volumes);
      anariCommitParameters(m_device, g);
      ANARIInstance i = anariNewInstance(m_device, "transform");
      anariSetParameter(m_device, i, "group", ANARI_GROUP, &g);
      anariSetParameter(
          m_device, i, "transform", ANARI_FLOAT32_MAT4, transform);
      anariCommitParameters(m_device, i);
      anariRelease(m_device, g);
      setArray(w,
          "instance",
          anariNewArray1D(m_device, &i, nullptr, nullptr, ANARI_INSTANCE, 1));
      anariRelease(m_device, i);
    }
    anariRelease(m_device, v);
    anariCommitParameters(m_device, w);
    return w;
  }
  ANARIRenderer withBackground(const char *subtype, const float rgba[4])
  {
    ANARIRenderer r = anariNewRenderer(m_device, subtype);
    anariSetParameter(m_device, r, "background", ANARI_FLOAT32_VEC4, rgba);
    anariCommitParameters(m_device, r);
    return r;
  }
  // The mean red of the size x size image's central half.
  static float centralMean(const std::vector<float> &color, uint32_t size)
  {
    double sum = 0.0;
    int n = 0;
    for (uint32_t y = size / 4; y < 3 * size / 4; y++)
      for (uint32_t x = size / 4; x < 3 * size / 4; x++, n++)
        sum += color[4 * (size_t(y) * size + x)];
    return float(sum / n);
  }
};

// A constant field, opacity 0.5 per unit distance: sigma = ln 2.
auto constant = [](float, float, float) {
  return 1.f;
};

TEST_F(VolumeTest, HomogeneousSlabTransmitsAndEmitsExactly)
{
  // A black slab before a white background shows its transmittance
  // exp(-sigma d); a white slab before black, its emission 1 - that.
  const float depth = 2.f;
  const float transmittance = std::exp(-std::log(2.f) * depth); // 0.25
  struct Case
  {
    float volumeColor, background, expected;
  };
  for (const Case &test :
      {Case{0.f, 1.f, transmittance}, Case{1.f, 0.f, 1.f - transmittance}}) {
    for (const char *subtype : {"raycast", "pathtracer"}) {
      const float color[3] = {
          test.volumeColor, test.volumeColor, test.volumeColor};
      const float background[4] = {
          test.background, test.background, test.background, 1.f};
      ANARIWorld w =
          volumeWorld(volume(field(3, 3, 5, depth, constant), color, {0.5f}));
      ANARICamera c = orthographic(kEye, kDown, 0.5f);
      ANARIRenderer r = withBackground(subtype, background);
      // Raycast: exact (a constant field). Path tracer: 128 frames of
      // 32 x 32 central pixels, each a 0/1 estimate, leave a standard
      // error of 0.5 % of the expectation: 2 % is four of them.
      const bool traced = std::string(subtype) == "pathtracer";
      const float mean =
          centralMean(accumulatedColor(w, c, r, 64, traced ? 128 : 1), 64);
      EXPECT_NEAR(
          mean, test.expected, (traced ? 0.02f : 0.001f) * test.expected)
          << subtype << " background " << test.background;
      for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
        anariRelease(m_device, o);
    }
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(VolumeTest, InstanceScaleStretchesTheWorldSpacePath)
{
  // Scaled by 2 along z: the slab is 4 deep in world space, where the
  // spec's unitDistance is measured.
  const float black[3] = {0, 0, 0}, white[4] = {1, 1, 1, 1};
  const float scale[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, 0, 0, 0, -2, 1};
  const float expected = std::exp(-std::log(2.f) * 4.f);
  ANARIWorld w =
      volumeWorld(volume(field(3, 3, 5, 2.f, constant), black, {0.5f}), scale);
  ANARICamera c = orthographic(kEye, kDown, 0.5f);
  ANARIRenderer r = withBackground("raycast", white);
  const float mean = centralMean(accumulatedColor(w, c, r, 16, 1), 16);
  EXPECT_NEAR(mean, expected, 0.01f * expected);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(VolumeTest, DepthAndObjectIdComeFromTheFirstSampleWithOpacity)
{
  // Opacity only where z >= 1, and the eye at z = 5 looks down into the
  // slab's top at z = 2: the first sample with opacity lies within a step
  // of the top, at depth 3.
  const float white[3] = {1, 1, 1}, black[4] = {0, 0, 0, 1};
  auto upperHalf = [](float, float, float z) {
    return z >= 1.f ? 1.f : 0.f;
  };
  ANARIWorld w = volumeWorld(
      volume(field(3, 3, 9, 2.f, upperHalf), white, {0.f, 0.9f}, 1.f, 42));
  ANARICamera c = orthographic(kEye, kDown, 0.5f);
  ANARIRenderer r = withBackground("raycast", black);
  const RenderedImage image = render(w, c, r, 8, 8);
  const float step = 0.25f; // the field's spacing along z
  EXPECT_GE(image.depthAt(4, 4), 3.f - 1e-4f);
  EXPECT_LE(image.depthAt(4, 4), 3.f + step);
  EXPECT_EQ(image.objectId[4 * 8 + 4], 42u);
  EXPECT_GT(image.pixel(4, 4)[0], 0.5f);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

// The ray-marching renderers' depth (raycast; debug in its id views) is
// where the first step with opacity begins: a slab of unit cells entered at
// distance 3.0 reads 3.0 (as helide's does; float rounding only), not the first
// sample's midpoint half a step further in (3.5 at the volume's unit step).
TEST_F(VolumeTest, DepthIsWhereTheSlabIsEntered)
{
  const float white[3] = {1, 1, 1}, black[4] = {0, 0, 0, 1};
  auto constant = [](float, float, float) {
    return 1.f;
  };
  for (const char *subtype : {"raycast", "debug"}) {
    // Unit cells over [0, 1]^2 x [0, 2], the eye at z = 5.
    ANARIWorld w =
        volumeWorld(volume(field(2, 2, 3, 2.f, constant), white, {0.5f}));
    ANARICamera c = orthographic(kEye, kDown, 0.5f);
    ANARIRenderer r = withBackground(subtype, black);
    if (std::string(subtype) == "debug") {
      // The debug renderer marches volumes in its id views.
      anariSetParameter(m_device, r, "mode", ANARI_STRING, "objectId");
      anariCommitParameters(m_device, r);
    }
    const RenderedImage image = render(w, c, r, 8, 8);
    EXPECT_NEAR(image.depthAt(4, 4), 3.f, 1e-4f) << subtype;
    for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
  }
  EXPECT_TRUE(problems().empty());
}

// The ANARI-SDK's volumeSampleRateFactor (EXP_VOLUME_SAMPLE_RATE) is the
// raycast renderer's volumeSamplingRate under another name. A black slab
// whose opacity is 0 up to value 0.5 and rises to 1 at value 1, over
// values falling linearly from 1 at its top (z = 2) to 0 at z = 1: one
// step per unit cell samples value 0.5 there and lets the white
// background through; four per cell sample the opaque part.
TEST_F(VolumeTest, SdkSampleRateFactorIsTheSamplingRate)
{
  const float black[3] = {0, 0, 0}, white[4] = {1, 1, 1, 1};
  auto top = [](float, float, float z) {
    return std::max(0.f, z - 1.f);
  };
  ANARIWorld w =
      volumeWorld(volume(field(2, 2, 3, 2.f, top), black, {0.f, 0.f, 1.f}));
  ANARICamera c = orthographic(kEye, kDown, 0.5f);
  auto centre = [&](const char *name, float rate) {
    ANARIRenderer r = withBackground("raycast", white);
    if (name) {
      anariSetParameter(m_device, r, name, ANARI_FLOAT32, &rate);
      anariCommitParameters(m_device, r);
    }
    const float value = render(w, c, r, 8, 8).pixel(4, 4)[0];
    anariRelease(m_device, r);
    return value;
  };
  const float coarse = centre(nullptr, 1.f);
  const float fine = centre("volumeSamplingRate", 4.f);
  EXPECT_FLOAT_EQ(coarse, 1.f);
  EXPECT_LT(fine, 0.9f);
  EXPECT_EQ(centre("volumeSampleRateFactor", 4.f), fine);
  EXPECT_EQ(centre("volumeSampleRateFactor", 1.f), coarse);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(VolumeTest, PathTracerConvergesToTheReferenceMarcher)
{
  // A heterogeneous blob: density falling off from the centre, coloured
  // by value. The marcher at a tenth of the default step is the
  // reference.
  auto blob = [](float x, float y, float z) {
    const float dx = x - 0.5f, dy = y - 0.5f, dz = z - 0.5f;
    return std::max(0.f, 1.f - 2.f * std::sqrt(dx * dx + dy * dy + dz * dz));
  };
  const float black[4] = {0, 0, 0, 1};
  auto makeWorld = [&] {
    ANARIVolume v = anariNewVolume(m_device, "transferFunction1D");
    ANARISpatialField f = field(17, 17, 17, 1.f, blob);
    anariSetParameter(m_device, v, "value", ANARI_SPATIAL_FIELD, &f);
    anariRelease(m_device, f);
    ANARIArray1D colors = array1D(
        std::vector<float>{0, 0, 1, 0, 1, 0, 1, 0, 0}, ANARI_FLOAT32_VEC3);
    anariSetParameter(m_device, v, "color", ANARI_ARRAY1D, &colors);
    anariRelease(m_device, colors);
    ANARIArray1D opacities =
        array1D(std::vector<float>{0.f, 0.3f, 0.6f, 0.9f}, ANARI_FLOAT32);
    anariSetParameter(m_device, v, "opacity", ANARI_ARRAY1D, &opacities);
    anariRelease(m_device, opacities);
    const float unitDistance = 0.2f;
    anariSetParameter(
        m_device, v, "unitDistance", ANARI_FLOAT32, &unitDistance);
    anariCommitParameters(m_device, v);
    return volumeWorld(v);
  };
  const float eye[3] = {0.5f, 0.5f, 3.f};
  const uint32_t size = 16;
  ANARIWorld w = makeWorld();
  ANARICamera c = orthographic(eye, kDown, 1.f);
  ANARIRenderer reference = withBackground("raycast", black);
  const float fine = 10.f;
  anariSetParameter(
      m_device, reference, "volumeSamplingRate", ANARI_FLOAT32, &fine);
  anariCommitParameters(m_device, reference);
  ANARIRenderer traced = withBackground("pathtracer", black);
  const std::vector<float> expected =
      accumulatedColor(w, c, reference, size, 4);
  const std::vector<float> image = accumulatedColor(w, c, traced, size, 1024);
  // Per pixel: 1024 paths of a bounded estimator (each 0 or a colour <= 1)
  // leave a standard error of at most 1/64; the image mean is far tighter.
  double sumExpected = 0.0, sumImage = 0.0, worst = 0.0;
  for (size_t i = 0; i < expected.size(); i++) {
    if (i % 4 == 3)
      continue;
    sumExpected += expected[i];
    sumImage += image[i];
    worst = std::max(worst, double(std::abs(image[i] - expected[i])));
  }
  EXPECT_GT(sumExpected, 10.0); // the blob is visible
  EXPECT_NEAR(sumImage / sumExpected, 1.0, 0.01);
  EXPECT_LT(worst, 4.0 / 64.0);
  for (ANARIObject o : {(ANARIObject)w,
           (ANARIObject)c,
           (ANARIObject)reference,
           (ANARIObject)traced})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(VolumeTest, ShadowThroughASlabDimsTheLitPlane)
{
  // A directional light straight down through a black slab of depth 2
  // onto a matte plane: the plane's radiance is rho E / pi times the
  // slab's transmittance (the camera sees the plane beside the slab).
  const float rho = 0.5f, E = 2.f;
  const float black[3] = {0, 0, 0}, background[4] = {0, 0, 0, 1};
  ANARIGeometry g =
      geometry("quad", {-50, -50, -1, 50, -50, -1, 50, 50, -1, -50, 50, -1});
  ANARIWorld w =
      volumeWorld(volume(field(3, 3, 5, 2.f, constant), black, {0.5f}),
          nullptr,
          {surface(g, matte(rho, rho, rho))});
  ANARILight light = anariNewLight(m_device, "directional");
  anariSetParameter(m_device, light, "direction", ANARI_FLOAT32_VEC3, kDown);
  anariSetParameter(m_device, light, "irradiance", ANARI_FLOAT32, &E);
  setOnlyLight(w, light);
  // Looking down at a slant from beside the slab, at the plane below it.
  ANARIRenderer r = withBackground("pathtracer", background);
  const int one = 1;
  anariSetParameter(m_device, r, "maxPathLength", ANARI_INT32, &one);
  anariCommitParameters(m_device, r);
  const float eye[3] = {0.5f, 0.5f, -0.5f};
  ANARICamera c = orthographic(eye, kDown, 0.5f);
  // 128 frames of 16 x 16 central pixels, each ratio tracking's 0/1
  // estimate here: a standard error of 1 % of the expectation.
  const float mean = centralMean(accumulatedColor(w, c, r, 32, 128), 32);
  const float expected = rho * E / float(M_PI) * 0.25f;
  EXPECT_NEAR(mean, expected, 0.04f * expected);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(VolumeTest, ExtremeScalesFinishWithFinitePixels)
{
  // A volume 1e30 deep seen from beyond it, and one whose unitDistance
  // of 1e-30 makes its extinction ~1e31 (steps and tentative collisions
  // that would not advance a float distance): every renderer finishes and
  // every pixel is finite.
  const float white[3] = {1, 1, 1}, background[4] = {0.2f, 0.2f, 0.2f, 1};
  struct Case
  {
    float depth, unitDistance, eyeHeight;
  };
  for (const Case &test : {Case{1e30f, 1.f, 2e30f}, Case{2.f, 1e-30f, 5.f}}) {
    ANARIWorld w = volumeWorld(volume(field(3, 3, 3, test.depth, constant),
        white,
        {0.5f},
        test.unitDistance));
    const float eye[3] = {0.5f, 0.5f, test.eyeHeight};
    ANARICamera c = orthographic(eye, kDown, 0.5f);
    for (const char *subtype : {"raycast", "pathtracer", "ao", "debug"}) {
      ANARIRenderer r = withBackground(subtype, background);
      const std::vector<float> image = accumulatedColor(w, c, r, 4, 2);
      ASSERT_EQ(image.size(), 4u * 4u * 4u) << subtype;
      for (float v : image)
        ASSERT_TRUE(std::isfinite(v)) << subtype;
      anariRelease(m_device, r);
    }
    anariRelease(m_device, w);
    anariRelease(m_device, c);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(VolumeTest, ValueRangeNarrowerThanItsReciprocalStillSortsValues)
{
  // valueRange [0, 1e-44]: 1 / 1e-44 overflows a float (and 0 * inf is
  // NaN). Values of 0 sit at the range's start (opacity 0: the slab is
  // clear); values of 1 lie above it and take the last opacity (0.5 per
  // unit: the slab of depth 2 transmits 0.25).
  const float black[3] = {0, 0, 0}, white[4] = {1, 1, 1, 1};
  for (const float value : {0.f, 1.f}) {
    ANARIVolume v =
        volume(field(3, 3, 5, 2.f, [&](float, float, float) { return value; }),
            black,
            {0.f, 0.f, 0.5f});
    const float range[2] = {0.f, 1e-44f};
    anariSetParameter(m_device, v, "valueRange", ANARI_FLOAT32_BOX1, range);
    anariCommitParameters(m_device, v);
    ANARIWorld w = volumeWorld(v);
    ANARICamera c = orthographic(kEye, kDown, 0.5f);
    for (const char *subtype : {"raycast", "pathtracer"}) {
      ANARIRenderer r = withBackground(subtype, white);
      EXPECT_NEAR(centralMean(accumulatedColor(w, c, r, 8, 1), 8),
          value == 0.f ? 1.f : 0.25f,
          value == 0.f ? 1e-6f : 0.2f)
          << subtype << " value " << value;
      anariRelease(m_device, r);
    }
    anariRelease(m_device, w);
    anariRelease(m_device, c);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(VolumeTest, ColorAlphaScalesOpacityAndInvisibleVolumesAreSkipped)
{
  // A FLOAT32_VEC4 colour's alpha multiplies the opacity (spec 5.12.1):
  // alpha 0.5 and opacity 1 absorb half per unit, so a slab of depth 2
  // transmits 0.25; with visible false the slab is not drawn at all.
  const float white[4] = {1, 1, 1, 1};
  const float halfBlack[4] = {0, 0, 0, 0.5f};
  ANARICamera c = orthographic(kEye, kDown, 0.5f);
  ANARIRenderer r = withBackground("raycast", white);
  for (const bool visible : {true, false}) {
    ANARIVolume v = anariNewVolume(m_device, "transferFunction1D");
    ANARISpatialField f = field(3, 3, 5, 2.f, constant);
    anariSetParameter(m_device, v, "value", ANARI_SPATIAL_FIELD, &f);
    anariRelease(m_device, f);
    anariSetParameter(m_device, v, "color", ANARI_FLOAT32_VEC4, halfBlack);
    anariSetParameter(m_device, v, "visible", ANARI_BOOL, &visible);
    anariCommitParameters(m_device, v);
    ANARIWorld w = volumeWorld(v);
    EXPECT_NEAR(centralMean(accumulatedColor(w, c, r, 8, 1), 8),
        visible ? 0.25f : 1.f,
        1e-3f)
        << "visible " << visible;
    anariRelease(m_device, w);
  }
  for (ANARIObject o : {(ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(VolumeTest, BadVolumesAreReportedAndSkipped)
{
  // Commits apply when a frame starts: each case renders once.
  const float white[4] = {1, 1, 1, 1};
  ANARICamera c = orthographic(kEye, kDown, 0.5f);
  ANARIRenderer r = withBackground("raycast", white);
  auto meanOf = [&](ANARIWorld w) {
    return centralMean(accumulatedColor(w, c, r, 8, 1), 8);
  };
  // No field at all: reported, and the volume is not drawn.
  ANARIVolume empty = anariNewVolume(m_device, "transferFunction1D");
  anariCommitParameters(m_device, empty);
  ANARIWorld w = volumeWorld(empty);
  EXPECT_FLOAT_EQ(meanOf(w), 1.f);
  EXPECT_TRUE(
      reported(ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_ARGUMENT, "'value'"));
  anariRelease(m_device, w);
  // A valueRange of the wrong type is warned about and [0, 1] used; a
  // FLOAT64_BOX1 one is read.
  const float black[3] = {0, 0, 0};
  ANARIVolume v = volume(field(3, 3, 3, 1.f, constant), black, {0.5f});
  anariRetain(m_device, v);
  const int wrong = 3;
  anariSetParameter(m_device, v, "valueRange", ANARI_INT32, &wrong);
  anariCommitParameters(m_device, v);
  w = volumeWorld(v);
  EXPECT_NEAR(meanOf(w), 0.5f, 1e-3f); // opacity 0.5 over unit depth
  EXPECT_TRUE(reported(
      ANARI_SEVERITY_WARNING, ANARI_STATUS_INVALID_ARGUMENT, "valueRange"));
  // Values 1 in [0, 4]: a quarter up a constant opacity table, the same.
  const double range[2] = {0.0, 4.0};
  anariSetParameter(m_device, v, "valueRange", ANARI_FLOAT64_BOX1, range);
  anariCommitParameters(m_device, v);
  EXPECT_NEAR(meanOf(w), 0.5f, 1e-3f);
  EXPECT_TRUE(problems().empty());
  anariRelease(m_device, v);
  anariRelease(m_device, w);
  // An unknown volume subtype is reported, not fatal.
  ANARIVolume unknown = anariNewVolume(m_device, "noSuchVolume");
  EXPECT_FALSE(problems().empty());
  anariRelease(m_device, unknown);
  for (ANARIObject o : {(ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
}

} // namespace
