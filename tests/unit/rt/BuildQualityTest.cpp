// The device's bvhQuality parameter (PRISM_BVH_QUALITY): the three
// names set the Embree build quality of BVHs built afterwards, anything
// else is reported and changes nothing.
#include "../ObjectTestFixture.h"
#include "rt/Context.h"

namespace prism {
namespace {

using BuildQuality = rt::Context::BuildQuality;

TEST(BuildQuality, NamesSetTheQualityAndOthersAreRefused)
{
  rt::Context context([](const std::string &) {});
  EXPECT_EQ(context.buildQuality(), BuildQuality::Medium);
  EXPECT_TRUE(context.setBuildQuality(std::string("high")));
  EXPECT_EQ(context.buildQuality(), BuildQuality::High);
  EXPECT_TRUE(context.setBuildQuality(std::string("low")));
  EXPECT_EQ(context.buildQuality(), BuildQuality::Low);
  EXPECT_FALSE(context.setBuildQuality(std::string("best")));
  EXPECT_EQ(context.buildQuality(), BuildQuality::Low);
}

using BuildQualityParameter = testing::ObjectTestFixture;

TEST_F(BuildQualityParameter, TheDeviceAcceptsItAndWarnsAboutUnknownNames)
{
  const auto device = (ANARIObject)m_device.this_device();
  m_device.setParameter(device, "bvhQuality", ANARI_STRING, "high");
  EXPECT_EQ(m_device.rtContext().buildQuality(), BuildQuality::High);
  EXPECT_TRUE(m_messages.empty());
  m_device.setParameter(device, "bvhQuality", ANARI_STRING, "best");
  EXPECT_EQ(m_device.rtContext().buildQuality(), BuildQuality::High);
  EXPECT_EQ(m_messages.size(), 1u);
}

} // namespace
} // namespace prism
