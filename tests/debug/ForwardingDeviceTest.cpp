// ForwardingDevice: every anariNew* and parameter array map reaches its
// hook with the type and sizes of the call, the device's own handle
// becomes the inner device's, and a call admits() refuses never reaches
// the inner device.
#include "ForwardingDevice.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

// An inner device that records what reaches it (and forwards nowhere).
class Recorder : public prism::ForwardingDevice
{
 public:
  Recorder() : ForwardingDevice(nullptr) {}

  std::vector<ANARIDataType> created;
  std::vector<uint64_t> arrayItems;
  std::vector<std::string> calls;
  ANARIObject lastObject{nullptr};

  void setParameter(ANARIObject object,
      const char *name,
      ANARIDataType,
      const void *) override
  {
    lastObject = object;
    calls.push_back(std::string("set ") + name);
  }
  void release(ANARIObject object) override
  {
    lastObject = object;
    calls.push_back("release");
  }

 protected:
  ANARIObject newObjectOf(ANARIDataType type, const char *) override
  {
    created.push_back(type);
    return (ANARIObject)(uintptr_t)(created.size());
  }
  ANARIArray newArrayOf(ANARIDataType arrayType,
      const void *,
      ANARIMemoryDeleter,
      const void *,
      ANARIDataType,
      const uint64_t items[3]) override
  {
    created.push_back(arrayType);
    arrayItems.assign(items, items + 3);
    return (ANARIArray)(uintptr_t)(created.size());
  }
  void *mapParameterArrayOf(ANARIObject object,
      const char *name,
      ANARIDataType arrayType,
      ANARIDataType,
      const uint64_t items[3],
      uint64_t *) override
  {
    lastObject = object;
    calls.push_back(
        std::string(mapParameterArrayFunctionName(arrayType)) + " " + name);
    arrayItems.assign(items, items + 3);
    return nullptr;
  }
};

// A layer over a recorder that refuses one handle and counts creations.
class Layer : public prism::ForwardingDevice
{
 public:
  explicit Layer(anari::DeviceImpl *inner) : ForwardingDevice(nullptr)
  {
    setInner(inner);
  }

  ANARIObject refused{nullptr};
  std::vector<std::string> refusals;
  int creations{0};

 protected:
  bool admits(ANARIObject object, const char *function) override
  {
    if (object != refused)
      return true;
    refusals.push_back(function);
    return false;
  }
  void beforeCreating(ANARIDataType) override
  {
    creations++;
  }
};

TEST(ForwardingDevice, EveryNewReachesItsHookWithItsType)
{
  Recorder inner;
  Layer layer(&inner);
  layer.newGeometry("sphere");
  layer.newSurface();
  layer.newFrame();
  layer.newArray2D(nullptr, nullptr, nullptr, ANARI_FLOAT32, 4, 3);
  const std::vector<ANARIDataType> expected = {
      ANARI_GEOMETRY, ANARI_SURFACE, ANARI_FRAME, ANARI_ARRAY2D};
  EXPECT_EQ(inner.created, expected);
  EXPECT_EQ(inner.arrayItems, (std::vector<uint64_t>{4, 3, 0}));
  EXPECT_EQ(layer.creations, 4);
}

TEST(ForwardingDevice, ParameterArrayMapsReachOneHook)
{
  Recorder inner;
  Layer layer(&inner);
  const ANARIObject object = (ANARIObject)(uintptr_t)7;
  uint64_t stride = 0;
  layer.mapParameterArray3D(object, "data", ANARI_UINT8, 2, 3, 5, &stride);
  ASSERT_EQ(inner.calls.size(), 1u);
  EXPECT_EQ(inner.calls[0], "anariMapParameterArray3D data");
  EXPECT_EQ(inner.lastObject, object);
  EXPECT_EQ(inner.arrayItems, (std::vector<uint64_t>{2, 3, 5}));
}

TEST(ForwardingDevice, OwnHandleBecomesTheInnerDevices)
{
  Recorder inner;
  Layer layer(&inner);
  const float value = 1.f;
  layer.setParameter(
      (ANARIObject)layer.this_device(), "someParameter", ANARI_FLOAT32, &value);
  EXPECT_EQ(inner.lastObject, (ANARIObject)inner.this_device());
  // Releasing the layer itself is the layer's affair.
  layer.release((ANARIObject)layer.this_device());
  EXPECT_EQ(inner.calls, (std::vector<std::string>{"set someParameter"}));
}

TEST(ForwardingDevice, RefusedCallsNeverReachTheInnerDevice)
{
  Recorder inner;
  Layer layer(&inner);
  layer.refused = (ANARIObject)(uintptr_t)9;
  const float value = 1.f;
  layer.setParameter(layer.refused, "radius", ANARI_FLOAT32, &value);
  layer.release(layer.refused);
  uint32_t width = 5, height = 5;
  ANARIDataType type = ANARI_FLOAT32;
  EXPECT_EQ(
      layer.frameBufferMap(
          (ANARIFrame)layer.refused, "channel.color", &width, &height, &type),
      nullptr);
  EXPECT_TRUE(inner.calls.empty());
  EXPECT_EQ(width, 0u);
  EXPECT_EQ(height, 0u);
  EXPECT_EQ(type, ANARI_UNKNOWN);
  EXPECT_EQ(layer.refusals,
      (std::vector<std::string>{
          "anariSetParameter", "anariRelease", "anariMapFrame"}));
}

TEST(ForwardingDevice, WithoutAnInnerDeviceCallsAnswerNothing)
{
  Layer layer(nullptr);
  EXPECT_EQ(layer.newWorld(), nullptr);
  EXPECT_EQ(
      layer.newArray1D(nullptr, nullptr, nullptr, ANARI_FLOAT32, 3), nullptr);
  EXPECT_EQ(layer.getObjectSubtypes(ANARI_RENDERER), nullptr);
  EXPECT_EQ(layer.frameReady(nullptr, ANARI_WAIT), 0);
}

} // namespace
