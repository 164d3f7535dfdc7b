// Asynchronous frames: completion callbacks, discard, commits while a frame
// is in flight, properties.
#include "DeviceTestSupport.h"

#include <atomic>
#include <cstring>
#include <thread>

namespace {

const float kRed[4] = {1, 0, 0, 1};
const float kBlue[4] = {0, 0, 1, 1};

struct CompletionRecord
{
  std::atomic<int> calls{0};
  std::thread::id thread;
  ANARIFrame frame{nullptr};
};

void onComplete(const void *userPtr, ANARIDevice, ANARIFrame frame)
{
  auto *record = (CompletionRecord *)userPtr;
  record->thread = std::this_thread::get_id();
  record->frame = frame;
  record->calls++;
}

// Sets and commits `frame`'s completion callback to onComplete(record).
void setCompletion(
    ANARIDevice device, ANARIFrame frame, CompletionRecord &record)
{
  ANARIFrameCompletionCallback callback = onComplete;
  anariSetParameter(device,
      frame,
      "frameCompletionCallback",
      ANARI_FRAME_COMPLETION_CALLBACK,
      &callback);
  anariSetParameter(device,
      frame,
      "frameCompletionCallbackUserData",
      ANARI_VOID_POINTER,
      &record);
  anariCommitParameters(device, frame);
}

using DeviceFrame = PrismDeviceTest;

TEST_F(DeviceFrame, CompletionCallbackRunsOnAWorkerBeforeWaitReturns)
{
  ANARIRenderer renderer = newRenderer(kRed);
  ANARIFrame frame = newFrame(renderer, 16, 16);
  CompletionRecord record;
  setCompletion(m_device, frame, record);
  for (int i = 1; i <= 3; i++) {
    anariRenderFrame(m_device, frame);
    EXPECT_EQ(anariFrameReady(m_device, frame, ANARI_WAIT), 1);
    EXPECT_EQ(record.calls, i);
  }
  EXPECT_EQ(record.frame, frame);
  EXPECT_NE(record.thread, std::this_thread::get_id());
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
  EXPECT_TRUE(problems().empty());
}

TEST_F(DeviceFrame, CommitDuringAFrameAppliesToTheNextOne)
{
  ANARIRenderer renderer = newRenderer(kRed);
  ANARIFrame frame = newFrame(renderer, 512, 512);
  anariRenderFrame(m_device, frame);
  // Staged and committed while the frame may still be rendering.
  anariSetParameter(
      m_device, renderer, "background", ANARI_FLOAT32_VEC4, kBlue);
  anariCommitParameters(m_device, renderer);
  EXPECT_EQ(firstPixel(frame), std::vector<float>({1, 0, 0, 1}));
  anariRenderFrame(m_device, frame);
  EXPECT_EQ(firstPixel(frame), std::vector<float>({0, 0, 1, 1}));
  // Staged but not committed: never visible.
  anariSetParameter(m_device, renderer, "background", ANARI_FLOAT32_VEC4, kRed);
  anariRenderFrame(m_device, frame);
  EXPECT_EQ(firstPixel(frame), std::vector<float>({0, 0, 1, 1}));
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
  EXPECT_TRUE(problems().empty());
}

TEST_F(DeviceFrame, DiscardStopsARenderAndTheFrameStaysUsable)
{
  ANARIRenderer renderer = newRenderer(kRed);
  ANARIFrame frame = newFrame(renderer, 2048, 2048);
  anariRenderFrame(m_device, frame);
  anariDiscardFrame(m_device, frame);
  EXPECT_EQ(anariFrameReady(m_device, frame, ANARI_WAIT), 1);
  anariRenderFrame(m_device, frame);
  EXPECT_EQ(firstPixel(frame), std::vector<float>({1, 0, 0, 1}));
  float progress = -1.f;
  EXPECT_EQ(anariGetProperty(m_device,
                frame,
                "renderProgress",
                ANARI_FLOAT32,
                &progress,
                sizeof(progress),
                ANARI_NO_WAIT),
      1);
  EXPECT_EQ(progress, 1.f);
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
}

TEST_F(DeviceFrame, ReleasingAFrameInFlightIsSafe)
{
  ANARIRenderer renderer = newRenderer(kRed);
  ANARIFrame frame = newFrame(renderer, 1024, 1024);
  anariRenderFrame(m_device, frame);
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
  EXPECT_TRUE(problems().empty());
}

TEST_F(DeviceFrame, DurationProperty)
{
  ANARIRenderer renderer = newRenderer(kRed);
  ANARIFrame frame = newFrame(renderer, 64, 64);
  anariRenderFrame(m_device, frame);
  float duration = -1.f;
  EXPECT_EQ(anariGetProperty(m_device,
                frame,
                "duration",
                ANARI_FLOAT32,
                &duration,
                sizeof(duration),
                ANARI_WAIT),
      1);
  EXPECT_GE(duration, 0.f);
  // The wrong type or too small a buffer writes nothing.
  double wrong = 0;
  EXPECT_EQ(anariGetProperty(m_device,
                frame,
                "duration",
                ANARI_FLOAT64,
                &wrong,
                sizeof(wrong),
                ANARI_WAIT),
      0);
  EXPECT_EQ(
      anariGetProperty(
          m_device, frame, "duration", ANARI_FLOAT32, &duration, 2, ANARI_WAIT),
      0);
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
}

TEST_F(DeviceFrame, DeviceProperties)
{
  int32_t value = -1;
  EXPECT_EQ(anariGetProperty(m_device,
                m_device,
                "anariVersion.major",
                ANARI_INT32,
                &value,
                4,
                ANARI_WAIT),
      1);
  EXPECT_EQ(value, 1);
  EXPECT_EQ(
      anariGetProperty(
          m_device, m_device, "version", ANARI_INT32, &value, 4, ANARI_WAIT),
      1);
  EXPECT_GT(value, 0);
  uint64_t length = 0;
  EXPECT_EQ(anariGetProperty(m_device,
                m_device,
                "version.name.size",
                ANARI_UINT64,
                &length,
                8,
                ANARI_WAIT),
      1);
  std::string name(length, '?');
  EXPECT_EQ(anariGetProperty(m_device,
                m_device,
                "version.name",
                ANARI_STRING,
                name.data(),
                length,
                ANARI_WAIT),
      1);
  EXPECT_EQ(name.size(), std::strlen(name.c_str()) + 1); // ends in its NUL
  EXPECT_NE(name.find("Prism"), std::string::npos);
  uint64_t maxIndex = 0;
  EXPECT_EQ(anariGetProperty(m_device,
                m_device,
                "geometryMaxIndex",
                ANARI_UINT64,
                &maxIndex,
                8,
                ANARI_WAIT),
      1);
  EXPECT_GE(maxIndex, 0xffffffffull);
  const char **extensions = nullptr;
  EXPECT_EQ(anariGetProperty(m_device,
                m_device,
                "extension",
                ANARI_STRING_LIST,
                &extensions,
                sizeof(extensions),
                ANARI_WAIT),
      1);
  ASSERT_NE(extensions, nullptr);
  bool hasBackground = false;
  for (const char **e = extensions; *e; e++)
    hasBackground |= std::string(*e) == "ANARI_KHR_RENDERER_BACKGROUND_COLOR";
  EXPECT_TRUE(hasBackground);
  EXPECT_EQ(
      anariGetProperty(
          m_device, m_device, "nonsense", ANARI_INT32, &value, 4, ANARI_WAIT),
      0);
}

// KHR_DEVICE_SYNCHRONIZATION: different objects edited from several threads.
TEST_F(DeviceFrame, ObjectsEditedFromManyThreadsAtOnce)
{
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; t++) {
    threads.emplace_back([this, t] {
      for (int i = 0; i < 50; i++) {
        const float color[4] = {float(t) / 4, 0, 0, 1};
        ANARIRenderer renderer = newRenderer(color);
        ANARIFrame frame = newFrame(renderer, 8, 8);
        anariRenderFrame(m_device, frame);
        auto pixel = firstPixel(frame);
        EXPECT_EQ(pixel, std::vector<float>({float(t) / 4, 0, 0, 1}));
        anariRelease(m_device, frame);
        anariRelease(m_device, renderer);
      }
    });
  }
  for (auto &thread : threads)
    thread.join();
  EXPECT_TRUE(problems().empty());
}

// Defect: the worker still touched the frame (callback, condition
// variable) after anariFrameReady(WAIT) had returned, so a release right
// after the wait destroyed it under the worker; re-committing the frame
// raced the worker reading the committed callback. ThreadSanitizer runs it.
TEST_F(DeviceFrame, ReleasedOrRecommittedRightAfterWait)
{
  ANARIRenderer renderer = newRenderer(kRed);
  CompletionRecord record;
  for (int i = 0; i < 300; i++) {
    ANARIFrame frame = newFrame(renderer, 4, 4);
    setCompletion(m_device, frame, record);
    for (int again = 0; again < 3; again++) {
      anariRenderFrame(m_device, frame);
      anariFrameReady(m_device, frame, ANARI_WAIT);
      // Recommitted while the worker may still be in the last render's
      // completion.
      setCompletion(m_device, frame, record);
    }
    anariRelease(m_device, frame);
  }
  EXPECT_EQ(record.calls, 900);
  anariRelease(m_device, renderer);
  EXPECT_TRUE(problems().empty());
}

} // namespace
