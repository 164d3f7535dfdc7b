// Ownership as real applications exercise it (spec 3.5, 3.9): shared
// arrays released and freed before rendering, objects released while
// object arrays still name them, reference cycles, handles of another
// device, scenes edited into invalid states, absurd sizes and transforms.
#include "DeviceTestSupport.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <sys/mman.h>

namespace {

constexpr uint32_t kSize = 16;

class DeviceOwnership : public PrismDeviceTest
{
 protected:
  // A triangle covering the image's centre, coloured per vertex, seen by a
  // perspective camera on +z, rendered by `renderer`.
  struct Scene
  {
    ANARIWorld world{nullptr};
    ANARISurface surface{nullptr};
    ANARIGeometry geometry{nullptr};
    ANARIMaterial material{nullptr};
    ANARIArray1D surfaces{nullptr};
  };

  ANARIGeometry newTriangle(bool releaseBuffersEarly)
  {
    auto *positions = new float[9]{-2, -2, 0, 2, -2, 0, 0, 2, 0};
    auto *colors = new float[12]{1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1};
    auto *indices = new uint32_t[3]{0, 1, 2};
    ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
    ANARIArray1D arrays[3] = {
        anariNewArray1D(
            m_device, positions, nullptr, nullptr, ANARI_FLOAT32_VEC3, 3),
        anariNewArray1D(
            m_device, colors, nullptr, nullptr, ANARI_FLOAT32_VEC4, 3),
        anariNewArray1D(
            m_device, indices, nullptr, nullptr, ANARI_UINT32_VEC3, 1)};
    anariSetParameter(
        m_device, geometry, "vertex.position", ANARI_ARRAY1D, &arrays[0]);
    anariSetParameter(
        m_device, geometry, "vertex.color", ANARI_ARRAY1D, &arrays[1]);
    anariSetParameter(
        m_device, geometry, "primitive.index", ANARI_ARRAY1D, &arrays[2]);
    anariCommitParameters(m_device, geometry);
    for (ANARIArray1D array : arrays)
      anariRelease(m_device, array);
    auto scribbleAndFree = [](auto *memory, size_t bytes) {
      // Heap reuse, made certain: what a freed buffer holds is garbage.
      std::memset((void *)memory, 0x7b, bytes);
      delete[] memory;
    };
    if (releaseBuffersEarly) {
      scribbleAndFree(positions, sizeof(float) * 9);
      scribbleAndFree(colors, sizeof(float) * 12);
      scribbleAndFree(indices, sizeof(uint32_t) * 3);
    } else {
      m_kept.emplace_back(positions);
      m_kept.emplace_back(colors);
      m_keptIndices.emplace_back(indices);
    }
    return geometry;
  }

  Scene newScene(ANARIGeometry geometry)
  {
    Scene scene;
    scene.geometry = geometry;
    scene.material = anariNewMaterial(m_device, "matte");
    const char *color = "color";
    anariSetParameter(m_device, scene.material, "color", ANARI_STRING, color);
    anariCommitParameters(m_device, scene.material);
    scene.surface = anariNewSurface(m_device);
    anariSetParameter(
        m_device, scene.surface, "geometry", ANARI_GEOMETRY, &geometry);
    anariSetParameter(
        m_device, scene.surface, "material", ANARI_MATERIAL, &scene.material);
    anariCommitParameters(m_device, scene.surface);
    // A managed object array, written by mapping, as viewers do.
    scene.surfaces =
        anariNewArray1D(m_device, nullptr, nullptr, nullptr, ANARI_SURFACE, 1);
    auto *handles = (ANARISurface *)anariMapArray(m_device, scene.surfaces);
    handles[0] = scene.surface;
    anariUnmapArray(m_device, scene.surfaces);
    scene.world = anariNewWorld(m_device);
    anariSetParameter(
        m_device, scene.world, "surface", ANARI_ARRAY1D, &scene.surfaces);
    anariCommitParameters(m_device, scene.world);
    return scene;
  }

  ANARIFrame newSceneFrame(ANARIWorld world, const char *rendererType)
  {
    ANARIRenderer renderer = anariNewRenderer(m_device, rendererType);
    const float background[4] = {0.25f, 0.25f, 0.25f, 1.f};
    anariSetParameter(
        m_device, renderer, "background", ANARI_FLOAT32_VEC4, background);
    anariCommitParameters(m_device, renderer);
    ANARICamera camera = anariNewCamera(m_device, "perspective");
    const float position[3] = {0, 0, 3}, direction[3] = {0, 0, -1};
    anariSetParameter(
        m_device, camera, "position", ANARI_FLOAT32_VEC3, position);
    anariSetParameter(
        m_device, camera, "direction", ANARI_FLOAT32_VEC3, direction);
    anariCommitParameters(m_device, camera);
    ANARIFrame frame = newFrameOf(world, camera, renderer, kSize, kSize);
    anariRelease(m_device, camera);
    anariRelease(m_device, renderer);
    return frame;
  }

  std::vector<float> render(ANARIFrame frame)
  {
    anariRenderFrame(m_device, frame);
    return colorPixels(frame);
  }

  static const float *centre(const std::vector<float> &image)
  {
    return image.data() + ((kSize / 2) * kSize + kSize / 2) * 4;
  }

  void releaseScene(Scene &scene)
  {
    for (ANARIObject o : {(ANARIObject)scene.world,
             (ANARIObject)scene.surface,
             (ANARIObject)scene.geometry,
             (ANARIObject)scene.material,
             (ANARIObject)scene.surfaces})
      anariRelease(m_device, o);
  }

  std::vector<std::unique_ptr<float[]>> m_kept;
  std::vector<std::unique_ptr<uint32_t[]>> m_keptIndices;
};

// Defect: shared arrays were read after the application released them,
// through the memory it then freed.
TEST_F(DeviceOwnership, SharedArraysReleasedAndFreedRenderAsIfKept)
{
  std::vector<float> images[2];
  for (int early = 0; early < 2; early++) {
    Scene scene = newScene(newTriangle(early == 1));
    ANARIFrame frame = newSceneFrame(scene.world, "raycast");
    images[early] = render(frame);
    anariRelease(m_device, frame);
    releaseScene(scene);
  }
  ASSERT_EQ(images[0].size(), size_t(kSize * kSize * 4));
  EXPECT_EQ(images[0], images[1]);
  // The triangle is there (not the grey background) in both.
  EXPECT_NE(centre(images[1])[0], 0.25f);
  EXPECT_TRUE(problems().empty());
}

// Defect: released after a frame had used it, a shared array's data was
// copied, but a world recommitted alone was rebuilt (Embree reading the
// geometry's vertices in place) before the geometry re-read the copy: the
// build read the memory the application had freed.
TEST_F(DeviceOwnership, SharedVerticesFreedAfterAFrameThenWorldRecommitted)
{
  // Each covers the image's centre.
  // The last two: PRISM_GEOMETRY_POSITION_RADIUS's packed vertices, read
  // in place like positions.
  const struct
  {
    const char *subtype;
    std::vector<float> positions;
    bool packed;
  } shapes[] = {{"triangle", {-1, -1, 0, 1, -1, 0, 0, 1, 0}, false},
      {"cylinder", {-1, 0, 0, 1, 0, 0}, false},
      {"sphere", {0, 0, 0}, false},
      {"sphere", {0, 0, 0, 0.25f}, true},
      {"curve", {-1, 0, 0, 0.25f, 1, 0, 0, 0.25f}, true}};
  for (const auto &[subtype, shape, packed] : shapes) {
    SCOPED_TRACE(std::string(subtype) + (packed ? " packed" : ""));
    // A page of its own, unmapped once released: a read after that faults
    // in any build, not only under AddressSanitizer.
    const size_t bytes = 4096;
    auto *positions = (float *)mmap(nullptr,
        bytes,
        PROT_READ | PROT_WRITE,
        MAP_PRIVATE | MAP_ANONYMOUS,
        -1,
        0);
    ASSERT_NE(positions, MAP_FAILED);
    std::copy(shape.begin(), shape.end(), positions);
    ANARIArray1D array = anariNewArray1D(m_device,
        positions,
        nullptr,
        nullptr,
        packed ? ANARI_FLOAT32_VEC4 : ANARI_FLOAT32_VEC3,
        shape.size() / (packed ? 4 : 3));
    ANARIGeometry geometry = anariNewGeometry(m_device, subtype);
    anariSetParameter(m_device,
        geometry,
        packed ? "vertex.positionRadius" : "vertex.position",
        ANARI_ARRAY1D,
        &array);
    const float radius = 0.25f;
    if (!packed && std::string(subtype) != "triangle")
      anariSetParameter(m_device, geometry, "radius", ANARI_FLOAT32, &radius);
    anariCommitParameters(m_device, geometry);
    Scene scene = newScene(geometry);
    ANARIFrame frame = newSceneFrame(scene.world, "raycast");
    const std::vector<float> before = render(frame);
    anariRelease(m_device, array);
    munmap(positions, bytes);
    anariCommitParameters(m_device, scene.world);
    EXPECT_EQ(render(frame), before);
    EXPECT_NE(centre(before)[0], 0.25f); // something is there to compare
    anariRelease(m_device, frame);
    releaseScene(scene);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(DeviceOwnership, SharedTransformArrayFreedAfterAFrame)
{
  // KHR_INSTANCE_TRANSFORM_ARRAY: the device reads the transforms and ids
  // where the application keeps them; released after a frame and unmapped,
  // they must have been copied first (a read would fault in any build).
  const size_t bytes = 4096;
  auto *page = (unsigned char *)mmap(nullptr,
      bytes,
      PROT_READ | PROT_WRITE,
      MAP_PRIVATE | MAP_ANONYMOUS,
      -1,
      0);
  ASSERT_NE(page, MAP_FAILED);
  // Two placements, half size, left and right of the centre (column-major
  // 4x4), and their ids.
  const float transforms[32] = {0.5f,
      0,
      0,
      0,
      0,
      0.5f,
      0,
      0,
      0,
      0,
      0.5f,
      0,
      -0.6f,
      0,
      0,
      1,
      0.5f,
      0,
      0,
      0,
      0,
      0.5f,
      0,
      0,
      0,
      0,
      0.5f,
      0,
      0.6f,
      0,
      0,
      1};
  const uint32_t ids[2] = {7, 9};
  std::memcpy(page, transforms, sizeof(transforms));
  std::memcpy(page + sizeof(transforms), ids, sizeof(ids));
  ANARIArray1D transformArray =
      anariNewArray1D(m_device, page, nullptr, nullptr, ANARI_FLOAT32_MAT4, 2);
  ANARIArray1D idArray = anariNewArray1D(
      m_device, page + sizeof(transforms), nullptr, nullptr, ANARI_UINT32, 2);
  Scene scene = newScene(newTriangle(false));
  ANARIGroup group = anariNewGroup(m_device);
  anariSetParameter(m_device, group, "surface", ANARI_ARRAY1D, &scene.surfaces);
  anariCommitParameters(m_device, group);
  ANARIInstance instance = anariNewInstance(m_device, "transform");
  anariSetParameter(m_device, instance, "group", ANARI_GROUP, &group);
  anariSetParameter(
      m_device, instance, "transform", ANARI_ARRAY1D, &transformArray);
  anariSetParameter(m_device, instance, "id", ANARI_ARRAY1D, &idArray);
  anariCommitParameters(m_device, instance);
  ANARIArray1D instances =
      anariNewArray1D(m_device, &instance, nullptr, nullptr, ANARI_INSTANCE, 1);
  anariUnsetParameter(m_device, scene.world, "surface");
  anariSetParameter(
      m_device, scene.world, "instance", ANARI_ARRAY1D, &instances);
  anariCommitParameters(m_device, scene.world);
  ANARIFrame frame = newSceneFrame(scene.world, "raycast");
  const std::vector<float> before = render(frame);
  EXPECT_EQ(centre(before)[0], 0.25f) << "nothing at the centre";
  anariRelease(m_device, transformArray);
  anariRelease(m_device, idArray);
  munmap(page, bytes);
  anariCommitParameters(m_device, scene.world);
  EXPECT_EQ(render(frame), before);
  const std::vector<float> image = before;
  EXPECT_NE(image, std::vector<float>(image.size(), image[0]))
      << "the placements are in view";
  for (ANARIObject o : {(ANARIObject)frame,
           (ANARIObject)instances,
           (ANARIObject)instance,
           (ANARIObject)group})
    anariRelease(m_device, o);
  releaseScene(scene);
  EXPECT_TRUE(problems().empty());
}

// Defect: a world kept raw pointers to surfaces named by an object array;
// remapping the array after the surface's release freed the surface.
TEST_F(DeviceOwnership, RemappedObjectArrayKeepsReleasedSurfaces)
{
  Scene scene = newScene(newTriangle(false));
  ANARIFrame frame = newSceneFrame(scene.world, "raycast");
  const std::vector<float> before = render(frame);
  anariRelease(m_device, scene.surface);
  anariRelease(m_device, scene.geometry);
  anariRelease(m_device, scene.material);
  for (int i = 0; i < 2; i++) {
    // Mapped and unmapped, nothing written: the array still holds the
    // surface (its handle is the application's no more, its slot is).
    anariMapArray(m_device, scene.surfaces);
    anariUnmapArray(m_device, scene.surfaces);
    EXPECT_EQ(render(frame), before);
  }
  EXPECT_NE(centre(before)[0], 0.25f);
  anariRelease(m_device, frame);
  anariRelease(m_device, scene.world);
  anariRelease(m_device, scene.surfaces);
  EXPECT_TRUE(problems().empty());
}

// A released handle written into an object array is refused by name.
TEST_F(DeviceOwnership, ReleasedHandleWrittenIntoAnObjectArrayIsReported)
{
  Scene scene = newScene(newTriangle(false));
  ANARISurface other = anariNewSurface(m_device);
  anariRelease(m_device, other);
  auto *handles = (ANARISurface *)anariMapArray(m_device, scene.surfaces);
  handles[0] = other;
  anariUnmapArray(m_device, scene.surfaces);
  EXPECT_TRUE(reported(
      ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_ARGUMENT, "element 0"));
  ANARIFrame frame = newSceneFrame(scene.world, "raycast");
  EXPECT_EQ(centre(render(frame))[0], 0.25f); // nothing left to show
  anariRelease(m_device, frame);
  releaseScene(scene);
}

// Defect: a surface in a group losing its material (unset, or set with a
// wrong type) while only the world was recommitted dereferenced NULL.
TEST_F(DeviceOwnership, SurfaceLosingItsMaterialInAGroupRendersWithout)
{
  for (int how = 0; how < 2; how++) {
    ANARIGeometry geometry = newTriangle(false);
    ANARIMaterial material = anariNewMaterial(m_device, "physicallyBased");
    const float emissive[3] = {1, 1, 1};
    anariSetParameter(
        m_device, material, "emissive", ANARI_FLOAT32_VEC3, emissive);
    anariCommitParameters(m_device, material);
    ANARISurface surface = anariNewSurface(m_device);
    anariSetParameter(m_device, surface, "geometry", ANARI_GEOMETRY, &geometry);
    anariSetParameter(m_device, surface, "material", ANARI_MATERIAL, &material);
    anariCommitParameters(m_device, surface);
    ANARIGroup group = anariNewGroup(m_device);
    ANARIArray1D surfaces =
        anariNewArray1D(m_device, &surface, nullptr, nullptr, ANARI_SURFACE, 1);
    anariSetParameter(m_device, group, "surface", ANARI_ARRAY1D, &surfaces);
    anariCommitParameters(m_device, group);
    ANARIInstance instance = anariNewInstance(m_device, "transform");
    anariSetParameter(m_device, instance, "group", ANARI_GROUP, &group);
    anariCommitParameters(m_device, instance);
    ANARIWorld world = anariNewWorld(m_device);
    ANARIArray1D instances = anariNewArray1D(
        m_device, &instance, nullptr, nullptr, ANARI_INSTANCE, 1);
    anariSetParameter(m_device, world, "instance", ANARI_ARRAY1D, &instances);
    anariCommitParameters(m_device, world);
    ANARIFrame frame = newSceneFrame(world, "pathtracer");
    EXPECT_NE(centre(render(frame))[0], 0.25f);
    if (how == 0) {
      anariUnsetParameter(m_device, surface, "material");
    } else {
      anariSetParameter(
          m_device, surface, "material", ANARI_GEOMETRY, &geometry);
    }
    anariCommitParameters(m_device, surface);
    anariCommitParameters(m_device, world);
    EXPECT_EQ(centre(render(frame))[0], 0.25f); // the surface is gone
    m_status.take();
    for (ANARIObject o : {(ANARIObject)frame,
             (ANARIObject)world,
             (ANARIObject)instances,
             (ANARIObject)instance,
             (ANARIObject)group,
             (ANARIObject)surfaces,
             (ANARIObject)surface,
             (ANARIObject)material,
             (ANARIObject)geometry})
      anariRelease(m_device, o);
  }
}

// Defect: a huge but finite instance transform made rays non-finite inside
// Embree, which aborted the process.
TEST_F(DeviceOwnership, HugeInstanceTransformsNeverReachEmbree)
{
  const float huge[] = {1e30f, 1e20f, -3e38f, 1e-30f, 0.f};
  for (float value : huge) {
    for (int entry : {0, 5, 9, 12}) {
      ANARIGeometry geometry = newTriangle(false);
      Scene scene = newScene(geometry);
      ANARIGroup group = anariNewGroup(m_device);
      anariSetParameter(
          m_device, group, "surface", ANARI_ARRAY1D, &scene.surfaces);
      anariCommitParameters(m_device, group);
      ANARIInstance instance = anariNewInstance(m_device, "transform");
      float transform[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
      transform[entry] = value;
      anariSetParameter(m_device, instance, "group", ANARI_GROUP, &group);
      anariSetParameter(
          m_device, instance, "transform", ANARI_FLOAT32_MAT4, transform);
      anariCommitParameters(m_device, instance);
      ANARIArray1D instances = anariNewArray1D(
          m_device, &instance, nullptr, nullptr, ANARI_INSTANCE, 1);
      ANARIWorld world = anariNewWorld(m_device);
      anariSetParameter(m_device, world, "instance", ANARI_ARRAY1D, &instances);
      anariCommitParameters(m_device, world);
      for (const char *renderer : {"raycast", "pathtracer", "ao", "debug"}) {
        ANARIFrame frame = newSceneFrame(world, renderer);
        EXPECT_EQ(render(frame).size(), size_t(kSize * kSize * 4))
            << renderer << " " << value << " at " << entry;
        anariRelease(m_device, frame);
      }
      for (ANARIObject o : {(ANARIObject)world,
               (ANARIObject)instances,
               (ANARIObject)instance,
               (ANARIObject)group})
        anariRelease(m_device, o);
      releaseScene(scene);
      // Placements that cannot be traced are reported, not rendered: huge
      // entries, and scales so small that the inverse is huge.
      const bool diagonal = entry == 0 || entry == 5;
      const bool untraceable =
          std::abs(value) > 1e18f || (diagonal && std::abs(value) < 1e-18f);
      auto messages = problems();
      EXPECT_EQ(messages.size(), untraceable ? 1u : 0u)
          << value << " at " << entry;
      if (!messages.empty()) {
        EXPECT_NE(messages[0].text.find("transform"), std::string::npos)
            << messages[0].text;
      }
    }
  }
}

// Defect: a frame size the machine cannot hold threw std::bad_alloc out of
// anariRenderFrame and aborted the process.
TEST_F(DeviceOwnership, AbsurdFrameSizeIsOutOfMemoryNotAnAbort)
{
  Scene scene = newScene(newTriangle(false));
  ANARIFrame frame = newSceneFrame(scene.world, "raycast");
  const uint32_t absurd[2] = {100000, 100000};
  anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, absurd);
  anariCommitParameters(m_device, frame);
  anariRenderFrame(m_device, frame);
  EXPECT_EQ(anariFrameReady(m_device, frame, ANARI_WAIT), 1);
  EXPECT_TRUE(reported(
      ANARI_SEVERITY_ERROR, ANARI_STATUS_OUT_OF_MEMORY, "100000x100000"));
  // The device and the frame keep working at a size that fits.
  const uint32_t fits[2] = {kSize, kSize};
  anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, fits);
  anariCommitParameters(m_device, frame);
  EXPECT_NE(centre(render(frame))[0], 0.25f);
  EXPECT_TRUE(problems().empty());
  anariRelease(m_device, frame);
  releaseScene(scene);
}

std::atomic<int> g_deleterCalls{0};
void countDeleter(const void *, const void *)
{
  g_deleterCalls++;
}

// Defect: handles were per-device slot numbers, so one device's handle named
// another device's object in the same slot.
TEST_F(DeviceOwnership, HandlesOfAnotherDeviceAreReportedAsForeign)
{
  ANARIDevice other = anariNewDevice(m_library, "default");
  ASSERT_NE(other, nullptr);
  g_deleterCalls = 0;
  static const float data[3] = {1, 2, 3};
  ANARIArray1D mine =
      anariNewArray1D(m_device, data, countDeleter, nullptr, ANARI_FLOAT32, 3);
  ANARIArray1D theirs =
      anariNewArray1D(other, data, countDeleter, nullptr, ANARI_FLOAT32, 3);
  ASSERT_NE(mine, theirs);
  anariRelease(m_device, theirs); // not this device's: refused
  EXPECT_TRUE(reported(
      ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_ARGUMENT, "another device"));
  anariCommitParameters(m_device, theirs);
  EXPECT_TRUE(reported(
      ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_ARGUMENT, "another device"));
  EXPECT_EQ(anariMapArray(m_device, theirs), nullptr);
  EXPECT_TRUE(reported(
      ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_ARGUMENT, "another device"));
  ANARIGeometry geometry = anariNewGeometry(m_device, "sphere");
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &theirs);
  EXPECT_TRUE(reported(
      ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_ARGUMENT, "another device"));
  EXPECT_EQ(g_deleterCalls, 0); // nobody's array was destroyed
  anariRelease(other, theirs);
  EXPECT_EQ(g_deleterCalls, 1);
  anariRelease(m_device, mine);
  EXPECT_EQ(g_deleterCalls, 2);
  anariRelease(m_device, geometry);
  anariRelease(other, other);
  EXPECT_TRUE(problems().empty());
}

// Defect: reference cycles leaked and their deleters never ran, even at
// device release. Now every object goes at device release, deleters once.
TEST_F(DeviceOwnership, ReferenceCyclesAreFreedAtDeviceRelease)
{
  g_deleterCalls = 0;
  ANARIDevice device = anariNewDevice(m_library, "default");
  // An array of arrays holding itself: its storage is the application's,
  // with a deleter, so the count shows it was destroyed exactly once.
  static ANARIArray1D selfStorage[1];
  ANARIArray1D self = anariNewArray1D(
      device, selfStorage, countDeleter, nullptr, ANARI_ARRAY1D, 1);
  selfStorage[0] = self;
  anariMapArray(device, self);
  anariUnmapArray(device, self);
  anariRelease(device, self);
  // Two arrays holding each other.
  static ANARIArray1D aStorage[1], bStorage[1];
  ANARIArray1D a = anariNewArray1D(
      device, aStorage, countDeleter, nullptr, ANARI_ARRAY1D, 1);
  ANARIArray1D b = anariNewArray1D(
      device, bStorage, countDeleter, nullptr, ANARI_ARRAY1D, 1);
  aStorage[0] = b;
  bStorage[0] = a;
  for (ANARIArray1D array : {a, b}) {
    anariMapArray(device, array);
    anariUnmapArray(device, array);
  }
  anariRelease(device, a);
  anariRelease(device, b);
  // A geometry whose parameter holds an array that holds the geometry.
  static ANARIGeometry geometryStorage[1];
  ANARIGeometry geometry = anariNewGeometry(device, "sphere");
  geometryStorage[0] = geometry;
  ANARIArray1D holder = anariNewArray1D(
      device, geometryStorage, countDeleter, nullptr, ANARI_GEOMETRY, 1);
  anariSetParameter(device, geometry, "primitive.id", ANARI_ARRAY1D, &holder);
  anariCommitParameters(device, geometry);
  anariRelease(device, holder);
  anariRelease(device, geometry);
  EXPECT_EQ(g_deleterCalls, 0); // every cycle still holds itself
  anariRelease(device, device);
  EXPECT_EQ(g_deleterCalls, 4);
}

// Whatever the geometry holds (NaN, infinities, values past Embree's range)
// and wherever the camera is, nothing reaches Embree that it aborts on.
TEST_F(DeviceOwnership, NonFiniteAndHugeGeometryNeverAbort)
{
  const float bad[] = {NAN, INFINITY, -INFINITY, 1e30f, -3e38f, 1e19f};
  const char *subtypes[] = {
      "triangle", "quad", "sphere", "cylinder", "cone", "curve"};
  for (const char *subtype : subtypes) {
    for (float value : bad) {
      // Four points, the first broken; every subtype reads them as its
      // positions (and the sphere/curve radius is broken too).
      float positions[12] = {value, 0, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
      ANARIGeometry geometry = anariNewGeometry(m_device, subtype);
      ANARIArray1D array = anariNewArray1D(
          m_device, positions, nullptr, nullptr, ANARI_FLOAT32_VEC3, 4);
      anariSetParameter(
          m_device, geometry, "vertex.position", ANARI_ARRAY1D, &array);
      anariSetParameter(m_device, geometry, "radius", ANARI_FLOAT32, &value);
      anariCommitParameters(m_device, geometry);
      anariRelease(m_device, array);
      Scene scene = newScene(geometry);
      for (const char *renderer : {"raycast", "pathtracer", "ao", "debug"}) {
        ANARIFrame frame = newSceneFrame(scene.world, renderer);
        EXPECT_EQ(render(frame).size(), size_t(kSize * kSize * 4))
            << subtype << " " << value << " " << renderer;
        anariRelease(m_device, frame);
      }
      releaseScene(scene);
      m_status.take();
    }
  }
}

// A camera anywhere, looking anywhere, renders the background at worst.
TEST_F(DeviceOwnership, CamerasAnywhereNeverAbort)
{
  Scene scene = newScene(newTriangle(false));
  const float bad[] = {NAN, INFINITY, 1e30f, 1e19f, -1e19f, 0.f};
  for (const char *type : {"perspective", "orthographic", "omnidirectional"}) {
    for (float value : bad) {
      ANARIFrame frame = newSceneFrame(scene.world, "pathtracer");
      ANARICamera camera = anariNewCamera(m_device, type);
      const float position[3] = {0, value, 3}, direction[3] = {value, 0, -1};
      anariSetParameter(
          m_device, camera, "position", ANARI_FLOAT32_VEC3, position);
      anariSetParameter(
          m_device, camera, "direction", ANARI_FLOAT32_VEC3, direction);
      anariSetParameter(m_device, camera, "up", ANARI_FLOAT32_VEC3, direction);
      anariCommitParameters(m_device, camera);
      anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &camera);
      anariCommitParameters(m_device, frame);
      anariRelease(m_device, camera);
      anariRenderFrame(m_device, frame);
      EXPECT_EQ(anariFrameReady(m_device, frame, ANARI_WAIT), 1);
      anariRelease(m_device, frame);
      m_status.take();
    }
  }
  releaseScene(scene);
}

} // namespace

// KHR_DEVICE_SYNCHRONIZATION, what the device promises: threads share one
// geometry; each builds its own material, surface, world and frame on it
// and renders while the others do. Calls naming the shared geometry are
// serialized (the application's duty: calls sharing an object must not
// overlap); everything else runs at once. The threads hold the only
// public references, so the last one is dropped by whichever finishes
// last, while the others' frames may still hold the geometry inside the
// device. Every frame shows the triangle, nothing is reported, and the
// sanitizer builds check the memory.
TEST_F(DeviceOwnership, SharedObjectsUsedAndReleasedFromManyThreads)
{
  constexpr int kThreads = 4, kFramesEach = 10;
  ANARIGeometry geometry = newTriangle(false);
  for (int t = 0; t < kThreads; ++t)
    anariRetain(m_device, geometry);
  anariRelease(m_device, geometry);
  std::mutex geometryCalls;
  std::atomic<int> framesShowingIt{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < kFramesEach; ++i) {
        Scene scene;
        {
          std::lock_guard lock(geometryCalls);
          anariRetain(m_device, geometry); // releaseScene releases it
          scene = newScene(geometry);
        }
        ANARIFrame frame = newSceneFrame(scene.world, "raycast");
        const std::vector<float> image = render(frame);
        if (image.size() == size_t(kSize) * kSize * 4) {
          const float *pixel = centre(image);
          framesShowingIt +=
              pixel[0] != 0.25f || pixel[1] != 0.25f || pixel[2] != 0.25f;
        }
        anariRelease(m_device, frame);
        std::lock_guard lock(geometryCalls);
        releaseScene(scene);
      }
      std::lock_guard lock(geometryCalls);
      anariRelease(m_device, geometry);
    });
  }
  for (auto &thread : threads)
    thread.join();
  EXPECT_EQ(framesShowingIt, kThreads * kFramesEach);
  EXPECT_TRUE(problems().empty());
}
