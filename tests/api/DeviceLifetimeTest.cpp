// Reference counts and memory ownership (spec 3.5, 3.9): deleters run once,
// when the device no longer needs the memory; internal references keep
// released objects alive; device release frees everything.
#include "DeviceTestSupport.h"

#include <atomic>

namespace {

std::atomic<int> g_deleted{0};
const void *g_deletedMemory = nullptr;

void countingDeleter(const void *userPtr, const void *memory)
{
  g_deleted++;
  g_deletedMemory = memory;
  EXPECT_EQ(userPtr, (const void *)0x1234);
}

class DeviceLifetime : public PrismDeviceTest
{
 protected:
  void SetUp() override
  {
    PrismDeviceTest::SetUp();
    g_deleted = 0;
    g_deletedMemory = nullptr;
  }
  const float m_texels[4] = {0.5f, 0.25f, 0.125f, 1.f};

  ANARIArray2D newImage()
  {
    return anariNewArray2D(m_device,
        m_texels,
        countingDeleter,
        (const void *)0x1234,
        ANARI_FLOAT32_VEC4,
        1,
        1);
  }
};

TEST_F(DeviceLifetime, DeleterRunsOnceWhenTheLastUserLetsGo)
{
  ANARIArray2D image = newImage();
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  anariSetParameter(m_device, renderer, "background", ANARI_ARRAY2D, &image);
  anariCommitParameters(m_device, renderer);
  anariRelease(m_device, image);
  EXPECT_EQ(g_deleted, 0); // the renderer still uses it
  // The released array is still rendered from.
  ANARIFrame frame = newFrame(renderer, 2, 2);
  anariRenderFrame(m_device, frame);
  EXPECT_EQ(firstPixel(frame), std::vector<float>({0.5f, 0.25f, 0.125f, 1.f}));
  anariRelease(m_device, frame);
  anariUnsetParameter(m_device, renderer, "background");
  EXPECT_EQ(g_deleted, 0); // staged only; the committed value still holds it
  anariRelease(m_device, renderer);
  EXPECT_EQ(g_deleted, 1);
  EXPECT_EQ(g_deletedMemory, m_texels);
  EXPECT_TRUE(problems().empty());
}

TEST_F(DeviceLifetime, ReplacedValuesLiveUntilTheNextFrameStarts)
{
  ANARIArray2D image = newImage();
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  anariSetParameter(m_device, renderer, "background", ANARI_ARRAY2D, &image);
  anariCommitParameters(m_device, renderer);
  anariRelease(m_device, image);
  ANARIFrame frame = newFrame(renderer, 256, 256);
  anariRenderFrame(m_device, frame);
  // Replaced and committed while the frame may still read the image: the
  // image must outlive that frame, so it goes only when the next starts.
  const float blue[4] = {0, 0, 1, 1};
  anariSetParameter(m_device, renderer, "background", ANARI_FLOAT32_VEC4, blue);
  anariCommitParameters(m_device, renderer);
  EXPECT_EQ(g_deleted, 0);
  EXPECT_EQ(firstPixel(frame), std::vector<float>({0.5f, 0.25f, 0.125f, 1.f}));
  anariRenderFrame(m_device, frame);
  EXPECT_EQ(firstPixel(frame), std::vector<float>({0, 0, 1, 1}));
  EXPECT_EQ(g_deleted, 1);
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
  EXPECT_TRUE(problems().empty());
}

TEST_F(DeviceLifetime, ObjectArraysHoldTheirElements)
{
  ANARIArray2D image = newImage();
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  anariSetParameter(m_device, renderer, "background", ANARI_ARRAY2D, &image);
  anariCommitParameters(m_device, renderer);
  anariRelease(m_device, image);
  // A waiting property query applies pending commits, as a render would.
  int32_t unused;
  anariGetProperty(
      m_device, renderer, "x", ANARI_INT32, &unused, 4, ANARI_WAIT);
  ANARIObject handles[2] = {renderer, nullptr};
  ANARIArray1D objects =
      anariNewArray1D(m_device, handles, nullptr, nullptr, ANARI_RENDERER, 2);
  anariRelease(m_device, renderer);
  EXPECT_EQ(g_deleted, 0); // renderer kept alive by the object array
  // Mapping and writing NULL over the element drops the reference at unmap.
  auto *mapped = (ANARIObject *)anariMapArray(m_device, objects);
  ASSERT_EQ(mapped, handles);
  mapped[0] = nullptr;
  EXPECT_EQ(g_deleted, 0);
  anariUnmapArray(m_device, objects);
  EXPECT_EQ(g_deleted, 1);
  anariRelease(m_device, objects);
  EXPECT_TRUE(problems().empty());
}

TEST_F(DeviceLifetime, RetainAddsAPublicReference)
{
  ANARIArray2D image = newImage();
  anariRetain(m_device, image);
  anariRelease(m_device, image);
  EXPECT_EQ(g_deleted, 0);
  anariRelease(m_device, image);
  EXPECT_EQ(g_deleted, 1);
  EXPECT_TRUE(problems().empty());
}

TEST_F(DeviceLifetime, DeviceReleaseFreesLeakedObjectsAndSaysSo)
{
  ANARIArray2D image = newImage();
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  anariSetParameter(m_device, renderer, "background", ANARI_ARRAY2D, &image);
  anariCommitParameters(m_device, renderer);
  // A reference cycle through an object array must not leak either.
  ANARIObject handles[1] = {renderer};
  ANARIArray1D objects =
      anariNewArray1D(m_device, handles, nullptr, nullptr, ANARI_RENDERER, 1);
  anariSetParameter(m_device, renderer, "cycle", ANARI_ARRAY1D, &objects);
  anariRelease(m_device, m_device);
  m_device = nullptr;
  EXPECT_EQ(g_deleted, 1);
  bool listed = false;
  for (auto &m : m_status.take()) {
    if (m.severity == ANARI_SEVERITY_DEBUG
        && m.text.find("3 object(s) the application did not release")
               != std::string::npos)
      listed = true;
  }
  EXPECT_TRUE(listed);
}

TEST_F(DeviceLifetime, ManagedArraysNeverCallDeleters)
{
  ANARIArray1D array = anariNewArray1D(
      m_device, nullptr, countingDeleter, (const void *)0x1234, ANARI_UINT8, 8);
  auto *bytes = (unsigned char *)anariMapArray(m_device, array);
  ASSERT_NE(bytes, nullptr);
  for (int i = 0; i < 8; i++)
    EXPECT_EQ(bytes[i], 0); // managed memory starts zeroed
  anariUnmapArray(m_device, array);
  anariRelease(m_device, array);
  EXPECT_EQ(g_deleted, 0);
}

} // namespace
