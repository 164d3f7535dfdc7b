/* The prism device through libanari, from C99 with the public header only:
   every advertised subtype is creatable, the whole introspection can be
   walked, and an empty world shows the background in every color format. */
#include <anari/anari.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static int g_failures = 0;
static int g_errors = 0;

#define CHECK(cond)                                                   \
  do {                                                                \
    if (!(cond)) {                                                    \
      printf("%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      g_failures++;                                                   \
    }                                                                 \
  } while (0)

static void onStatus(const void *user,
    ANARIDevice device,
    ANARIObject source,
    ANARIDataType type,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message)
{
  (void)user, (void)device, (void)source, (void)type, (void)code;
  if (severity <= ANARI_SEVERITY_WARNING) {
    printf("status %d: %s\n", (int)severity, message);
    g_errors++;
  }
}

static const ANARIDataType kSubtyped[] = {ANARI_CAMERA,
    ANARI_GEOMETRY,
    ANARI_INSTANCE,
    ANARI_LIGHT,
    ANARI_MATERIAL,
    ANARI_RENDERER,
    ANARI_SAMPLER,
    ANARI_SPATIAL_FIELD,
    ANARI_VOLUME};

static ANARIObject newOfType(ANARIDevice d, ANARIDataType type, const char *s)
{
  switch (type) {
  case ANARI_CAMERA:
    return anariNewCamera(d, s);
  case ANARI_GEOMETRY:
    return anariNewGeometry(d, s);
  case ANARI_INSTANCE:
    return anariNewInstance(d, s);
  case ANARI_LIGHT:
    return anariNewLight(d, s);
  case ANARI_MATERIAL:
    return anariNewMaterial(d, s);
  case ANARI_RENDERER:
    return anariNewRenderer(d, s);
  case ANARI_SAMPLER:
    return anariNewSampler(d, s);
  case ANARI_SPATIAL_FIELD:
    return anariNewSpatialField(d, s);
  default:
    return anariNewVolume(d, s);
  }
}

/* Walks every info of every parameter of one object (sub)type. */
static int walkIntrospection(ANARIDevice d, ANARIDataType type, const char *s)
{
  static const char *kParameterInfos[] = {"description",
      "required",
      "default",
      "minimum",
      "maximum",
      "elementType",
      "value",
      "extension"};
  const ANARIParameter *params = (const ANARIParameter *)anariGetObjectInfo(
      d, type, s, "parameter", ANARI_PARAMETER_LIST);
  int count = 0;
  const char *description =
      (const char *)anariGetObjectInfo(d, type, s, "description", ANARI_STRING);
  CHECK(description != NULL);
  CHECK(params != NULL);
  for (; params && params->name; params++, count++) {
    const void *required = anariGetParameterInfo(
        d, type, s, params->name, params->type, "required", ANARI_BOOL);
    unsigned i;
    CHECK(required != NULL);
    for (i = 0; i < sizeof(kParameterInfos) / sizeof(*kParameterInfos); i++) {
      /* Any info may be absent, but asking must be safe. */
      anariGetParameterInfo(d,
          type,
          s,
          params->name,
          params->type,
          kParameterInfos[i],
          ANARI_STRING);
    }
  }
  return count;
}

static ANARIFrame makeFrame(ANARIDevice d,
    ANARIRenderer renderer,
    ANARIDataType colorType,
    uint32_t w,
    uint32_t h)
{
  ANARIFrame frame = anariNewFrame(d);
  ANARIWorld world = anariNewWorld(d);
  ANARICamera camera = anariNewCamera(d, "perspective");
  uint32_t size[2];
  ANARIDataType depthType = ANARI_FLOAT32;
  size[0] = w;
  size[1] = h;
  anariCommitParameters(d, world);
  anariCommitParameters(d, camera);
  anariSetParameter(d, frame, "world", ANARI_WORLD, &world);
  anariSetParameter(d, frame, "camera", ANARI_CAMERA, &camera);
  anariSetParameter(d, frame, "renderer", ANARI_RENDERER, &renderer);
  anariSetParameter(d, frame, "size", ANARI_UINT32_VEC2, size);
  anariSetParameter(d, frame, "channel.color", ANARI_DATA_TYPE, &colorType);
  anariSetParameter(d, frame, "channel.depth", ANARI_DATA_TYPE, &depthType);
  anariCommitParameters(d, frame);
  anariRelease(d, world);
  anariRelease(d, camera);
  return frame;
}

static void testBackgroundColor(ANARIDevice d)
{
  const float background[4] = {0.25f, 0.5f, 1.0f, 0.75f};
  const ANARIDataType formats[3] = {
      ANARI_UFIXED8_VEC4, ANARI_UFIXED8_RGBA_SRGB, ANARI_FLOAT32_VEC4};
  /* Expected bytes: linear 8-bit rounds v*255; sRGB encodes rgb. */
  const unsigned char linear8[4] = {64, 128, 255, 191};
  const unsigned char srgb8[4] = {137, 188, 255, 191};
  ANARIRenderer renderer = anariNewRenderer(d, "default");
  int f;
  anariSetParameter(d, renderer, "background", ANARI_FLOAT32_VEC4, background);
  anariCommitParameters(d, renderer);
  for (f = 0; f < 3; f++) {
    ANARIFrame frame = makeFrame(d, renderer, formats[f], 7, 5);
    uint32_t w = 0, h = 0, i;
    ANARIDataType type = ANARI_UNKNOWN;
    const void *pixels;
    const float *depth;
    anariRenderFrame(d, frame);
    CHECK(anariFrameReady(d, frame, ANARI_WAIT) == 1);
    pixels = anariMapFrame(d, frame, "channel.color", &w, &h, &type);
    CHECK(pixels != NULL && w == 7 && h == 5 && type == formats[f]);
    for (i = 0; pixels && i < w * h; i++) {
      if (formats[f] == ANARI_FLOAT32_VEC4) {
        CHECK(memcmp((const float *)pixels + 4 * i, background, 16) == 0);
      } else {
        const unsigned char *p = (const unsigned char *)pixels + 4 * i;
        CHECK(memcmp(p, f == 0 ? linear8 : srgb8, 4) == 0);
      }
    }
    anariUnmapFrame(d, frame, "channel.color");
    depth =
        (const float *)anariMapFrame(d, frame, "channel.depth", &w, &h, &type);
    CHECK(depth != NULL && type == ANARI_FLOAT32);
    for (i = 0; depth && i < w * h; i++)
      CHECK(isinf(depth[i]) && depth[i] > 0);
    anariUnmapFrame(d, frame, "channel.depth");
    anariRelease(d, frame);
  }
  anariRelease(d, renderer);
}

/* A 2x2 background image stretched over 4x4 pixels, bilinear, clamped. */
static void testBackgroundImage(ANARIDevice d)
{
  const float texels[4][4] = {
      {0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {1, 1, 0, 1}};
  ANARIArray2D image =
      anariNewArray2D(d, texels, NULL, NULL, ANARI_FLOAT32_VEC4, 2, 2);
  ANARIRenderer renderer = anariNewRenderer(d, "default");
  ANARIFrame frame;
  const float *pixels;
  uint32_t w, h;
  ANARIDataType type;
  anariSetParameter(d, renderer, "background", ANARI_ARRAY2D, &image);
  anariCommitParameters(d, renderer);
  anariRelease(d, image);
  frame = makeFrame(d, renderer, ANARI_FLOAT32_VEC4, 4, 4);
  anariRenderFrame(d, frame);
  anariFrameReady(d, frame, ANARI_WAIT);
  pixels =
      (const float *)anariMapFrame(d, frame, "channel.color", &w, &h, &type);
  CHECK(pixels != NULL && w == 4 && h == 4);
  if (pixels) {
    /* Pixel centres at u = 1/8, 3/8, 5/8, 7/8 sample texel coordinates
       -0.25 (clamped to 0), 0.25, 0.75, 1.25 (clamped to 1). */
    const float expectedRed[4] = {0.f, 0.25f, 0.75f, 1.f};
    int x, y;
    for (y = 0; y < 4; y++) {
      for (x = 0; x < 4; x++) {
        const float *p = pixels + 4 * (y * 4 + x);
        CHECK(fabsf(p[0] - expectedRed[x]) < 1e-6f);
        CHECK(fabsf(p[1] - expectedRed[y]) < 1e-6f);
        CHECK(p[2] == 0.f && p[3] == 1.f);
      }
    }
  }
  anariUnmapFrame(d, frame, "channel.color");
  anariRelease(d, frame);
  anariRelease(d, renderer);
}

int main(void)
{
  ANARILibrary library = anariLoadLibrary("prism", onStatus, NULL);
  ANARIDevice d;
  const char **extensions;
  unsigned t;
  int objects = 0, parameters = 0;
  CHECK(library != NULL);
  if (!library)
    return 1;
  d = anariNewDevice(library, "default");
  CHECK(d != NULL);
  extensions = anariGetDeviceExtensions(library, "default");
  CHECK(extensions != NULL && extensions[0] != NULL);

  for (t = 0; t < sizeof(kSubtyped) / sizeof(*kSubtyped); t++) {
    const char **subtypes = anariGetObjectSubtypes(d, kSubtyped[t]);
    for (; subtypes && *subtypes; subtypes++) {
      /* Not committed: most subtypes rightly reject a commit without their
         required parameters; creating them must be silent. */
      ANARIObject object = newOfType(d, kSubtyped[t], *subtypes);
      CHECK(object != NULL);
      anariRelease(d, object);
      parameters += walkIntrospection(d, kSubtyped[t], *subtypes);
      objects++;
    }
  }
  parameters += walkIntrospection(d, ANARI_FRAME, NULL);
  parameters += walkIntrospection(d, ANARI_WORLD, NULL);
  parameters += walkIntrospection(d, ANARI_SURFACE, NULL);
  CHECK(anariGetObjectInfo(d, ANARI_FRAME, NULL, "channel", ANARI_STRING_LIST)
        != NULL);
  CHECK(objects >= 3);

  testBackgroundColor(d);
  testBackgroundImage(d);

  anariRelease(d, d);
  anariUnloadLibrary(library);
  CHECK(g_errors == 0);
  printf("%d subtyped objects, %d parameters walked, %d failures\n",
      objects,
      parameters,
      g_failures);
  return g_failures == 0 ? 0 : 1;
}
