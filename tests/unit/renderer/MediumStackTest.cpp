// The media a path is in: nested entries, leaving back to the outer one,
// and a full stack replacing its innermost entry.
#include "renderer/wavefront/MediumStack.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

TEST(MediumStack, NestedMediaReturnToTheOuterOne)
{
  MediumStack media;
  const float3 none{0, 0, 0}, glass{0.1f, 0.1f, 0.1f}, water{0, 0.5f, 1};
  EXPECT_EQ(media.absorption(), none);
  media.enter(glass);
  media.enter(water);
  EXPECT_EQ(media.absorption(), water);
  media.leave();
  EXPECT_EQ(media.absorption(), glass); // back in the glass
  media.leave();
  media.leave(); // leaving nothing stays outside
  EXPECT_EQ(media.absorption(), none);
  EXPECT_EQ(media.depth(), 0);
}

TEST(MediumStack, AFullStackReplacesItsInnermostEntry)
{
  MediumStack media;
  for (int i = 0; i < MediumStack::kCapacity + 2; i++)
    media.enter(float3{float(i), 0, 0});
  EXPECT_EQ(media.depth(), MediumStack::kCapacity);
  EXPECT_EQ(media.absorption().x, float(MediumStack::kCapacity + 1));
  media.leave();
  EXPECT_EQ(media.absorption().x, float(MediumStack::kCapacity - 2));
}

} // namespace
} // namespace prism
