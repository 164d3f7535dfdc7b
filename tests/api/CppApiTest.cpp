// The C++ wrappers of anari_cpp.hpp reach the device through libanari with
// the types, names, pointers and sizes the matching C calls would carry.
#include "StatusRecorder.h"

#include <anari/anari_cpp/ext/std.h>
#include <anari/anari_cpp.hpp>

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

// An application math type, mapped the way SDK users map glm types.
struct AppVec3
{
  float x, y, z;
};

namespace anari {
ANARI_TYPEFOR_SPECIALIZATION(AppVec3, ANARI_FLOAT32_VEC3);
ANARI_TYPEFOR_DEFINITION(AppVec3);
} // namespace anari

namespace {

// What the recording device logged for each traced C call, in order.
std::vector<std::string> g_trace;
const char *(*g_lastCall)(void) = nullptr;
// The bytes anariSetParameter last received (the text for ANARI_STRING).
std::string g_setValue;
// What the last traced map call handed out.
void *g_mapped = nullptr;

template <typename F>
F libanariDefinition(F, const char *name)
{
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

void traceLastCall()
{
  if (g_lastCall)
    g_trace.push_back(g_lastCall());
}

} // namespace

// One C++ call makes several C calls but the device remembers only the last,
// so these stand in front of libanari's entry points and log each step.
extern "C" {

ANARIArray1D anariNewArray1D(ANARIDevice device,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType dataType,
    uint64_t numElements1)
{
  static const auto next =
      libanariDefinition(&anariNewArray1D, "anariNewArray1D");
  auto array =
      next(device, appMemory, deleter, userData, dataType, numElements1);
  traceLastCall();
  return array;
}

ANARIArray2D anariNewArray2D(ANARIDevice device,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t numElements2)
{
  static const auto next =
      libanariDefinition(&anariNewArray2D, "anariNewArray2D");
  auto array = next(device,
      appMemory,
      deleter,
      userData,
      dataType,
      numElements1,
      numElements2);
  traceLastCall();
  return array;
}

ANARIArray3D anariNewArray3D(ANARIDevice device,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3)
{
  static const auto next =
      libanariDefinition(&anariNewArray3D, "anariNewArray3D");
  auto array = next(device,
      appMemory,
      deleter,
      userData,
      dataType,
      numElements1,
      numElements2,
      numElements3);
  traceLastCall();
  return array;
}

void *anariMapArray(ANARIDevice device, ANARIArray array)
{
  static const auto next = libanariDefinition(&anariMapArray, "anariMapArray");
  g_mapped = next(device, array);
  traceLastCall();
  return g_mapped;
}

void anariSetParameter(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType dataType,
    const void *mem)
{
  static const auto next =
      libanariDefinition(&anariSetParameter, "anariSetParameter");
  if (dataType == ANARI_STRING)
    g_setValue = mem ? (const char *)mem : "(null)";
  else if (dataType == ANARI_VOID_POINTER || !mem)
    g_setValue.clear();
  else
    g_setValue.assign((const char *)mem, anari::sizeOf(dataType));
  next(device, object, name, dataType, mem);
  traceLastCall();
}

void *anariMapParameterArray1D(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t *elementStride)
{
  static const auto next =
      libanariDefinition(&anariMapParameterArray1D, "anariMapParameterArray1D");
  g_mapped = next(device, object, name, dataType, numElements1, elementStride);
  traceLastCall();
  return g_mapped;
}

void *anariMapParameterArray2D(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t *elementStride)
{
  static const auto next =
      libanariDefinition(&anariMapParameterArray2D, "anariMapParameterArray2D");
  g_mapped = next(device,
      object,
      name,
      dataType,
      numElements1,
      numElements2,
      elementStride);
  traceLastCall();
  return g_mapped;
}

void *anariMapParameterArray3D(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3,
    uint64_t *elementStride)
{
  static const auto next =
      libanariDefinition(&anariMapParameterArray3D, "anariMapParameterArray3D");
  g_mapped = next(device,
      object,
      name,
      dataType,
      numElements1,
      numElements2,
      numElements3,
      elementStride);
  traceLastCall();
  return g_mapped;
}

} // extern "C"

namespace {

// The recording device's fake handles.
const auto kArray1D = (anari::Array1D)0x1001;
const auto kArray2D = (anari::Array2D)0x1002;
const auto kGeometry = (anari::Geometry)0x1004;
const auto kSampler = (anari::Sampler)0x1006;
const auto kSurface = (anari::Surface)0x1007;
const auto kSpatialField = (anari::SpatialField)0x1008;
const auto kWorld = (anari::World)0x100d;
const auto kFrame = (anari::Frame)0x1010;

std::string ptr(const void *p)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%p", p);
  return buffer;
}

template <typename T>
std::string bytesOf(const T &value)
{
  return std::string((const char *)&value, sizeof(T));
}

bool startsWith(const std::string &s, const std::string &prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string &s, const std::string &suffix)
{
  return s.size() >= suffix.size()
         && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void statusFunction(const void *,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity,
    ANARIStatusCode,
    const char *)
{}

void deleterFunction(const void *, const void *) {}

void frameDone(const void *, ANARIDevice, ANARIFrame) {}

class CppApi : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    m_library =
        anari::loadLibrary("recording", StatusRecorder::callback, &m_status);
    ASSERT_NE(m_library, nullptr);
    m_device = anari::newDevice(m_library);
    ASSERT_NE(m_device, nullptr);
    g_lastCall = (const char *(*)(void))anariDeviceGetProcAddress(
        m_device, "recordingLastCall");
    ASSERT_NE(g_lastCall, nullptr);
    g_trace.clear();
    g_setValue.clear();
    g_mapped = nullptr;
  }
  void TearDown() override
  {
    g_lastCall = nullptr;
    anari::release(m_device, m_device);
    anari::unloadLibrary(m_library);
    EXPECT_TRUE(m_status.take().empty());
  }

  std::string last() const
  {
    return g_lastCall();
  }
  std::string setRecord(
      const void *object, const char *name, int type, const void *mem) const
  {
    return "setParameter(" + ptr(object) + ", " + name + ", "
           + std::to_string(type) + ", " + ptr(mem) + ")";
  }

  // Sets `value` as a parameter of kGeometry; checks type, address, bytes.
  template <typename T>
  void expectSet(const char *name, const T &value, int type)
  {
    SCOPED_TRACE(name);
    anari::setParameter(m_device, kGeometry, name, value);
    EXPECT_EQ(last(), setRecord(kGeometry, name, type, &value));
    EXPECT_EQ(g_setValue, bytesOf(value));
  }

  StatusRecorder m_status;
  anari::Library m_library{nullptr};
  anari::Device m_device{nullptr};
};

TEST_F(CppApi, LibrariesModulesAndDevices)
{
  anari::loadModule(m_library, "extras");
  EXPECT_EQ(last(), "loadModule(extras)");
  anari::unloadModule(m_library, "extras");
  EXPECT_EQ(last(), "unloadModule(extras)");

  auto liveDevices = (int (*)(void))anariDeviceGetProcAddress(
      m_device, "recordingLiveDevices");
  ASSERT_NE(liveDevices, nullptr);
  anari::Device second = anari::newDevice(m_library, "second");
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(liveDevices(), 2);
  anari::retain(second, second);
  EXPECT_EQ(last(), "retain(" + ptr(second) + ")");
  anari::release(second, second);
  EXPECT_EQ(last(), "release(" + ptr(second) + ")");
  EXPECT_EQ(liveDevices(), 2);
  anari::release(second, second);
  EXPECT_EQ(liveDevices(), 1);
}

TEST_F(CppApi, NewObjectCreatesEveryObjectType)
{
  auto d = m_device;
  EXPECT_EQ(anari::newObject<anari::Geometry>(d, "triangle"), kGeometry);
  EXPECT_EQ(last(), "newGeometry(triangle)");
  EXPECT_EQ(
      anari::newObject<anari::Material>(d, "matte"), (anari::Material)0x1005);
  EXPECT_EQ(last(), "newMaterial(matte)");
  EXPECT_EQ(anari::newObject<anari::Sampler>(d, "image2D"), kSampler);
  EXPECT_EQ(last(), "newSampler(image2D)");
  EXPECT_EQ(anari::newObject<anari::Surface>(d), kSurface);
  EXPECT_EQ(last(), "newSurface()");
  EXPECT_EQ(anari::newObject<anari::SpatialField>(d, "structuredRegular"),
      kSpatialField);
  EXPECT_EQ(last(), "newSpatialField(structuredRegular)");
  EXPECT_EQ(anari::newObject<anari::Volume>(d, "transferFunction1D"),
      (anari::Volume)0x1009);
  EXPECT_EQ(last(), "newVolume(transferFunction1D)");
  EXPECT_EQ(
      anari::newObject<anari::Light>(d, "directional"), (anari::Light)0x100a);
  EXPECT_EQ(last(), "newLight(directional)");
  EXPECT_EQ(anari::newObject<anari::Group>(d), (anari::Group)0x100b);
  EXPECT_EQ(last(), "newGroup()");
  EXPECT_EQ(anari::newObject<anari::Instance>(d, "transform"),
      (anari::Instance)0x100c);
  EXPECT_EQ(last(), "newInstance(transform)");
  EXPECT_EQ(anari::newObject<anari::World>(d), kWorld);
  EXPECT_EQ(last(), "newWorld()");
  EXPECT_EQ(
      anari::newObject<anari::Camera>(d, "perspective"), (anari::Camera)0x100e);
  EXPECT_EQ(last(), "newCamera(perspective)");
  EXPECT_EQ(
      anari::newObject<anari::Renderer>(d, "default"), (anari::Renderer)0x100f);
  EXPECT_EQ(last(), "newRenderer(default)");
  EXPECT_EQ(anari::newObject<anari::Frame>(d), kFrame);
  EXPECT_EQ(last(), "newFrame()");
  EXPECT_EQ(anari::newObject(d, "extension", "custom"), (anari::Object)0x1011);
  EXPECT_EQ(last(), "newObject(extension, custom)");
}

TEST_F(CppApi, TypedArraysWithoutDeleterCopyIntoManagedArrays)
{
  const float values[5] = {1.f, 2.f, 3.f, 4.f, 5.f};
  EXPECT_EQ(anari::newArray1D(m_device, values, 5), kArray1D);
  EXPECT_EQ(g_trace,
      (std::vector<std::string>{
          "newArray1D((nil), (nil), (nil), 1068, 5)", "mapArray(0x1001)"}));
  EXPECT_EQ(last(), "unmapArray(0x1001)");
  EXPECT_EQ(std::memcmp(g_mapped, values, sizeof(values)), 0);

  g_trace.clear();
  const int32_t single = -9;
  anari::newArray1D(m_device, &single);
  EXPECT_EQ(g_trace.at(0), "newArray1D((nil), (nil), (nil), 1016, 1)");
  EXPECT_EQ(std::memcmp(g_mapped, &single, sizeof(single)), 0);

  g_trace.clear();
  const uint8_t pixels[6] = {1, 2, 3, 4, 5, 6};
  EXPECT_EQ(anari::newArray2D(m_device, pixels, 3, 2), kArray2D);
  EXPECT_EQ(g_trace,
      (std::vector<std::string>{
          "newArray2D((nil), (nil), (nil), 1004, 3, 2)", "mapArray(0x1002)"}));
  EXPECT_EQ(last(), "unmapArray(0x1002)");
  EXPECT_EQ(std::memcmp(g_mapped, pixels, sizeof(pixels)), 0);

  g_trace.clear();
  const anari::std_types::vec2 cells[8] = {{0.f, 1.f},
      {2.f, 3.f},
      {4.f, 5.f},
      {6.f, 7.f},
      {8.f, 9.f},
      {10.f, 11.f},
      {12.f, 13.f},
      {14.f, 15.f}};
  EXPECT_EQ(
      anari::newArray3D(m_device, cells, 2, 2, 2), (anari::Array3D)0x1003);
  EXPECT_EQ(g_trace,
      (std::vector<std::string>{
          "newArray3D((nil), (nil), (nil), 1069, 2, 2, 2)",
          "mapArray(0x1003)"}));
  EXPECT_EQ(last(), "unmapArray(0x1003)");
  EXPECT_EQ(std::memcmp(g_mapped, cells, sizeof(cells)), 0);

  g_trace.clear();
  const anari::Surface surfaces[2] = {kSurface, (anari::Surface)0x2007};
  anari::newArray1D(m_device, surfaces, 2);
  EXPECT_EQ(g_trace.at(0), "newArray1D((nil), (nil), (nil), 515, 2)");
  EXPECT_EQ(std::memcmp(g_mapped, surfaces, sizeof(surfaces)), 0);
}

TEST_F(CppApi, ArraysWithDeleterShareTheCallersMemory)
{
  const float values[4] = {};
  const void *user = (const void *)0x77;
  const std::string del = ptr((const void *)&deleterFunction);
  anari::newArray1D(m_device, values, deleterFunction, user, 4);
  EXPECT_EQ(last(),
      "newArray1D(" + ptr(values) + ", " + del + ", " + ptr(user)
          + ", 1068, 4)");
  anari::newArray2D(m_device, values, deleterFunction, user, 2, 2);
  EXPECT_EQ(last(),
      "newArray2D(" + ptr(values) + ", " + del + ", " + ptr(user)
          + ", 1068, 2, 2)");
  anari::newArray3D(m_device, values, deleterFunction, user, 1, 2, 2);
  EXPECT_EQ(last(),
      "newArray3D(" + ptr(values) + ", " + del + ", " + ptr(user)
          + ", 1068, 1, 2, 2)");
  // Nothing was mapped: the device got the caller's pointer.
  EXPECT_EQ(g_trace.size(), 3u);
  EXPECT_EQ(g_mapped, nullptr);

  anari::newArray1D(
      m_device, (const void *)values, deleterFunction, user, ANARI_UINT8, 16);
  EXPECT_EQ(last(),
      "newArray1D(" + ptr(values) + ", " + del + ", " + ptr(user)
          + ", 1004, 16)");
  anari::newArray2D(
      m_device, (const void *)values, nullptr, nullptr, ANARI_UINT16, 4, 2);
  EXPECT_EQ(
      last(), "newArray2D(" + ptr(values) + ", (nil), (nil), 1012, 4, 2)");
  anari::newArray3D(m_device,
      (const void *)values,
      deleterFunction,
      nullptr,
      ANARI_FLOAT32,
      1,
      1,
      4);
  EXPECT_EQ(last(),
      "newArray3D(" + ptr(values) + ", " + del + ", (nil), 1068, 1, 1, 4)");
}

TEST_F(CppApi, UntypedArraysAreManaged)
{
  EXPECT_EQ(anari::newArray1D(m_device, ANARI_FLOAT32_VEC3, 7), kArray1D);
  EXPECT_EQ(last(), "newArray1D((nil), (nil), (nil), 1070, 7)");
  EXPECT_EQ(
      anari::newArray2D(m_device, ANARI_UFIXED8_VEC4, 640, 480), kArray2D);
  EXPECT_EQ(last(), "newArray2D((nil), (nil), (nil), 1039, 640, 480)");
  anari::newArray3D(m_device, ANARI_FLOAT64, 1ull << 33, 2, 9);
  EXPECT_EQ(last(), "newArray3D((nil), (nil), (nil), 1072, 8589934592, 2, 9)");
  // Untyped creation maps nothing.
  EXPECT_EQ(g_trace.size(), 3u);
}

TEST_F(CppApi, MapAndUnmapArrays)
{
  float *values = anari::map<float>(m_device, kArray1D);
  EXPECT_EQ(last(), "mapArray(0x1001)");
  EXPECT_NE(values, nullptr);
  EXPECT_EQ((void *)values, g_mapped);
  anari::unmap(m_device, kArray1D);
  EXPECT_EQ(last(), "unmapArray(0x1001)");

  EXPECT_NE(anari::map<uint8_t>(m_device, kArray2D), nullptr);
  EXPECT_EQ(last(), "mapArray(0x1002)");
  anari::unmap(m_device, kArray2D);
  EXPECT_EQ(last(), "unmapArray(0x1002)");
}

TEST_F(CppApi, ScalarParametersCarryTheirType)
{
  anari::setParameter(m_device, kGeometry, "x", 2.f);
  EXPECT_EQ(last(), "setParameter(0x1004, x, 1068, 2)");
  const float half = 0.5f;
  anari::setParameter(m_device, kGeometry, "half", half);
  EXPECT_EQ(last(), "setParameter(0x1004, half, 1068, 0.5)");

  expectSet("i8", int8_t(-3), 1000);
  expectSet("u8", uint8_t(200), 1004);
  expectSet("i16", int16_t(-300), 1008);
  expectSet("u16", uint16_t(60000), 1012);
  expectSet("i32", int32_t(-70000), 1016);
  expectSet("u32", uint32_t(4000000000u), 1020);
  expectSet("i64", int64_t(-(1ll << 40)), 1024);
  expectSet("u64", uint64_t(1ull << 63), 1028);
  expectSet("ll", -5ll, 1024);
  expectSet("ull", 5ull, 1028);
  expectSet("size", sizeof(double), 1028);
  expectSet("f64", 0.25, 1072);

  int plain = 42;
  anari::setParameter(m_device, kGeometry, "plain", plain);
  EXPECT_EQ(last(), setRecord(kGeometry, "plain", 1016, &plain));
  EXPECT_EQ(g_setValue, bytesOf(plain));
}

TEST_F(CppApi, VectorParametersFromArraysAndAppTypes)
{
  const std::array<float, 3> direction{0.f, -1.f, 0.f};
  expectSet("direction", direction, 1070);
  expectSet("v2", std::array<float, 2>{1.f, 2.f}, 1069);
  expectSet("v4", std::array<float, 4>{1.f, 2.f, 3.f, 4.f}, 1071);
  expectSet("iv2", anari::std_types::ivec2{-1, 1}, 1017);
  expectSet("iv3", anari::std_types::ivec3{-1, 1, 2}, 1018);
  expectSet("uv4", anari::std_types::uvec4{1u, 2u, 3u, 4u}, 1023);
  expectSet("dv3", std::array<double, 3>{1.0, 2.0, 3.0}, 1074);
  expectSet("u8v4", std::array<uint8_t, 4>{1, 2, 3, 4}, 1007);
  expectSet(
      "box", anari::std_types::box3{{{0.f, 0.f, 0.f}, {1.f, 1.f, 1.f}}}, 2010);
  expectSet("transform",
      anari::std_types::mat4{{{1.f, 0.f, 0.f, 0.f},
          {0.f, 1.f, 0.f, 0.f},
          {0.f, 0.f, 1.f, 0.f},
          {0.f, 0.f, 0.f, 1.f}}},
      2014);
  expectSet("app", AppVec3{1.f, 2.f, 3.f}, 1070);

  float color[3] = {0.8f, 0.1f, 0.1f};
  anari::setParameter(m_device, kGeometry, "color", color);
  EXPECT_EQ(last(), setRecord(kGeometry, "color", 1070, color));
  EXPECT_EQ(g_setValue, bytesOf(color));

  // A temporary still arrives with its type and bytes.
  anari::setParameter(
      m_device, kGeometry, "temp", std::array<int, 4>{5, 6, 7, 8});
  EXPECT_TRUE(startsWith(last(), "setParameter(0x1004, temp, 1019, 0x"));
  EXPECT_EQ(g_setValue, bytesOf(std::array<int, 4>{5, 6, 7, 8}));
}

TEST_F(CppApi, StringParametersPassTheCharacters)
{
  const char *name = "hello";
  anari::setParameter(m_device, kGeometry, "name", name);
  EXPECT_EQ(last(), setRecord(kGeometry, "name", 101, name));
  EXPECT_EQ(g_setValue, "hello");

  static const char literal[] = "literal";
  anari::setParameter(m_device, kGeometry, "name", literal);
  EXPECT_EQ(last(), setRecord(kGeometry, "name", 101, literal));
  EXPECT_EQ(g_setValue, "literal");

  anari::setParameter(m_device, kGeometry, "name", "inline literal");
  EXPECT_EQ(g_setValue, "inline literal");

  char buffer[] = "mutable";
  char *mutableName = buffer;
  anari::setParameter(m_device, kGeometry, "name", mutableName);
  EXPECT_EQ(last(), setRecord(kGeometry, "name", 101, buffer));

  const std::string text = "from std::string";
  anari::setParameter(m_device, kGeometry, "name", text);
  EXPECT_TRUE(startsWith(last(), "setParameter(0x1004, name, 101, 0x"));
  EXPECT_EQ(g_setValue, "from std::string");
  anari::setParameter(m_device, kGeometry, "name", std::string("temporary"));
  EXPECT_EQ(g_setValue, "temporary");
}

TEST_F(CppApi, ObjectParametersPassTheHandle)
{
  anari::Geometry geometry = kGeometry;
  anari::setParameter(m_device, kSurface, "geometry", geometry);
  EXPECT_EQ(last(), setRecord(kSurface, "geometry", 509, &geometry));
  EXPECT_EQ(g_setValue, bytesOf(geometry));

  const anari::Array1D surfaces = kArray1D;
  anari::setParameter(m_device, kWorld, "surface", surfaces);
  EXPECT_EQ(last(), setRecord(kWorld, "surface", 504, &surfaces));
  EXPECT_EQ(g_setValue, bytesOf(surfaces));

  anari::World world = kWorld;
  anari::setParameter(m_device, kFrame, "world", world);
  EXPECT_EQ(last(), setRecord(kFrame, "world", 519, &world));

  anari::Object generic = (anari::Object)kSampler;
  anari::setParameter(m_device, kGeometry, "any", generic);
  EXPECT_EQ(last(), setRecord(kGeometry, "any", 502, &generic));
}

TEST_F(CppApi, BoolAndExplicitlyTypedParameters)
{
  anari::setParameter(m_device, kGeometry, "flag", true);
  EXPECT_TRUE(startsWith(last(), "setParameter(0x1004, flag, 103, 0x"));
  EXPECT_EQ(g_setValue, std::string(1, '\1'));
  bool off = false;
  anari::setParameter(m_device, kGeometry, "flag", off);
  EXPECT_EQ(g_setValue, std::string(1, '\0'));

  const float value = 4.5f;
  anari::setParameter(m_device, kGeometry, "x", ANARI_FLOAT32, &value);
  EXPECT_EQ(last(), "setParameter(0x1004, x, 1068, 4.5)");
  const uint8_t rgba[4] = {1, 2, 3, 4};
  anari::setParameter(m_device, kGeometry, "rgba", ANARI_UFIXED8_VEC4, rgba);
  EXPECT_EQ(last(), setRecord(kGeometry, "rgba", 1039, rgba));
  EXPECT_EQ(g_setValue, bytesOf(rgba));

  uint32_t count = 12;
  anari::setParameterAs(m_device, kGeometry, "count", ANARI_INT32, count);
  EXPECT_EQ(last(), setRecord(kGeometry, "count", 1016, &count));

  // A DataType value is itself a parameter (e.g. a frame channel format).
  anari::setParameter(
      m_device, kFrame, "channel.color", ANARI_UFIXED8_RGBA_SRGB);
  EXPECT_TRUE(
      startsWith(last(), "setParameter(0x1010, channel.color, 100, 0x"));
  EXPECT_EQ(g_setValue, bytesOf(int32_t(2003)));
}

TEST_F(CppApi, PointerAndCallbackParameters)
{
  int target = 0;
  void *pointer = &target;
  anari::setParameter(m_device, kGeometry, "user", pointer);
  EXPECT_EQ(last(), setRecord(kGeometry, "user", 102, &target));
  const void *constPointer = &target;
  anari::setParameter(m_device, kGeometry, "user", constPointer);
  EXPECT_EQ(last(), setRecord(kGeometry, "user", 102, &target));

  anari::StatusCallback status = statusFunction;
  anari::setParameter(m_device, m_device, "statusCallback", status);
  EXPECT_EQ(last(), setRecord(m_device, "statusCallback", 202, &status));
  EXPECT_EQ(g_setValue, bytesOf(status));
  // A function named directly goes as a pointer to it.
  anari::setParameter(m_device, m_device, "statusCallback", statusFunction);
  EXPECT_TRUE(startsWith(
      last(), "setParameter(" + ptr(m_device) + ", statusCallback, 202, 0x"));
  EXPECT_EQ(g_setValue, bytesOf(status));

  anari::MemoryDeleter deleter = deleterFunction;
  anari::setParameter(m_device, kGeometry, "deleter", deleter);
  EXPECT_EQ(last(), setRecord(kGeometry, "deleter", 201, &deleter));

  anari::FrameCompletionCallback done = frameDone;
  anari::setParameter(m_device, kFrame, "frameCompletionCallback", done);
  EXPECT_EQ(last(), setRecord(kFrame, "frameCompletionCallback", 203, &done));
  EXPECT_EQ(g_setValue, bytesOf(done));
}

TEST_F(CppApi, ParameterAndObjectLifetime)
{
  anari::unsetParameter(m_device, kGeometry, "x");
  EXPECT_EQ(last(), "unsetParameter(0x1004, x)");
  anari::unsetAllParameters(m_device, kGeometry);
  EXPECT_EQ(last(), "unsetAllParameters(0x1004)");
  anari::commitParameters(m_device, kGeometry);
  EXPECT_EQ(last(), "commitParameters(0x1004)");
  anari::retain(m_device, kGeometry);
  EXPECT_EQ(last(), "retain(0x1004)");
  anari::release(m_device, kGeometry);
  EXPECT_EQ(last(), "release(0x1004)");

  g_trace.clear();
  const anari::Geometry geometry = kGeometry;
  anari::setAndReleaseParameter(m_device, kSurface, "geometry", geometry);
  EXPECT_EQ(g_trace,
      (std::vector<std::string>{
          setRecord(kSurface, "geometry", 509, &geometry)}));
  EXPECT_EQ(last(), "release(0x1004)");
}

TEST_F(CppApi, ParameterArraysAreWrittenIntoMappedMemory)
{
  const anari::std_types::uvec3 triangles[2] = {{0, 1, 2}, {2, 1, 3}};
  anari::setParameterArray1D(
      m_device, kGeometry, "primitive.index", triangles, 2);
  ASSERT_EQ(g_trace.size(), 1u);
  EXPECT_TRUE(startsWith(
      g_trace[0], "mapParameterArray1D(0x1004, primitive.index, 1022, 2, 0x"));
  EXPECT_EQ(last(), "unmapParameterArray(0x1004, primitive.index)");
  EXPECT_EQ(std::memcmp(g_mapped, triangles, sizeof(triangles)), 0);

  g_trace.clear();
  const float radii[3] = {0.1f, 0.2f, 0.3f};
  anari::setParameterArray1D(
      m_device, kGeometry, "vertex.radius", ANARI_FLOAT32, radii, 3);
  ASSERT_EQ(g_trace.size(), 1u);
  EXPECT_TRUE(startsWith(
      g_trace[0], "mapParameterArray1D(0x1004, vertex.radius, 1068, 3, 0x"));
  EXPECT_EQ(last(), "unmapParameterArray(0x1004, vertex.radius)");
  EXPECT_EQ(std::memcmp(g_mapped, radii, sizeof(radii)), 0);

  // Interleaved input: only the positions land, packed.
  struct Vertex
  {
    float position[3];
    uint32_t id;
  };
  const Vertex vertices[3] = {
      {{1.f, 2.f, 3.f}, 7}, {{4.f, 5.f, 6.f}, 8}, {{7.f, 8.f, 9.f}, 9}};
  g_trace.clear();
  anari::setParameterArray1DStrided(m_device,
      kGeometry,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      vertices,
      3,
      sizeof(Vertex));
  ASSERT_EQ(g_trace.size(), 1u);
  EXPECT_TRUE(startsWith(
      g_trace[0], "mapParameterArray1D(0x1004, vertex.position, 1070, 3, 0x"));
  EXPECT_EQ(last(), "unmapParameterArray(0x1004, vertex.position)");
  const float packed[9] = {1.f, 2.f, 3.f, 4.f, 5.f, 6.f, 7.f, 8.f, 9.f};
  EXPECT_EQ(std::memcmp(g_mapped, packed, sizeof(packed)), 0);

  g_trace.clear();
  const float image[2][3] = {{1.f, 2.f, 3.f}, {4.f, 5.f, 6.f}};
  anari::setParameterArray2D(m_device, kSampler, "image", &image[0][0], 3, 2);
  ASSERT_EQ(g_trace.size(), 1u);
  EXPECT_TRUE(startsWith(
      g_trace[0], "mapParameterArray2D(0x1006, image, 1068, 3, 2, 0x"));
  EXPECT_EQ(last(), "unmapParameterArray(0x1006, image)");
  EXPECT_EQ(std::memcmp(g_mapped, image, sizeof(image)), 0);

  g_trace.clear();
  const uint8_t texels[16] = {
      1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  anari::setParameterArray2D(
      m_device, kSampler, "image", ANARI_UFIXED8_VEC4, texels, 2, 2);
  ASSERT_EQ(g_trace.size(), 1u);
  EXPECT_TRUE(startsWith(
      g_trace[0], "mapParameterArray2D(0x1006, image, 1039, 2, 2, 0x"));
  EXPECT_EQ(std::memcmp(g_mapped, texels, sizeof(texels)), 0);

  g_trace.clear();
  const float voxels[8] = {0.f, 1.f, 2.f, 3.f, 4.f, 5.f, 6.f, 7.f};
  anari::setParameterArray3D(m_device, kSpatialField, "data", voxels, 2, 2, 2);
  ASSERT_EQ(g_trace.size(), 1u);
  EXPECT_TRUE(startsWith(
      g_trace[0], "mapParameterArray3D(0x1008, data, 1068, 2, 2, 2, 0x"));
  EXPECT_EQ(last(), "unmapParameterArray(0x1008, data)");
  EXPECT_EQ(std::memcmp(g_mapped, voxels, sizeof(voxels)), 0);

  g_trace.clear();
  const uint8_t mask[12] = {1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0};
  anari::setParameterArray3D(
      m_device, kSpatialField, "mask", ANARI_UINT8, mask, 3, 2, 2);
  ASSERT_EQ(g_trace.size(), 1u);
  EXPECT_TRUE(startsWith(
      g_trace[0], "mapParameterArray3D(0x1008, mask, 1004, 3, 2, 2, 0x"));
  EXPECT_EQ(std::memcmp(g_mapped, mask, sizeof(mask)), 0);
}

TEST_F(CppApi, PropertiesAreQueriedWithTypeAndSize)
{
  int32_t count = 0;
  EXPECT_TRUE(anari::getProperty(m_device, kGeometry, "count", count));
  EXPECT_EQ(
      last(), "getProperty(0x1004, count, 1016, " + ptr(&count) + ", 4, 1)");

  float duration = 0.f;
  EXPECT_TRUE(anari::getProperty(
      m_device, kFrame, "duration", duration, ANARI_NO_WAIT));
  EXPECT_EQ(last(),
      "getProperty(0x1010, duration, 1068, " + ptr(&duration) + ", 4, 0)");

  anari::std_types::box3 bounds{};
  EXPECT_TRUE(anari::getProperty(m_device, kWorld, "bounds", bounds));
  EXPECT_EQ(
      last(), "getProperty(0x100d, bounds, 2010, " + ptr(&bounds) + ", 24, 1)");

  const char *name = nullptr;
  EXPECT_TRUE(anari::getProperty(m_device, m_device, "version.name", name));
  EXPECT_EQ(last(),
      "getProperty(" + ptr(m_device) + ", version.name, 101, " + ptr(&name)
          + ", 8, 1)");

  const char **extensions = nullptr;
  EXPECT_TRUE(anari::getProperty(m_device, m_device, "extension", extensions));
  EXPECT_EQ(last(),
      "getProperty(" + ptr(m_device) + ", extension, 150, " + ptr(&extensions)
          + ", 8, 1)");

  // bool travels as 32 bits; the device wrote none, so the zero comes back.
  bool ready = true;
  EXPECT_TRUE(anari::getProperty<bool>(
      m_device, kFrame, "ready", ready, ANARI_NO_WAIT));
  EXPECT_TRUE(startsWith(last(), "getProperty(0x1010, ready, 103, 0x"));
  EXPECT_TRUE(endsWith(last(), ", 4, 0)"));
  EXPECT_FALSE(ready);

  // std::string goes through a const char *; a null answer reads as "".
  std::string version = "unset";
  EXPECT_TRUE(anari::getProperty(m_device, m_device, "version.name", version));
  EXPECT_TRUE(startsWith(
      last(), "getProperty(" + ptr(m_device) + ", version.name, 101, 0x"));
  EXPECT_TRUE(endsWith(last(), ", 8, 1)"));
  EXPECT_EQ(version, "");
}

TEST_F(CppApi, FrameOperations)
{
  auto pixels = anari::map<uint32_t>(m_device, kFrame, "channel.color");
  EXPECT_EQ(last(), "frameBufferMap(0x1010, channel.color)");
  EXPECT_EQ(pixels.width, 4u);
  EXPECT_EQ(pixels.height, 2u);
  EXPECT_EQ(pixels.pixelType, ANARI_UFIXED8_RGBA_SRGB);
  EXPECT_NE(pixels.data, nullptr);
  anari::unmap(m_device, kFrame, "channel.color");
  EXPECT_EQ(last(), "frameBufferUnmap(0x1010, channel.color)");

  anari::render(m_device, kFrame);
  EXPECT_EQ(last(), "renderFrame(0x1010)");
  EXPECT_TRUE(anari::isReady(m_device, kFrame));
  EXPECT_EQ(last(), "frameReady(0x1010, 0)");
  anari::wait(m_device, kFrame);
  EXPECT_EQ(last(), "frameReady(0x1010, 1)");
  anari::discard(m_device, kFrame);
  EXPECT_EQ(last(), "discardFrame(0x1010)");

  const anari::MappedFrameData<float> empty;
  EXPECT_EQ(empty.width, 0u);
  EXPECT_EQ(empty.height, 0u);
  EXPECT_EQ(empty.pixelType, ANARI_UNKNOWN);
  EXPECT_EQ(empty.data, nullptr);
}

// The aliases and the type mapping, checked at compile time.
template <typename T>
constexpr int typeFor = anari::ANARITypeFor<T>::value;

static_assert(std::is_same_v<anari::Library, ANARILibrary>);
static_assert(std::is_same_v<anari::Object, ANARIObject>);
static_assert(std::is_same_v<anari::Device, ANARIDevice>);
static_assert(std::is_same_v<anari::Future, ANARIFuture>);
static_assert(std::is_same_v<anari::Array3D, ANARIArray3D>);
static_assert(std::is_same_v<anari::SpatialField, ANARISpatialField>);
static_assert(std::is_same_v<anari::DataType, ANARIDataType>);
static_assert(std::is_same_v<anari::WaitMask, ANARIWaitMask>);
static_assert(std::is_same_v<anari::StatusCallback, ANARIStatusCallback>);
static_assert(std::is_same_v<anari::StatusSeverity, ANARIStatusSeverity>);
static_assert(std::is_same_v<anari::StatusCode, ANARIStatusCode>);
static_assert(std::is_same_v<anari::MemoryDeleter, ANARIMemoryDeleter>);
static_assert(std::is_same_v<anari::Parameter, ANARIParameter>);
static_assert(
    std::is_same_v<decltype(anari::ANARITypeFor<float>::value), const int>);

static_assert(typeFor<bool> == 103);
static_assert(typeFor<int8_t> == 1000 && typeFor<uint8_t> == 1004);
static_assert(typeFor<int16_t> == 1008 && typeFor<uint16_t> == 1012);
static_assert(typeFor<int32_t> == 1016 && typeFor<uint32_t> == 1020);
static_assert(typeFor<int64_t> == 1024 && typeFor<uint64_t> == 1028);
static_assert(
    typeFor<long long> == 1024 && typeFor<unsigned long long> == 1028);
static_assert(typeFor<float> == 1068 && typeFor<const float> == 1068);
static_assert(typeFor<double> == 1072);
static_assert(typeFor<float[3]> == 1070 && typeFor<const float[3]> == 1070);
static_assert(typeFor<float[12]> == 2016 && typeFor<float[16]> == 2014);
static_assert(typeFor<uint8_t[4]> == 1007 && typeFor<double[2]> == 1073);
static_assert(typeFor<void *> == 102 && typeFor<const void *> == 102);
static_assert(typeFor<char *> == 101 && typeFor<const char *> == 101);
static_assert(typeFor<const char[]> == 101);
static_assert(typeFor<char **> == 150 && typeFor<const char **> == 150);
static_assert(typeFor<ANARIDataType> == 100);
static_assert(typeFor<ANARIStatusCallback> == 202);
static_assert(typeFor<ANARIMemoryDeleter> == 201);
static_assert(typeFor<ANARIFrameCompletionCallback> == 203);
static_assert(typeFor<anari::Library> == 500 && typeFor<anari::Device> == 501);
static_assert(typeFor<anari::Object> == 502 && typeFor<anari::Array> == 503);
static_assert(typeFor<anari::Array1D> == 504 && typeFor<anari::Array2D> == 505);
static_assert(typeFor<anari::Array3D> == 506 && typeFor<anari::Camera> == 507);
static_assert(typeFor<anari::Frame> == 508 && typeFor<anari::Geometry> == 509);
static_assert(typeFor<anari::Group> == 510 && typeFor<anari::Instance> == 511);
static_assert(typeFor<anari::Light> == 512 && typeFor<anari::Material> == 513);
static_assert(
    typeFor<anari::Renderer> == 514 && typeFor<anari::Surface> == 515);
static_assert(typeFor<anari::Sampler> == 516);
static_assert(typeFor<anari::SpatialField> == 517);
static_assert(typeFor<anari::Volume> == 518 && typeFor<anari::World> == 519);
static_assert(typeFor<const anari::Geometry> == 509);
static_assert(typeFor<std::array<float, 2>> == 1069);
static_assert(typeFor<std::array<float, 3>> == 1070);
static_assert(typeFor<const std::array<float, 4>> == 1071);
static_assert(typeFor<std::array<int, 3>> == 1018);
static_assert(typeFor<std::array<unsigned, 2>> == 1021);
static_assert(typeFor<std::array<double, 4>> == 1075);
static_assert(typeFor<anari::std_types::box2> == 2009);
static_assert(typeFor<anari::std_types::box4> == 2011);
static_assert(typeFor<anari::std_types::mat4> == 2014);
static_assert(typeFor<std::array<std::array<int, 3>, 2>> == 2006);
static_assert(typeFor<AppVec3> == 1070 && typeFor<const AppVec3> == 1070);
static_assert(typeFor<std::array<AppVec3, 2>> == 0);
static_assert(typeFor<std::string> == 0 && typeFor<std::array<float, 5>> == 0);

// Arrays are copied element by element in the device's element size, so
// every mapped C++ type must occupy exactly that.
template <typename... T>
bool elementSizesMatch()
{
  return ((anari::sizeOf(typeFor<T>) == sizeof(T)) && ...);
}

TEST(CppApiTypes, MappedTypesHaveTheDeviceElementSize)
{
  EXPECT_TRUE((elementSizesMatch<bool,
      int8_t,
      uint16_t,
      int32_t,
      uint64_t,
      long long,
      float,
      double,
      float[3],
      float[16],
      void *,
      const char *,
      anari::Geometry,
      anari::StatusCallback,
      ANARIDataType>()));
  EXPECT_TRUE((elementSizesMatch<anari::std_types::vec2,
      anari::std_types::ivec3,
      anari::std_types::uvec4,
      std::array<double, 3>,
      std::array<uint8_t, 4>,
      anari::std_types::box3,
      anari::std_types::mat4,
      std::array<std::array<float, 3>, 4>,
      AppVec3>()));
}

} // namespace
