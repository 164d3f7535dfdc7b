// Picking coordinates (top-left, scaled to the frame) and the channel
// view's conversions.
#include "ChannelView.h"
#include "Picking.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prism::viewer {
namespace {

// A 4x2 frame: bottom row ids 0..3, top row ids 10..13; primitive = id + 100.
FrameIds smallFrame()
{
  FrameIds ids;
  ids.width = 4;
  ids.height = 2;
  ids.objectId = {0, 1, 2, 3, 10, 11, 12, kNoId};
  ids.instanceId = {5, 5, 5, 5, 5, 5, 5, kNoId};
  ids.primitiveId = {100, 101, 102, 103, 110, 111, 112, kNoId};
  ids.depth = {1.f, 2.f, 3.f, 4.f, 5.f, 6.f, 7.f, INFINITY};
  return ids;
}

TEST(Picking, CoordinatesCountFromTheTopLeft)
{
  const FrameIds ids = smallFrame();
  const std::optional<Pick> top = pickAt(ids, 1, 0, 4, 2);
  ASSERT_TRUE(top && top->hit);
  EXPECT_EQ(top->objectId, 11u);
  EXPECT_EQ(top->primitiveId, 111u);
  EXPECT_EQ(top->instanceId, 5u);
  EXPECT_FLOAT_EQ(*top->depth, 6.f);
  const std::optional<Pick> bottom = pickAt(ids, 3, 1, 4, 2);
  ASSERT_TRUE(bottom);
  EXPECT_EQ(bottom->objectId, 3u);
}

TEST(Picking, AWindowLargerThanTheFrameScalesDown)
{
  // The frame renders at half the window's size while the camera moves.
  const std::optional<Pick> p = pickAt(smallFrame(), 7, 3, 8, 4);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->objectId, 3u);
}

TEST(Picking, MissesOutsideAndEmptyAreTold)
{
  const FrameIds ids = smallFrame();
  const std::optional<Pick> miss = pickAt(ids, 3, 0, 4, 2);
  ASSERT_TRUE(miss);
  EXPECT_FALSE(miss->hit);
  EXPECT_FALSE(miss->depth);
  EXPECT_FALSE(pickAt(ids, 4, 0, 4, 2));
  EXPECT_FALSE(pickAt(ids, -1, 0, 4, 2));
  EXPECT_FALSE(pickAt(FrameIds{}, 0, 0, 4, 2));
}

TEST(Picking, TheMaskCoversTheObjectOnly)
{
  FrameIds ids = smallFrame();
  ids.objectId = {7, 7, 2, 7, 7, 1, 7, kNoId};
  ids.instanceId = {5, 5, 5, 6, 5, 5, 5, kNoId};
  const std::optional<Pick> p = pickAt(ids, 0, 1, 4, 2);
  ASSERT_TRUE(p);
  const std::vector<bool> mask = pickedMask(ids, *p);
  const std::vector<bool> expected = {
      true, true, false, false, true, false, true, false};
  EXPECT_EQ(mask, expected);
}

TEST(ChannelView, IdsGetStableVisibleColorsAndMissesBlack)
{
  EXPECT_EQ(idColor(kNoId), 0xff000000u);
  EXPECT_EQ(idColor(3), idColor(3));
  EXPECT_NE(idColor(3), idColor(4));
  for (uint32_t id : {0u, 1u, 2u, 1000u}) {
    const uint32_t c = idColor(id);
    EXPECT_GE(c & 0xff, 64u);
    EXPECT_GE((c >> 8) & 0xff, 64u);
    EXPECT_GE((c >> 16) & 0xff, 64u);
  }
}

TEST(ChannelView, DepthRunsFromWhiteNearToDarkFarAndMissesBlack)
{
  const float depth[3] = {1.f, 3.f, INFINITY};
  const Rgba8Image image =
      channelToRgba8(Channel::Depth, depth, ANARI_FLOAT32, 3, 1);
  ASSERT_EQ(image.pixels.size(), 12u);
  EXPECT_EQ(image.pixels[0], 255);
  EXPECT_EQ(image.pixels[4], 51); // 1 - 0.8
  EXPECT_EQ(image.pixels[8], 0);
  EXPECT_EQ(image.pixels[11], 255);
}

TEST(ChannelView, NormalsAndWrongTypes)
{
  const float normal[3] = {1.f, 0.f, -1.f};
  const Rgba8Image image =
      channelToRgba8(Channel::Normal, normal, ANARI_FLOAT32_VEC3, 1, 1);
  ASSERT_EQ(image.pixels.size(), 4u);
  EXPECT_EQ(image.pixels[0], 255);
  EXPECT_EQ(image.pixels[1], 128);
  EXPECT_EQ(image.pixels[2], 0);
  EXPECT_TRUE(channelToRgba8(Channel::Depth, normal, ANARI_FLOAT32_VEC3, 1, 1)
                  .pixels.empty());
  EXPECT_TRUE(channelToRgba8(Channel::Color, nullptr, ANARI_FLOAT32, 1, 1)
                  .pixels.empty());
}

TEST(ChannelView, NamesRoundTrip)
{
  for (Channel c : kAllChannels) {
    EXPECT_EQ(channelNamed(channelName(c)), c);
    EXPECT_EQ(channelNamed(channelParameter(c)), c);
  }
  EXPECT_FALSE(channelNamed("colour"));
}

} // namespace
} // namespace prism::viewer
