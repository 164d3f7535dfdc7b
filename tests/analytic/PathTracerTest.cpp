// The path tracer against analytic answers: a white furnace (a sphere of
// albedo 1 under uniform radiance L disappears), a Lambert plane under a
// directional light (rho E / pi) and under a point light (inverse square).
#include "AnalyticScene.h"

#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <string>

namespace {

const float kEye[3] = {0, 0, 5};
const float kDown[3] = {0, 0, -1};

struct float3Mean
{
  float r{0}, g{0}, b{0};
  int pixels{0};
};

class PathTracerTest : public AnalyticTest
{
 protected:
  ANARIRenderer pathTracer(float ambientRadiance, const float background[4])
  {
    ANARIRenderer r = anariNewRenderer(m_device, "pathtracer");
    anariSetParameter(
        m_device, r, "background", ANARI_FLOAT32_VEC4, background);
    anariSetParameter(
        m_device, r, "ambientRadiance", ANARI_FLOAT32, &ambientRadiance);
    const int32_t depth = 64;
    anariSetParameter(m_device, r, "maxPathLength", ANARI_INT32, &depth);
    anariCommitParameters(m_device, r);
    return r;
  }
  // Mean color over the pixels whose depth is finite, accumulated.
  float3Mean meanOverHits(
      ANARIWorld w, ANARICamera c, ANARIRenderer r, uint32_t size, int frames)
  {
    ANARIFrame f = anariNewFrame(m_device);
    const uint32_t extent[2] = {size, size};
    const ANARIDataType color = ANARI_FLOAT32_VEC4, depth = ANARI_FLOAT32;
    const uint8_t on = 1;
    anariSetParameter(m_device, f, "world", ANARI_WORLD, &w);
    anariSetParameter(m_device, f, "camera", ANARI_CAMERA, &c);
    anariSetParameter(m_device, f, "renderer", ANARI_RENDERER, &r);
    anariSetParameter(m_device, f, "size", ANARI_UINT32_VEC2, extent);
    anariSetParameter(m_device, f, "channel.color", ANARI_DATA_TYPE, &color);
    anariSetParameter(m_device, f, "channel.depth", ANARI_DATA_TYPE, &depth);
    anariSetParameter(m_device, f, "accumulation", ANARI_BOOL, &on);
    anariCommitParameters(m_device, f);
    for (int i = 0; i < frames; i++)
      anariRenderFrame(m_device, f);
    anariFrameReady(m_device, f, ANARI_WAIT);
    uint32_t width, height;
    ANARIDataType type;
    auto *p = (const float *)anariMapFrame(
        m_device, f, "channel.color", &width, &height, &type);
    auto *d = (const float *)anariMapFrame(
        m_device, f, "channel.depth", &width, &height, &type);
    float3Mean mean;
    for (uint32_t i = 0; i < width * height; i++) {
      if (!std::isfinite(d[i]))
        continue;
      mean.r += p[4 * i];
      mean.g += p[4 * i + 1];
      mean.b += p[4 * i + 2];
      mean.pixels++;
    }
    if (mean.pixels) {
      mean.r /= mean.pixels;
      mean.g /= mean.pixels;
      mean.b /= mean.pixels;
    }
    anariUnmapFrame(m_device, f, "channel.color");
    anariUnmapFrame(m_device, f, "channel.depth");
    anariRelease(m_device, f);
    return mean;
  }
  ANARISurface plane(ANARIMaterial m)
  {
    return surface(
        geometry("quad", {-50, -50, 0, 50, -50, 0, 50, 50, 0, -50, 50, 0}), m);
  }
  // Gives world `w` the one committed `light` (released) and recommits it.
  void addLight(ANARIWorld w, ANARILight light)
  {
    setArray(w,
        "light",
        anariNewArray1D(m_device, &light, nullptr, nullptr, ANARI_LIGHT, 1));
    anariRelease(m_device, light);
    anariCommitParameters(m_device, w);
  }
  // A black physicallyBased material emitting radiance L (committed).
  ANARIMaterial glowing(float L)
  {
    ANARIMaterial m = anariNewMaterial(m_device, "physicallyBased");
    const float none[3] = {0, 0, 0}, emissive[3] = {L, L, L};
    anariSetParameter(m_device, m, "baseColor", ANARI_FLOAT32_VEC3, none);
    anariSetParameter(m_device, m, "emissive", ANARI_FLOAT32_VEC3, emissive);
    anariCommitParameters(m_device, m);
    return m;
  }
  ANARIMaterial metal(float roughness)
  {
    ANARIMaterial m = anariNewMaterial(m_device, "physicallyBased");
    const float white[3] = {1, 1, 1}, one = 1.f;
    anariSetParameter(m_device, m, "baseColor", ANARI_FLOAT32_VEC3, white);
    anariSetParameter(m_device, m, "metallic", ANARI_FLOAT32, &one);
    anariSetParameter(m_device, m, "roughness", ANARI_FLOAT32, &roughness);
    anariCommitParameters(m_device, m);
    return m;
  }
};

TEST_F(PathTracerTest, WhiteFurnaceMatteSphereDisappears)
{
  const float L = 0.7f, background[4] = {L, L, L, 1};
  ANARIWorld w =
      world({surface(geometry("sphere", {0, 0, 0}), matte(1, 1, 1))});
  ANARICamera c = orthographic(kEye, kDown, 2.5f);
  ANARIRenderer r = pathTracer(L, background);
  const float3Mean mean = meanOverHits(w, c, r, 24, 16);
  EXPECT_GT(mean.pixels, 200);
  // A convex sphere: every bounced ray escapes to radiance L.
  EXPECT_NEAR(mean.r, L, 0.01f * L);
  EXPECT_NEAR(mean.g, L, 0.01f * L);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, GreySphereReflectsItsAlbedoOfTheFurnace)
{
  const float L = 0.7f, background[4] = {L, L, L, 1};
  ANARIWorld w =
      world({surface(geometry("sphere", {0, 0, 0}), matte(0.5f, 0.25f, 1.f))});
  // A view inside the silhouette, so no pixel mixes in the background.
  ANARICamera c = orthographic(kEye, kDown, 1.f);
  ANARIRenderer r = pathTracer(L, background);
  const float3Mean mean = meanOverHits(w, c, r, 24, 16);
  EXPECT_NEAR(mean.r, 0.5f * L, 0.01f * L);
  EXPECT_NEAR(mean.g, 0.25f * L, 0.01f * L);
  EXPECT_NEAR(mean.b, L, 0.01f * L);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
}

TEST_F(PathTracerTest, WhiteFurnaceMetalSphereAtEveryRoughness)
{
  const float L = 0.5f, background[4] = {L, L, L, 1};
  for (float roughness : {0.f, 0.25f, 0.5f, 1.f}) {
    ANARIWorld w =
        world({surface(geometry("sphere", {0, 0, 0}), metal(roughness))});
    ANARICamera c = orthographic(kEye, kDown, 2.5f);
    ANARIRenderer r = pathTracer(L, background);
    const float3Mean mean = meanOverHits(w, c, r, 24, 32);
    // Energy-compensated GGX: within 3% of L (Monte Carlo and fit error).
    EXPECT_NEAR(mean.r, L, 0.03f * L) << "roughness " << roughness;
    for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, LambertPlaneUnderADirectionalLight)
{
  const float black[4] = {0, 0, 0, 1};
  const float rho = 0.6f, E = 2.f;
  ANARILight light = anariNewLight(m_device, "directional");
  const float direction[3] = {0, 0, -1};
  anariSetParameter(
      m_device, light, "direction", ANARI_FLOAT32_VEC3, direction);
  anariSetParameter(m_device, light, "irradiance", ANARI_FLOAT32, &E);
  anariCommitParameters(m_device, light);
  ANARIWorld w = world({plane(matte(rho, rho, rho))});
  addLight(w, light);
  ANARICamera c = orthographic(kEye, kDown, 2.f);
  ANARIRenderer r = pathTracer(0.f, black);
  const float3Mean mean = meanOverHits(w, c, r, 8, 1);
  // A delta light on a single plane: exact, no noise.
  EXPECT_NEAR(mean.r, rho * E / float(M_PI), 1e-4f);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

// A diffuse physicallyBased plane (specular 0: no dielectric layer) with
// texture coordinates along x and y, `normalMap` a constant tangent-space
// normal (or none), `occlusion` a constant occlusion (or none).
ANARISurface diffusePlane(ANARIDevice device,
    float rho,
    const float *normalMap,
    const float *occlusion,
    const std::function<ANARIArray1D(const std::vector<float> &, ANARIDataType)>
        &array1D)
{
  ANARIGeometry g = anariNewGeometry(device, "quad");
  ANARIArray1D positions = array1D(
      {-50, -50, 0, 50, -50, 0, 50, 50, 0, -50, 50, 0}, ANARI_FLOAT32_VEC3);
  anariSetParameter(device, g, "vertex.position", ANARI_ARRAY1D, &positions);
  anariRelease(device, positions);
  ANARIArray1D uv = array1D({0, 0, 1, 0, 1, 1, 0, 1}, ANARI_FLOAT32_VEC2);
  anariSetParameter(device, g, "vertex.attribute0", ANARI_ARRAY1D, &uv);
  anariRelease(device, uv);
  anariCommitParameters(device, g);
  ANARIMaterial m = anariNewMaterial(device, "physicallyBased");
  const float base[3] = {rho, rho, rho}, zero = 0.f;
  anariSetParameter(device, m, "baseColor", ANARI_FLOAT32_VEC3, base);
  anariSetParameter(device, m, "metallic", ANARI_FLOAT32, &zero);
  anariSetParameter(device, m, "specular", ANARI_FLOAT32, &zero);
  // A 1x1 image sampler: the same value everywhere.
  auto constantSampler = [&](const char *name,
                             ANARIDataType type,
                             const float *value,
                             size_t components) {
    ANARISampler sampler = anariNewSampler(device, "image2D");
    ANARIArray2D texel =
        anariNewArray2D(device, nullptr, nullptr, nullptr, type, 1, 1);
    std::memcpy(
        anariMapArray(device, texel), value, components * sizeof(float));
    anariUnmapArray(device, texel);
    anariSetParameter(device, sampler, "image", ANARI_ARRAY2D, &texel);
    anariRelease(device, texel);
    anariCommitParameters(device, sampler);
    anariSetParameter(device, m, name, ANARI_SAMPLER, &sampler);
    anariRelease(device, sampler);
  };
  if (normalMap)
    constantSampler("normal", ANARI_FLOAT32_VEC3, normalMap, 3);
  if (occlusion)
    constantSampler("occlusion", ANARI_FLOAT32, occlusion, 1);
  anariCommitParameters(device, m);
  ANARISurface s = anariNewSurface(device);
  anariSetParameter(device, s, "geometry", ANARI_GEOMETRY, &g);
  anariSetParameter(device, s, "material", ANARI_MATERIAL, &m);
  anariCommitParameters(device, s);
  anariRelease(device, g);
  anariRelease(device, m);
  return s;
}

TEST_F(PathTracerTest, NormalMapTiltsTheShadingNormalAlongTheTangent)
{
  // The sun tilted by a towards +x (= +u, the tangent): a normal map
  // tilting the normal by a towards +u faces it (cos 0), one tilting away
  // sees cos 2a, none cos a. Lambert: rho E cos / pi, exact for one plane.
  const float black[4] = {0, 0, 0, 1};
  const float rho = 0.5f, E = 3.f, a = 0.5f;
  const float towards[3] = {std::sin(a), 0.f, std::cos(a)};
  const float away[3] = {-std::sin(a), 0.f, std::cos(a)};
  const struct
  {
    const float *map;
    float cosine;
  } cases[] = {
      {towards, 1.f}, {away, std::cos(2.f * a)}, {nullptr, std::cos(a)}};
  for (const auto &test : cases) {
    ANARILight light = anariNewLight(m_device, "directional");
    const float direction[3] = {-std::sin(a), 0.f, -std::cos(a)};
    anariSetParameter(
        m_device, light, "direction", ANARI_FLOAT32_VEC3, direction);
    anariSetParameter(m_device, light, "irradiance", ANARI_FLOAT32, &E);
    anariCommitParameters(m_device, light);
    ANARIWorld w = world({diffusePlane(m_device,
        rho,
        test.map,
        nullptr,
        [&](const std::vector<float> &v, ANARIDataType t) {
          return array1D(v, t);
        })});
    addLight(w, light);
    ANARICamera c = orthographic(kEye, kDown, 2.f);
    ANARIRenderer r = pathTracer(0.f, black);
    const float3Mean mean = meanOverHits(w, c, r, 8, 1);
    EXPECT_NEAR(mean.r, rho * E * test.cosine / float(M_PI), 2e-3f)
        << "expected cosine " << test.cosine;
    for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, DebugShadingNormalShowsTheNormalMap)
{
  // The debug renderer's Ns mode shows the normal shading uses: the map's
  // tangent-space (sin a, 0, cos a) on a +z plane with +u along +x is the
  // world normal (sin a, 0, cos a), drawn as n / 2 + 1/2.
  const float a = 0.5f;
  const float tilted[3] = {std::sin(a), 0.f, std::cos(a)};
  for (const float *map : {tilted, (const float *)nullptr}) {
    ANARIWorld w = world({diffusePlane(m_device,
        0.5f,
        map,
        nullptr,
        [&](const std::vector<float> &v, ANARIDataType t) {
          return array1D(v, t);
        })});
    ANARICamera c = orthographic(kEye, kDown, 2.f);
    ANARIRenderer r = renderer("debug");
    anariSetParameter(m_device, r, "mode", ANARI_STRING, "Ns");
    anariCommitParameters(m_device, r);
    RenderedImage image = render(w, c, r, 4, 4);
    const float nx = map ? std::sin(a) : 0.f, nz = map ? std::cos(a) : 1.f;
    const float *pixel = image.pixel(2, 2);
    EXPECT_NEAR(pixel[0], nx * 0.5f + 0.5f, 1e-4f);
    EXPECT_NEAR(pixel[1], 0.5f, 1e-4f);
    EXPECT_NEAR(pixel[2], nz * 0.5f + 0.5f, 1e-4f);
    for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, OcclusionDarkensAmbientLightOnly)
{
  // Ambient radiance L over the plane's hemisphere gives rho L; occlusion
  // o scales that to rho L o and leaves the sun's rho E / pi alone.
  const float black[4] = {0, 0, 0, 1};
  const float rho = 0.5f, L = 1.f, E = 2.f, o = 0.25f;
  for (const bool sun : {false, true}) {
    ANARIWorld w = world({diffusePlane(m_device,
        rho,
        nullptr,
        &o,
        [&](const std::vector<float> &v, ANARIDataType t) {
          return array1D(v, t);
        })});
    if (sun) {
      ANARILight light = anariNewLight(m_device, "directional");
      const float direction[3] = {0, 0, -1};
      anariSetParameter(
          m_device, light, "direction", ANARI_FLOAT32_VEC3, direction);
      anariSetParameter(m_device, light, "irradiance", ANARI_FLOAT32, &E);
      anariCommitParameters(m_device, light);
      addLight(w, light);
    }
    ANARICamera c = orthographic(kEye, kDown, 2.f);
    ANARIRenderer r = pathTracer(L, black);
    const float3Mean mean = meanOverHits(w, c, r, 16, 64);
    const float expected = rho * L * o + (sun ? rho * E / float(M_PI) : 0.f);
    EXPECT_NEAR(mean.r, expected, 0.01f * expected) << "sun " << sun;
    for (ANARIObject obj : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, obj);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, PointLightFallsOffWithTheInverseSquare)
{
  const float black[4] = {0, 0, 0, 1};
  const float rho = 1.f, I = 10.f;
  float previous = 0.f;
  for (float height : {1.f, 2.f, 4.f}) {
    ANARILight light = anariNewLight(m_device, "point");
    const float position[3] = {0, 0, height};
    anariSetParameter(
        m_device, light, "position", ANARI_FLOAT32_VEC3, position);
    anariSetParameter(m_device, light, "intensity", ANARI_FLOAT32, &I);
    anariCommitParameters(m_device, light);
    ANARIWorld w = world({plane(matte(rho, rho, rho))});
    addLight(w, light);
    // One pixel right under the light (orthographic, tiny view).
    ANARICamera c = orthographic(kEye, kDown, 1e-3f);
    ANARIRenderer r = pathTracer(0.f, black);
    const float3Mean mean = meanOverHits(w, c, r, 1, 1);
    const float expected = rho * I / (float(M_PI) * height * height);
    EXPECT_NEAR(mean.r, expected, 1e-3f * expected) << "height " << height;
    if (previous > 0.f) {
      EXPECT_NEAR(previous / mean.r, 4.f, 1e-2f);
    }
    previous = mean.r;
    for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, InsideALitSphereEveryBounceAddsItsShare)
{
  // A point light at the centre of a matte sphere of albedo a gives every
  // point of the wall the same irradiance I / r^2, and each bounce sees
  // the whole wall: vertex k of a path adds (a I / pi r^2) a^k. A path of
  // n vertices sums the geometric series; without Russian roulette every
  // path would be that exact sum, so the only noise here is the
  // roulette's, and a roulette that cut paths short without weighting the
  // survivors up would fall short of it by the deep bounces' share.
  const float black[4] = {0, 0, 0, 1};
  const float a = 0.8f, I = 2.f;
  ANARILight light = anariNewLight(m_device, "point");
  const float centre[3] = {0, 0, 0};
  anariSetParameter(m_device, light, "position", ANARI_FLOAT32_VEC3, centre);
  anariSetParameter(m_device, light, "intensity", ANARI_FLOAT32, &I);
  anariCommitParameters(m_device, light);
  ANARIWorld w =
      world({surface(geometry("sphere", {0, 0, 0}), matte(a, a, a))});
  addLight(w, light);
  const float eye[3] = {0, 0, 0};
  ANARICamera c = orthographic(eye, kDown, 1.f);
  for (int32_t vertices : {3, 12}) {
    ANARIRenderer r = pathTracer(0.f, black);
    anariSetParameter(m_device, r, "maxPathLength", ANARI_INT32, &vertices);
    anariCommitParameters(m_device, r);
    const float3Mean mean = meanOverHits(w, c, r, 24, 16);
    const float expected =
        a * I / float(M_PI) * (1.f - std::pow(a, float(vertices))) / (1.f - a);
    EXPECT_EQ(mean.pixels, 24 * 24);
    // Three vertices never reach the roulette: the sum itself, to float
    // rounding; twelve do, to its noise (~0.3 % here).
    const float tolerance = vertices == 3 ? 1e-4f : 0.015f;
    EXPECT_NEAR(mean.r, expected, tolerance * expected) << vertices;
    EXPECT_NEAR(mean.b, expected, tolerance * expected) << vertices;
    anariRelease(m_device, r);
  }
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, SphereAndSpotLightsGiveThePointLightsIrradiance)
{
  // Below a sphere light of intensity I (radius 0.3, found by rays and
  // sampled, weighted by MIS) and inside a spot's cone, the irradiance is
  // that of a point light: I / h^2.
  const float black[4] = {0, 0, 0, 1};
  const float I = 10.f, h = 2.f;
  for (const char *subtype : {"point", "spot"}) {
    ANARILight light = anariNewLight(m_device, subtype);
    const float position[3] = {0, 0, h}, down[3] = {0, 0, -1};
    anariSetParameter(
        m_device, light, "position", ANARI_FLOAT32_VEC3, position);
    anariSetParameter(m_device, light, "intensity", ANARI_FLOAT32, &I);
    if (std::string(subtype) == "point") {
      const float radius = 0.3f;
      anariSetParameter(m_device, light, "radius", ANARI_FLOAT32, &radius);
    } else {
      anariSetParameter(m_device, light, "direction", ANARI_FLOAT32_VEC3, down);
    }
    anariCommitParameters(m_device, light);
    ANARIWorld w = world({plane(matte(1, 1, 1))});
    addLight(w, light);
    // Below the light, which camera rays would otherwise see.
    const float eye[3] = {0, 0, 1};
    ANARICamera c = orthographic(eye, kDown, 1e-3f);
    ANARIRenderer r = pathTracer(0.f, black);
    const float3Mean mean = meanOverHits(w, c, r, 1, 1024);
    const float expected = I / (float(M_PI) * h * h);
    EXPECT_NEAR(mean.r, expected, 0.02f * expected) << subtype;
    for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
  }
  EXPECT_TRUE(problems().empty());
}

// Irradiance at the origin (normal +z) from a polygon of radiance L:
// Lambert's formula, E = L / 2 * sum_i angle(v_i, v_i+1) * (n . unit(v_i x
// v_i+1)).
float polygonIrradiance(
    const std::vector<std::array<float, 3>> &corners, float L)
{
  double sum = 0;
  for (size_t i = 0; i < corners.size(); i++) {
    auto a = corners[i], b = corners[(i + 1) % corners.size()];
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    const double ax = a[0] / la, ay = a[1] / la, az = a[2] / la;
    const double bx = b[0] / lb, by = b[1] / lb, bz = b[2] / lb;
    const double angle = std::acos(ax * bx + ay * by + az * bz);
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz,
                 cz = ax * by - ay * bx;
    const double cl = std::sqrt(cx * cx + cy * cy + cz * cz);
    sum += angle * cz / cl;
  }
  return float(std::abs(sum) * 0.5 * L);
}

TEST_F(PathTracerTest, QuadLightIrradianceIsThePolygonFormFactor)
{
  const float black[4] = {0, 0, 0, 1};
  // A 1 x 2 light 1.5 above the plane, off-centre, emitting downwards.
  const float corner[3] = {-0.3f, -0.8f, 1.5f}, edge1[3] = {1, 0, 0},
              edge2[3] = {0, 2, 0}, L = 3.f;
  ANARILight light = quadLight(corner, edge1, edge2, "radiance", L);
  anariCommitParameters(m_device, light);
  ANARIWorld w = world({plane(matte(1, 1, 1))});
  addLight(w, light);
  // One pixel looking at the origin from below the light's height.
  const float eye[3] = {0, 0, 1};
  ANARICamera c = orthographic(eye, kDown, 1e-3f);
  ANARIRenderer r = pathTracer(0.f, black);
  const float3Mean mean = meanOverHits(w, c, r, 1, 4096);
  const float E = polygonIrradiance({{-0.3f, -0.8f, 1.5f},
                                        {0.7f, -0.8f, 1.5f},
                                        {0.7f, 1.2f, 1.5f},
                                        {-0.3f, 1.2f, 1.5f}},
      L);
  // Radiance of a white Lambert plane is E / pi; 4096 samples: ~1%.
  EXPECT_NEAR(mean.r, E / float(M_PI), 0.02f * E / float(M_PI));
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, EmissiveQuadLightsLikeAQuadLight)
{
  // The same 1 x 2 rectangle as above as black geometry with emissive
  // radiance L: next-event estimation samples it, rays that hit it are
  // weighted against that, and the irradiance is the same form factor.
  const float black[4] = {0, 0, 0, 1};
  const float L = 3.f;
  ANARIMaterial glow = glowing(L);
  ANARIGeometry panel = geometry("quad",
      {-0.3f,
          -0.8f,
          1.5f,
          0.7f,
          -0.8f,
          1.5f,
          0.7f,
          1.2f,
          1.5f,
          -0.3f,
          1.2f,
          1.5f});
  ANARIWorld w = world({plane(matte(1, 1, 1)), surface(panel, glow)});
  const float eye[3] = {0, 0, 1};
  ANARICamera c = orthographic(eye, kDown, 1e-3f);
  ANARIRenderer r = pathTracer(0.f, black);
  const float3Mean mean = meanOverHits(w, c, r, 1, 4096);
  const float E = polygonIrradiance({{-0.3f, -0.8f, 1.5f},
                                        {0.7f, -0.8f, 1.5f},
                                        {0.7f, 1.2f, 1.5f},
                                        {-0.3f, 1.2f, 1.5f}},
      L);
  EXPECT_NEAR(mean.r, E / float(M_PI), 0.02f * E / float(M_PI));
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, SmallEmissiveSphereIsSampledAsALight)
{
  // A sphere of radius R and radiance L at height h over a white plane
  // gives the point below it E = pi L (R / h)^2 (a sphere's form factor).
  // Too small to be found by chance, it converges only through next-event
  // estimation; area samples on its far side are wasted, so it takes 16k
  // samples to bring the noise well under the tolerance (at 1k, a change of
  // random streams alone moved the mean by 6 %).
  const float black[4] = {0, 0, 0, 1};
  const float L = 50.f, R = 0.05f, h = 1.f;
  ANARIMaterial glow = glowing(L);
  ANARIGeometry ball = geometry("sphere", {0, 0, h});
  anariSetParameter(m_device, ball, "radius", ANARI_FLOAT32, &R);
  ANARIWorld w = world({plane(matte(1, 1, 1)), surface(ball, glow)});
  const float eye[3] = {0.f, 0.f, 0.5f};
  ANARICamera c = orthographic(eye, kDown, 1e-3f);
  ANARIRenderer r = pathTracer(0.f, black);
  const float3Mean mean = meanOverHits(w, c, r, 1, 16384);
  const float E = float(M_PI) * L * (R / h) * (R / h);
  EXPECT_NEAR(mean.r, E / float(M_PI), 0.03f * E / float(M_PI));
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(PathTracerTest, UniformHdriLightsAPlaneAndHidesAWhiteSphere)
{
  // An hdri light of uniform radiance L (a 4 x 2 image of L): a Lambert
  // plane of albedo rho facing up receives pi L from the upper hemisphere
  // and shows rho L; a white sphere in it shows L (a furnace made of a
  // light, importance sampled, rather than of the ambient term).
  const float black[4] = {0, 0, 0, 1};
  const float L = 0.8f, rho = 0.5f;
  for (const bool sphere : {false, true}) {
    ANARILight light = anariNewLight(m_device, "hdri");
    std::vector<float> texels(4 * 2 * 3, L);
    ANARIArray2D image = anariNewArray2D(
        m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32_VEC3, 4, 2);
    std::memcpy(anariMapArray(m_device, image),
        texels.data(),
        texels.size() * sizeof(float));
    anariUnmapArray(m_device, image);
    anariSetParameter(m_device, light, "radiance", ANARI_ARRAY2D, &image);
    anariRelease(m_device, image);
    const float up[3] = {0, 0, 1};
    anariSetParameter(m_device, light, "up", ANARI_FLOAT32_VEC3, up);
    anariCommitParameters(m_device, light);
    ANARIWorld w =
        world({sphere ? surface(geometry("sphere", {0, 0, 0}), matte(1, 1, 1))
                      : plane(matte(rho, rho, rho))});
    addLight(w, light);
    ANARICamera c = orthographic(kEye, kDown, sphere ? 1.f : 2.f);
    ANARIRenderer r = pathTracer(0.f, black);
    const float3Mean mean = meanOverHits(w, c, r, 16, 64);
    const float expected = sphere ? L : rho * L;
    EXPECT_NEAR(mean.r, expected, 0.01f * expected) << "sphere " << sphere;
    for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
  }
  EXPECT_TRUE(problems().empty());
}

} // namespace
