// Mapping discipline: arrays, parameter arrays and frame channels.
#include "DebugLayerTestSupport.h"

using DebugMapping = DebugLayerTest;

TEST_F(DebugMapping, ArrayMappedTwiceOrUnmappedUnmapped)
{
  ANARIArray1D array =
      anariNewArray1D(m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32, 4);
  anariUnmapArray(m_device, array);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "anariUnmapArray(array1d #1): the array is not mapped"));
  void *first = anariMapArray(m_device, array);
  EXPECT_NE(first, nullptr);
  EXPECT_EQ(anariMapArray(m_device, array), first);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "the array is already mapped"));
  anariCommitParameters(m_device, array);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "the array is mapped; unmap it before committing"));
  anariUnmapArray(m_device, array);

  anariMapArray(m_device, array);
  anariUnmapArray(m_device, array);
  anariCommitParameters(m_device, array);
  anariRelease(m_device, array);
  EXPECT_TRUE(silent());
}

TEST_F(DebugMapping, ParameterSetWhileMapped)
{
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  uint64_t stride = 0;
  void *memory = anariMapParameterArray2D(
      m_device, renderer, "background", ANARI_FLOAT32_VEC4, 2, 2, &stride);
  ASSERT_NE(memory, nullptr);
  const float red[4] = {1, 0, 0, 1};
  anariSetParameter(m_device, renderer, "background", ANARI_FLOAT32_VEC4, red);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "anariSetParameter(renderer default #1 'background'): the parameter is "
      "mapped"));
  anariMapParameterArray2D(
      m_device, renderer, "background", ANARI_FLOAT32_VEC4, 2, 2, &stride);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "the parameter is already mapped"));
  anariUnmapParameterArray(m_device, renderer, "background");
  anariUnmapParameterArray(m_device, renderer, "background");
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "the parameter is not mapped"));

  anariSetParameter(m_device, renderer, "background", ANARI_FLOAT32_VEC4, red);
  anariCommitParameters(m_device, renderer);
  anariRelease(m_device, renderer);
  EXPECT_TRUE(silent());
}

TEST_F(DebugMapping, FrameMappedBeforeItWasRendered)
{
  ANARIFrame frame = anariNewFrame(m_device);
  uint32_t w = 7, h = 7;
  ANARIDataType type = ANARI_FLOAT32;
  EXPECT_EQ(
      anariMapFrame(m_device, frame, "channel.color", &w, &h, &type), nullptr);
  EXPECT_EQ(w, 0u);
  EXPECT_EQ(type, ANARI_UNKNOWN);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "anariMapFrame(frame #1 'channel.color'): the frame was never rendered"));
  anariUnmapFrame(m_device, frame, "channel.color");
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "the channel is not mapped"));
  anariRelease(m_device, frame);
  EXPECT_TRUE(silent());
}

TEST_F(DebugMapping, FrameMappedWhileItMayStillRender)
{
  const float black[4] = {0, 0, 0, 1};
  ANARIRenderer renderer = newRenderer(black);
  ANARIFrame frame = newFrame(renderer, 8, 8);
  anariRelease(m_device, renderer);
  uint32_t w = 0, h = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  // Allowed (the map waits for the frame), but worth knowing.
  anariRenderFrame(m_device, frame);
  EXPECT_NE(
      anariMapFrame(m_device, frame, "channel.color", &w, &h, &type), nullptr);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_PERFORMANCE_WARNING,
      ANARI_STATUS_NO_ERROR,
      "anariMapFrame(frame #4 'channel.color'): the frame may still be "
      "rendering"));
  anariUnmapFrame(m_device, frame, "channel.color");

  // Waited for: nothing at all to say.
  anariRenderFrame(m_device, frame);
  EXPECT_EQ(anariFrameReady(m_device, frame, ANARI_WAIT), 1);
  EXPECT_NE(
      anariMapFrame(m_device, frame, "channel.color", &w, &h, &type), nullptr);
  anariUnmapFrame(m_device, frame, "channel.color");
  anariRelease(m_device, frame);
  EXPECT_TRUE(m_status.take().empty());
}
