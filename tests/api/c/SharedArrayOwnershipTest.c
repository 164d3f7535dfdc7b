/* The usage pattern of the ANARI-SDK's own test scenes, from C99: every
   array is shared over a heap buffer, released right after it is set, and
   the buffer is freed (scribbled on first, as heap reuse would) before the
   frame renders. The image must equal the one rendered with every buffer
   kept alive: every geometry subtype, a sampled image and an HDRI. */
#include <anari/anari.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIZE 32

static int g_problems = 0;

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
    g_problems++;
  }
}

/* Buffers to free once rendering is over (kept-alive run), or NULL. */
static void *g_kept[64];
static int g_keptCount = 0;

/* A shared 1D/2D array over a heap copy of `data`; `releaseEarly` frees the
   copy right after the array is set on `object`. */
static void setArray(ANARIDevice d,
    ANARIObject object,
    const char *name,
    ANARIDataType type,
    const void *data,
    size_t elementSize,
    uint64_t width,
    uint64_t height,
    int releaseEarly)
{
  const size_t bytes = elementSize * (size_t)(width * height);
  void *copy = malloc(bytes);
  ANARIArray array;
  memcpy(copy, data, bytes);
  if (height > 1) {
    array = anariNewArray2D(d, copy, NULL, NULL, type, width, height);
    anariSetParameter(d, object, name, ANARI_ARRAY2D, &array);
  } else {
    array = anariNewArray1D(d, copy, NULL, NULL, type, width);
    anariSetParameter(d, object, name, ANARI_ARRAY1D, &array);
  }
  anariRelease(d, array);
  if (releaseEarly) {
    memset(copy, 0x5a, bytes);
    free(copy);
  } else {
    g_kept[g_keptCount++] = copy;
  }
}

static ANARISurface newSurface(
    ANARIDevice d, ANARIGeometry geometry, ANARIMaterial material)
{
  ANARISurface surface = anariNewSurface(d);
  anariSetParameter(d, surface, "geometry", ANARI_GEOMETRY, &geometry);
  anariSetParameter(d, surface, "material", ANARI_MATERIAL, &material);
  anariCommitParameters(d, surface);
  anariRelease(d, geometry);
  return surface;
}

/* Six geometries in a row along x, each over shared arrays. */
static int addGeometries(
    ANARIDevice d, ANARIMaterial material, int early, ANARISurface *out)
{
  static const float triangle[] = {
      -3.4f, -0.4f, 0, -2.6f, -0.4f, 0, -3, 0.4f, 0};
  static const float triangleUv[] = {0, 0, 1, 0, 0.5f, 1};
  static const uint32_t triangleIndex[] = {0, 1, 2};
  static const float quad[] = {
      -2.2f, -0.4f, 0, -1.4f, -0.4f, 0, -1.4f, 0.4f, 0, -2.2f, 0.4f, 0};
  static const uint32_t quadIndex[] = {0, 1, 2, 3};
  static const float sphere[] = {-0.6f, 0, 0, -0.6f, 0.3f, 0};
  static const float sphereRadius[] = {0.3f, 0.15f};
  static const float cylinder[] = {0.2f, -0.4f, 0, 0.4f, 0.4f, 0};
  static const float cylinderRadius[] = {0.2f};
  static const float cone[] = {1.2f, -0.4f, 0, 1.2f, 0.4f, 0};
  static const float coneRadius[] = {0.35f, 0.05f};
  static const float curve[] = {2.6f, -0.4f, 0, 2.8f, 0, 0, 2.6f, 0.4f, 0};
  static const float curveRadius[] = {0.1f, 0.15f, 0.05f};
  static const uint32_t curveIndex[] = {0, 1};
  const size_t f3 = 3 * sizeof(float), f1 = sizeof(float);
  ANARIGeometry g;
  int n = 0;

  g = anariNewGeometry(d, "triangle");
  setArray(
      d, g, "vertex.position", ANARI_FLOAT32_VEC3, triangle, f3, 3, 1, early);
  setArray(d,
      g,
      "vertex.attribute0",
      ANARI_FLOAT32_VEC2,
      triangleUv,
      2 * f1,
      3,
      1,
      early);
  setArray(d,
      g,
      "primitive.index",
      ANARI_UINT32_VEC3,
      triangleIndex,
      3 * sizeof(uint32_t),
      1,
      1,
      early);
  anariCommitParameters(d, g);
  out[n++] = newSurface(d, g, material);

  g = anariNewGeometry(d, "quad");
  setArray(d, g, "vertex.position", ANARI_FLOAT32_VEC3, quad, f3, 4, 1, early);
  setArray(d,
      g,
      "primitive.index",
      ANARI_UINT32_VEC4,
      quadIndex,
      4 * sizeof(uint32_t),
      1,
      1,
      early);
  anariCommitParameters(d, g);
  out[n++] = newSurface(d, g, material);

  g = anariNewGeometry(d, "sphere");
  setArray(
      d, g, "vertex.position", ANARI_FLOAT32_VEC3, sphere, f3, 2, 1, early);
  setArray(d, g, "vertex.radius", ANARI_FLOAT32, sphereRadius, f1, 2, 1, early);
  anariCommitParameters(d, g);
  out[n++] = newSurface(d, g, material);

  g = anariNewGeometry(d, "cylinder");
  setArray(
      d, g, "vertex.position", ANARI_FLOAT32_VEC3, cylinder, f3, 2, 1, early);
  setArray(
      d, g, "primitive.radius", ANARI_FLOAT32, cylinderRadius, f1, 1, 1, early);
  anariCommitParameters(d, g);
  out[n++] = newSurface(d, g, material);

  g = anariNewGeometry(d, "cone");
  setArray(d, g, "vertex.position", ANARI_FLOAT32_VEC3, cone, f3, 2, 1, early);
  setArray(d, g, "vertex.radius", ANARI_FLOAT32, coneRadius, f1, 2, 1, early);
  anariCommitParameters(d, g);
  out[n++] = newSurface(d, g, material);

  g = anariNewGeometry(d, "curve");
  setArray(d, g, "vertex.position", ANARI_FLOAT32_VEC3, curve, f3, 3, 1, early);
  setArray(d, g, "vertex.radius", ANARI_FLOAT32, curveRadius, f1, 3, 1, early);
  setArray(d,
      g,
      "primitive.index",
      ANARI_UINT32,
      curveIndex,
      sizeof(uint32_t),
      2,
      1,
      early);
  anariCommitParameters(d, g);
  out[n++] = newSurface(d, g, material);
  return n;
}

/* Renders the scene once; returns a malloc'ed SIZE*SIZE RGBA8 image. */
static unsigned char *render(ANARIDevice d, int early)
{
  static const float checker[] = {
      1, 0.2f, 0.2f, 1, 0.2f, 1, 0.2f, 1, 0.2f, 0.2f, 1, 1, 1, 1, 0.2f, 1};
  static const float sky[] = {0.2f,
      0.3f,
      0.9f,
      0.9f,
      0.8f,
      0.6f,
      0.1f,
      0.1f,
      0.1f,
      0.5f,
      0.5f,
      0.5f,
      1,
      1,
      1,
      0.3f,
      0.2f,
      0.1f};
  const float eye[3] = {0, 0, 5}, dir[3] = {0, 0, -1};
  const uint32_t size[2] = {SIZE, SIZE};
  const ANARIDataType format = ANARI_UFIXED8_RGBA_SRGB;
  const int pathLength = 4;
  ANARISurface surfaces[8];
  ANARISampler image = anariNewSampler(d, "image2D");
  ANARIMaterial material = anariNewMaterial(d, "matte");
  ANARILight hdri = anariNewLight(d, "hdri");
  ANARIWorld world = anariNewWorld(d);
  ANARICamera camera = anariNewCamera(d, "perspective");
  ANARIRenderer renderer = anariNewRenderer(d, "pathtracer");
  ANARIFrame frame = anariNewFrame(d);
  unsigned char *out = NULL;
  uint32_t w = 0, h = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const void *pixels;
  int count, i;

  setArray(d,
      image,
      "image",
      ANARI_FLOAT32_VEC4,
      checker,
      4 * sizeof(float),
      2,
      2,
      early);
  anariSetParameter(d, image, "filter", ANARI_STRING, "nearest");
  anariCommitParameters(d, image);
  anariSetParameter(d, material, "color", ANARI_SAMPLER, &image);
  anariCommitParameters(d, material);
  anariRelease(d, image);
  count = addGeometries(d, material, early, surfaces);
  anariRelease(d, material);

  setArray(d,
      hdri,
      "radiance",
      ANARI_FLOAT32_VEC3,
      sky,
      3 * sizeof(float),
      3,
      2,
      early);
  anariCommitParameters(d, hdri);

  /* The object arrays are shared over heap buffers of handles too. */
  setArray(d,
      world,
      "surface",
      ANARI_SURFACE,
      surfaces,
      sizeof(ANARISurface),
      (uint64_t)count,
      1,
      early);
  setArray(
      d, world, "light", ANARI_LIGHT, &hdri, sizeof(ANARILight), 1, 1, early);
  anariCommitParameters(d, world);
  for (i = 0; i < count; i++)
    anariRelease(d, surfaces[i]);
  anariRelease(d, hdri);

  anariSetParameter(d, camera, "position", ANARI_FLOAT32_VEC3, eye);
  anariSetParameter(d, camera, "direction", ANARI_FLOAT32_VEC3, dir);
  anariCommitParameters(d, camera);
  anariSetParameter(d, renderer, "maxPathLength", ANARI_INT32, &pathLength);
  anariCommitParameters(d, renderer);
  anariSetParameter(d, frame, "world", ANARI_WORLD, &world);
  anariSetParameter(d, frame, "camera", ANARI_CAMERA, &camera);
  anariSetParameter(d, frame, "renderer", ANARI_RENDERER, &renderer);
  anariSetParameter(d, frame, "size", ANARI_UINT32_VEC2, size);
  anariSetParameter(d, frame, "channel.color", ANARI_DATA_TYPE, &format);
  anariCommitParameters(d, frame);
  anariRelease(d, world);
  anariRelease(d, camera);
  anariRelease(d, renderer);

  anariRenderFrame(d, frame);
  anariFrameReady(d, frame, ANARI_WAIT);
  pixels = anariMapFrame(d, frame, "channel.color", &w, &h, &type);
  if (pixels && w == SIZE && h == SIZE && type == format) {
    out = (unsigned char *)malloc(SIZE * SIZE * 4);
    memcpy(out, pixels, SIZE * SIZE * 4);
  }
  anariUnmapFrame(d, frame, "channel.color");
  anariRelease(d, frame);
  return out;
}

int main(void)
{
  ANARILibrary library = anariLoadLibrary("prism", onStatus, NULL);
  ANARIDevice device;
  unsigned char *kept, *freed;
  int i, differing = 0, lit = 0;
  if (!library) {
    printf("cannot load the prism library\n");
    return 1;
  }
  device = anariNewDevice(library, "default");
  kept = render(device, 0);
  freed = render(device, 1);
  for (i = 0; i < g_keptCount; i++)
    free(g_kept[i]);
  if (!kept || !freed) {
    printf("a frame could not be mapped\n");
    return 1;
  }
  for (i = 0; i < SIZE * SIZE * 4; i++) {
    differing += kept[i] != freed[i];
    lit += (i % 4) != 3 && kept[i] > 0;
  }
  printf("%d of %d bytes differ; %d color bytes lit\n",
      differing,
      SIZE * SIZE * 4,
      lit);
  free(kept);
  free(freed);
  anariRelease(device, device);
  anariUnloadLibrary(library);
  /* Something must be seen, and the two renders must agree exactly. */
  return differing == 0 && lit > SIZE * SIZE && g_problems == 0 ? 0 : 1;
}
