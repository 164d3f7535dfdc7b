// prism's material extensions for glTF, rendered with known answers:
// PRISM_MATERIAL_DOUBLE_SIDED (back faces invisible to camera and bounce
// rays; light passes them, so shadow rays pass front faces),
// PRISM_MATERIAL_UNLIT (the base color seen as is, whatever the lights,
// denoised or not) and PRISM_MATERIAL_BASE_COLOR_FACTOR (a sampled base
// color times the vertex colors).
#include "AnalyticScene.h"

#include <cmath>
#include <numbers>

namespace {

constexpr uint32_t kReceiver = 1, kOccluder = 2;
const float kDown[3] = {0, 0, -1};
const float kIdentity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

class MaterialExtensionsTest : public AnalyticTest
{
 protected:
  // A square of half size `half` at height z, centred on (cx, 0), its
  // corners counter-clockwise seen from +z (normal +z) or from -z.
  ANARIGeometry square(float cx, float half, float z, bool normalUp)
  {
    std::vector<float> p = {cx - half,
        -half,
        z,
        cx + half,
        -half,
        z,
        cx + half,
        half,
        z,
        cx - half,
        half,
        z};
    if (!normalUp)
      for (int k = 0; k < 3; k++)
        std::swap(p[3 + k], p[9 + k]);
    return geometry("quad", p);
  }
  ANARIMaterial matteSided(float rho, bool doubleSided)
  {
    ANARIMaterial m = matte(rho, rho, rho);
    const uint8_t sided = doubleSided;
    anariSetParameter(m_device, m, "doubleSided", ANARI_BOOL, &sided);
    anariCommitParameters(m_device, m);
    return m;
  }
  // The receiver (z = 0, white 0.6, normal up), an occluder over x >= 0 at
  // z = 1 (in the world, or `instanced` in an instance of its own) and a
  // directional light from (+x, +z): the light's shadow rays from the
  // receiver at x in [-0.75, -0.25] cross the occluder.
  ANARIWorld occluderScene(
      ANARIMaterial occluderMaterial, bool occluderUp, bool instanced = false)
  {
    return lightAndReceiverWith(
        surface(
            square(10.f, 10.f, 1.f, occluderUp), occluderMaterial, kOccluder),
        instanced);
  }
  // The same with another `occluder` (taken over).
  ANARIWorld lightAndReceiverWith(ANARISurface occluder, bool instanced)
  {
    ANARISurface receiver = surface(
        square(0.f, 20.f, 0.f, true), matte(0.6f, 0.6f, 0.6f), kReceiver);
    ANARIWorld w = instanced ? world({receiver}) : world({receiver, occluder});
    if (instanced)
      placeInstanced(w, occluder, kIdentity);
    ANARILight light = anariNewLight(m_device, "directional");
    const float direction[3] = {-1, 0, -1}, irradiance = 2.f;
    anariSetParameter(
        m_device, light, "direction", ANARI_FLOAT32_VEC3, direction);
    anariSetParameter(
        m_device, light, "irradiance", ANARI_FLOAT32, &irradiance);
    setOnlyLight(w, light);
    return w;
  }
  // An orthographic view straight down on (x, 0), 0.5 wide.
  ANARICamera above(float x)
  {
    const float eye[3] = {x, 0, 5};
    return orthographic(eye, kDown, 0.5f);
  }
  // Direct light only: shadows are exactly black.
  ANARIRenderer pathTracer()
  {
    ANARIRenderer r = renderer("pathtracer");
    const float none = 0.f;
    const int32_t direct = 2;
    anariSetParameter(m_device, r, "ambientRadiance", ANARI_FLOAT32, &none);
    anariSetParameter(m_device, r, "maxPathLength", ANARI_INT32, &direct);
    anariCommitParameters(m_device, r);
    return r;
  }
  // Every pixel's object id and red value of one 8x8 frame.
  RenderedImage look(ANARIWorld w, float x, const char *subtype = nullptr)
  {
    ANARICamera c = above(x);
    ANARIRenderer r = subtype ? renderer(subtype) : pathTracer();
    RenderedImage image = render(w, c, r, 8, 8);
    anariRelease(m_device, c);
    anariRelease(m_device, r);
    return image;
  }
  // look() at x = -0.5 with 256 samples a pixel (16384 in all): for
  // shadows that random passes lighten.
  RenderedImage lookLong(ANARIWorld w)
  {
    ANARIRenderer r = pathTracer();
    const int32_t samples = 256;
    anariSetParameter(m_device, r, "pixelSamples", ANARI_INT32, &samples);
    anariCommitParameters(m_device, r);
    ANARICamera c = above(-0.5f);
    RenderedImage image = render(w, c, r, 8, 8);
    anariRelease(m_device, c);
    anariRelease(m_device, r);
    return image;
  }
  static double meanRed(const RenderedImage &image)
  {
    double sum = 0.0;
    for (size_t i = 0; i < image.color.size(); i += 4)
      sum += image.color[i];
    return sum / double(image.color.size() / 4);
  }
  static bool allIds(const RenderedImage &image, uint32_t id)
  {
    for (uint32_t v : image.objectId)
      if (v != id)
        return false;
    return !image.objectId.empty();
  }
  static float maxRed(const RenderedImage &image)
  {
    float top = 0.f;
    for (size_t i = 0; i < image.color.size(); i += 4)
      top = std::max(top, image.color[i]);
    return top;
  }
  static float minRed(const RenderedImage &image)
  {
    float bottom = 1e30f;
    for (size_t i = 0; i < image.color.size(); i += 4)
      bottom = std::min(bottom, image.color[i]);
    return bottom;
  }
};

// Lambert under the directional light at 45 degrees: rho E cos / pi.
const float kLit =
    0.6f * 2.f * std::numbers::sqrt2_v<float> / 2.f / std::numbers::pi_v<float>;

TEST_F(MaterialExtensionsTest, CameraRaysPassBackFaces)
{
  // The occluder's back faces the camera: single-sided, every renderer
  // sees the receiver through it; double-sided, the occluder.
  for (const char *subtype : {"pathtracer", "raycast", "ao", "debug"}) {
    ANARIWorld single = occluderScene(matteSided(0.3f, false), false);
    EXPECT_TRUE(allIds(look(single, 1.5f, subtype), kReceiver)) << subtype;
    anariRelease(m_device, single);
    ANARIWorld both = occluderScene(matteSided(0.3f, true), false);
    EXPECT_TRUE(allIds(look(both, 1.5f, subtype), kOccluder)) << subtype;
    anariRelease(m_device, both);
  }
  // Its front faces the camera: seen either way.
  ANARIWorld front = occluderScene(matteSided(0.3f, false), true);
  EXPECT_TRUE(allIds(look(front, 1.5f), kOccluder));
  anariRelease(m_device, front);
  EXPECT_TRUE(problems().empty());
}

TEST_F(MaterialExtensionsTest, InstancedBackFacesFollowTheTransform)
{
  // The occluder in a group placed by a mirror (z -> -z) or a half turn
  // about x: its object-space front (+z) faces down in the world, so the
  // camera above sees through it; with its object front -z, it faces up
  // and is seen. (glTF: under a negative determinant the front faces run
  // clockwise in the world, i.e. stay the object's counter-clockwise side.)
  const float mirror[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
  const float halfTurn[16] = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
  for (const float *transform : {mirror, halfTurn})
    for (const bool objectUp : {true, false}) {
      ANARISurface receiver = surface(
          square(0.f, 20.f, 0.f, true), matte(0.6f, 0.6f, 0.6f), kReceiver);
      ANARISurface occluder = surface(square(10.f, 10.f, -1.f, objectUp),
          matteSided(0.3f, false),
          kOccluder);
      ANARIWorld w = world({receiver});
      placeInstanced(w, occluder, transform);
      EXPECT_TRUE(
          allIds(look(w, 1.5f, "raycast"), objectUp ? kReceiver : kOccluder))
          << (transform == mirror ? "mirror" : "half turn") << " " << objectUp;
      anariRelease(m_device, w);
    }
  EXPECT_TRUE(problems().empty());
}

TEST_F(MaterialExtensionsTest, LightPassesBackFaces)
{
  // Light runs from the light down to the receiver: it meets the
  // occluder's front when its normal points up (the receiver is shadowed),
  // its back when it points down (lit, exactly Lambert), as the camera
  // above sees through that back. Shadow rays, traced the other way, meet
  // the opposite sides.
  ANARIWorld up = occluderScene(matteSided(0.3f, false), true);
  EXPECT_EQ(maxRed(look(up, -0.5f)), 0.f);
  anariRelease(m_device, up);
  ANARIWorld down = occluderScene(matteSided(0.3f, false), false);
  const RenderedImage lit = look(down, -0.5f);
  EXPECT_TRUE(allIds(lit, kReceiver));
  EXPECT_NEAR(minRed(lit), kLit, 1e-4f);
  EXPECT_NEAR(maxRed(lit), kLit, 1e-4f);
  anariRelease(m_device, down);
  // Double-sided occluders shadow from either side.
  ANARIWorld both = occluderScene(matteSided(0.3f, true), false);
  EXPECT_EQ(maxRed(look(both, -0.5f)), 0.f);
  anariRelease(m_device, both);
  EXPECT_TRUE(problems().empty());
}

// Shadow rays meet see-through surfaces as camera and bounce rays do: an
// occluder blended at opacity 0.25 lets three quarters of the light
// through on average; a masked one all of it below the cutoff (0.5) and
// none above; an opaque one ignores its opacity. Single-sided, light
// meeting the blended occluder's back passes it whole. The same in an
// instance.
TEST_F(MaterialExtensionsTest, LightPassesSeeThroughSurfacesByTheirCoverage)
{
  struct Case
  {
    const char *alphaMode;
    float opacity;
    bool doubleSided, occluderUp;
    float lit; // the share of kLit
    bool instanced{false};
  };
  const Case cases[] = {{"blend", 0.25f, true, false, 0.75f},
      {"mask", 0.3f, true, false, 1.f},
      {"mask", 0.7f, true, false, 0.f},
      {"opaque", 0.3f, true, false, 0.f},
      {"blend", 0.25f, false, true, 0.75f},
      {"blend", 0.25f, false, false, 1.f},
      {"mask", 0.3f, true, false, 1.f, true},
      {"blend", 0.25f, true, false, 0.75f, true}};
  for (const Case &c : cases) {
    ANARIMaterial m = matteSided(0.3f, c.doubleSided);
    anariSetParameter(m_device, m, "opacity", ANARI_FLOAT32, &c.opacity);
    anariSetParameter(m_device, m, "alphaMode", ANARI_STRING, c.alphaMode);
    anariCommitParameters(m_device, m);
    ANARIWorld w = occluderScene(m, c.occluderUp, c.instanced);
    const RenderedImage image = lookLong(w);
    const double mean = meanRed(image);
    // 16384 samples of a pass or a stop: the blend's mean within 2 %
    // (four standard deviations); masks decide alike for every ray.
    EXPECT_TRUE(allIds(image, kReceiver));
    EXPECT_NEAR(mean, c.lit * kLit, 0.02 * kLit)
        << c.alphaMode << " " << c.opacity << " " << c.occluderUp << " "
        << c.instanced;
    if (c.lit == 0.f || c.lit == 1.f) {
      EXPECT_NEAR(minRed(image), c.lit * kLit, 1e-4f) << c.alphaMode;
      EXPECT_NEAR(maxRed(image), c.lit * kLit, 1e-4f) << c.alphaMode;
    }
    anariRelease(m_device, w);
  }
  EXPECT_TRUE(problems().empty());
}

// Shadow rays pass a see-through cylinder (geometry prism intersects
// itself, not Embree) at each of its crossings in turn: the two walls of
// a tube blended at opacity 0.25 let 0.75^2 of the light through; masked
// (below the cutoff) all of it; opaque none.
TEST_F(MaterialExtensionsTest, LightPassesSeeThroughCylindersAtEveryCrossing)
{
  struct Case
  {
    const char *alphaMode;
    float lit; // the share of kLit
  };
  for (const Case &c :
      {Case{"blend", 0.5625f}, Case{"mask", 1.f}, Case{"opaque", 0.f}}) {
    // Along y through (0.5, 1): every shadow ray from the receiver under
    // the camera crosses its axis within 0.18 of it.
    ANARIGeometry tube = geometry("cylinder", {0.5f, -10, 1, 0.5f, 10, 1});
    const float radius = 0.3f, opacity = 0.25f;
    anariSetParameter(m_device, tube, "radius", ANARI_FLOAT32, &radius);
    ANARIMaterial m = matteSided(0.3f, true);
    anariSetParameter(m_device, m, "opacity", ANARI_FLOAT32, &opacity);
    anariSetParameter(m_device, m, "alphaMode", ANARI_STRING, c.alphaMode);
    anariCommitParameters(m_device, m);
    ANARIWorld w = lightAndReceiverWith(surface(tube, m, kOccluder), false);
    const RenderedImage image = lookLong(w);
    const double mean = meanRed(image);
    EXPECT_TRUE(allIds(image, kReceiver));
    // As above: within 2 % (more than four standard deviations).
    EXPECT_NEAR(mean, c.lit * kLit, 0.02 * kLit) << c.alphaMode;
    anariRelease(m_device, w);
  }
  EXPECT_TRUE(problems().empty());
}

// The same rule under a quad light, which the path tracer reaches two
// ways: light samples (shadow rays) and BSDF rays that hit it, weighted
// against each other. Where the two kinds of ray see a single-sided
// occluder differently, the weights must not lose or double the light:
// with a black occluder between the receiver and the light, paths of four
// vertices show what direct light alone (one vertex) shows. A camera
// below the occluder looks down on the receiver. Again with a black
// see-through sheet (opacity 0.5) over the occluder: both kinds of ray
// pass it half the time, and a BSDF ray carried on past it still
// remembers the face it passed before.
TEST_F(MaterialExtensionsTest,
    LightThroughOneSidedFacesIsOneLightWhicheverRayFindsIt)
{
  const float eye[3] = {0, 0, 0.5f};
  ANARICamera c = orthographic(eye, kDown, 0.5f);
  for (const bool sheeted : {false, true})
    for (const bool occluderUp : {false, true}) {
      ANARISurface receiver = surface(
          square(0.f, 20.f, 0.f, true), matte(0.6f, 0.6f, 0.6f), kReceiver);
      ANARISurface occluder = surface(
          square(0.f, 3.f, 1.f, occluderUp), matteSided(0.f, false), kOccluder);
      std::vector<ANARISurface> surfaces = {receiver, occluder};
      if (sheeted) {
        ANARIMaterial black = matteSided(0.f, true);
        const float opacity = 0.5f;
        anariSetParameter(m_device, black, "opacity", ANARI_FLOAT32, &opacity);
        anariSetParameter(m_device, black, "alphaMode", ANARI_STRING, "blend");
        anariCommitParameters(m_device, black);
        surfaces.push_back(surface(square(0.f, 3.f, 1.5f, true), black));
      }
      ANARIWorld w = world(surfaces);
      // Wide, so BSDF rays find it often; it emits downwards.
      const float position[3] = {-2.f, -2.f, 2.f}, edge1[3] = {4, 0, 0},
                  edge2[3] = {0, 4, 0};
      setOnlyLight(w, quadLight(position, edge1, edge2, "intensity", 5.f));
      double image[2] = {0.0, 0.0};
      float brightest = 0.f;
      for (int k = 0; k < 2; k++) {
        ANARIRenderer r = renderer("pathtracer");
        const int32_t vertices = k == 0 ? 1 : 4, samples = 64;
        anariSetParameter(m_device, r, "maxPathLength", ANARI_INT32, &vertices);
        anariSetParameter(m_device, r, "pixelSamples", ANARI_INT32, &samples);
        anariCommitParameters(m_device, r);
        const RenderedImage rendered = render(w, c, r, 16, 16);
        EXPECT_TRUE(allIds(rendered, kReceiver)) << sheeted;
        image[k] = meanRed(rendered);
        brightest = std::max(brightest, maxRed(rendered));
        anariRelease(m_device, r);
      }
      if (occluderUp) {
        // Light meets the occluder's front: a shadow, however it is sampled
        // (BSDF rays pass its back and see the light; they must not count).
        EXPECT_EQ(brightest, 0.f) << sheeted;
      } else {
        // Light meets its back and passes; BSDF rays meet its front and stop
        // (the light samples must then count in full).
        // Sheeted, both images hold the sheet's random passes too (1 %
        // apart at 64 samples a pixel).
        EXPECT_GT(image[0], sheeted ? 0.025 : 0.05);
        EXPECT_NEAR(image[1], image[0], (sheeted ? 0.03 : 0.01) * image[0])
            << sheeted;
      }
      anariRelease(m_device, w);
    }
  anariRelease(m_device, c);
  EXPECT_TRUE(problems().empty());
}

TEST_F(MaterialExtensionsTest, ChangingDoubleSidedRebuildsTheWorld)
{
  ANARIMaterial m = matteSided(0.3f, false);
  anariRetain(m_device, m);
  ANARIWorld w = occluderScene(m, false);
  EXPECT_NEAR(maxRed(look(w, -0.5f)), kLit, 1e-4f);
  const uint8_t on = 1;
  anariSetParameter(m_device, m, "doubleSided", ANARI_BOOL, &on);
  anariCommitParameters(m_device, m);
  EXPECT_EQ(maxRed(look(w, -0.5f)), 0.f);
  anariRelease(m_device, m);
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

class UnlitTest : public MaterialExtensionsTest
{
 protected:
  // A 4x4 texture of distinct colors (none black: the denoiser cannot
  // divide a black albedo out) on a square seen from above.
  ANARIWorld texturedUnlit(bool unlit)
  {
    std::vector<float> texels;
    for (int i = 0; i < 16; i++)
      texels.insert(texels.end(),
          {0.1f + 0.05f * float(i),
              0.1f + float(i % 3) * 0.4f,
              0.9f - 0.05f * float(i)});
    ANARIArray2D image = anariNewArray2D(
        m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32_VEC3, 4, 4);
    std::memcpy(anariMapArray(m_device, image),
        texels.data(),
        texels.size() * sizeof(float));
    anariUnmapArray(m_device, image);
    ANARISampler sampler = anariNewSampler(m_device, "image2D");
    anariSetParameter(m_device, sampler, "image", ANARI_ARRAY2D, &image);
    anariSetParameter(m_device, sampler, "filter", ANARI_STRING, "nearest");
    anariCommitParameters(m_device, sampler);
    anariRelease(m_device, image);
    ANARIMaterial m = anariNewMaterial(m_device, "physicallyBased");
    anariSetParameter(m_device, m, "baseColor", ANARI_SAMPLER, &sampler);
    anariRelease(m_device, sampler);
    const uint8_t flag = unlit;
    anariSetParameter(m_device, m, "unlit", ANARI_BOOL, &flag);
    anariCommitParameters(m_device, m);
    ANARIGeometry g = square(0.f, 0.25f, 0.f, true);
    setArray(g,
        "vertex.attribute0",
        array1D(
            std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1}, ANARI_FLOAT32_VEC2));
    return world({surface(g, m, kReceiver)});
  }
  // The path-traced image of `w` (lit by a strong light and ambient light)
  // after `frames` frames, denoised or not.
  std::vector<float> pathTraced(ANARIWorld w, bool denoise, int frames)
  {
    ANARILight light = anariNewLight(m_device, "directional");
    const float irradiance = 5.f;
    anariSetParameter(m_device, light, "direction", ANARI_FLOAT32_VEC3, kDown);
    anariSetParameter(
        m_device, light, "irradiance", ANARI_FLOAT32, &irradiance);
    setOnlyLight(w, light);
    ANARIRenderer r = renderer("pathtracer");
    const float ambient = 1.f;
    const uint8_t on = denoise;
    anariSetParameter(m_device, r, "ambientRadiance", ANARI_FLOAT32, &ambient);
    anariSetParameter(m_device, r, "denoise", ANARI_BOOL, &on);
    anariCommitParameters(m_device, r);
    const float eye[3] = {0, 0, 5};
    ANARICamera c = orthographic(eye, kDown, 0.5f);
    std::vector<float> color = accumulatedColor(w, c, r, 16, frames);
    anariRelease(m_device, c);
    anariRelease(m_device, r);
    return color;
  }
};

TEST_F(UnlitTest, ShowsItsBaseColorWhateverTheLights)
{
  ANARIMaterial m = anariNewMaterial(m_device, "physicallyBased");
  const float color[3] = {0.2f, 0.5f, 0.8f};
  const uint8_t on = 1;
  anariSetParameter(m_device, m, "baseColor", ANARI_FLOAT32_VEC3, color);
  anariSetParameter(m_device, m, "unlit", ANARI_BOOL, &on);
  anariCommitParameters(m_device, m);
  ANARIWorld w = world({surface(square(0.f, 5.f, 0.f, true), m)});
  const std::vector<float> image = pathTraced(w, false, 4);
  ASSERT_EQ(image.size(), 16u * 16u * 4u);
  for (size_t i = 0; i < image.size(); i += 4)
    for (int c = 0; c < 3; c++)
      ASSERT_NEAR(image[i + size_t(c)], color[c], 1e-6f) << i / 4;
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

TEST_F(UnlitTest, DenoisingKeepsItsTexture)
{
  // Unlit surfaces report their base color as albedo: the denoiser divides
  // the texture out and back in exactly instead of blurring it.
  ANARIWorld w = texturedUnlit(true);
  const std::vector<float> plain = pathTraced(w, false, 1);
  const std::vector<float> denoised = pathTraced(w, true, 1);
  ASSERT_EQ(plain.size(), denoised.size());
  float worst = 0.f, spread = 0.f;
  for (size_t i = 0; i < plain.size(); i++) {
    worst = std::max(worst, std::abs(plain[i] - denoised[i]));
    spread = std::max(spread, std::abs(plain[i] - plain[0]));
  }
  EXPECT_LT(worst, 1e-4f);
  EXPECT_GT(spread, 0.3f); // the texture is there to keep
  anariRelease(m_device, w);
  // Lit, the same texture is shaded: the image differs.
  ANARIWorld lit = texturedUnlit(false);
  const std::vector<float> shaded = pathTraced(lit, false, 1);
  float difference = 0.f;
  for (size_t i = 0; i < plain.size(); i++)
    difference = std::max(difference, std::abs(plain[i] - shaded[i]));
  EXPECT_GT(difference, 0.1f);
  anariRelease(m_device, lit);
  EXPECT_TRUE(problems().empty());
}

TEST_F(MaterialExtensionsTest, BaseColorFactorMultipliesVertexColors)
{
  // baseColor (1, 0.5, 0.25) times vertex colors (0.5, 0.5, 0.5): the flat
  // raycast view (eyeLightBlendRatio 0) shows the product.
  ANARIMaterial m = anariNewMaterial(m_device, "physicallyBased");
  const float color[3] = {1.f, 0.5f, 0.25f};
  anariSetParameter(m_device, m, "baseColor", ANARI_FLOAT32_VEC3, color);
  anariSetParameter(m_device, m, "baseColorFactor", ANARI_STRING, "color");
  anariCommitParameters(m_device, m);
  ANARIGeometry g = square(0.f, 5.f, 0.f, true);
  setArray(g,
      "vertex.color",
      array1D(std::vector<float>(16, 0.5f), ANARI_FLOAT32_VEC4));
  ANARIWorld w = world({surface(g, m)});
  ANARIRenderer r = renderer("raycast");
  const float flat = 0.f;
  anariSetParameter(m_device, r, "eyeLightBlendRatio", ANARI_FLOAT32, &flat);
  anariCommitParameters(m_device, r);
  ANARICamera c = above(0.f);
  const RenderedImage image = render(w, c, r, 4, 4);
  for (uint32_t y = 0; y < 4; y++)
    for (uint32_t x = 0; x < 4; x++) {
      EXPECT_NEAR(image.pixel(x, y)[0], 0.5f, 1e-5f);
      EXPECT_NEAR(image.pixel(x, y)[1], 0.25f, 1e-5f);
      EXPECT_NEAR(image.pixel(x, y)[2], 0.125f, 1e-5f);
    }
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

} // namespace
