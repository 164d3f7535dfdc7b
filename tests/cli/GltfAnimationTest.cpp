// glTF animation sampling (scene_io::poseAtTime) on hand-made channels:
// each interpolation against its formula, times outside the keys clamped,
// and malformed channels refused by name.
#include "GltfAnimation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace {

using namespace prism::scene_io;

// The accessors the tests' channels read, by index.
std::map<int, std::vector<float>> g_accessors;

bool readCanned(const tinygltf::Model &,
    int accessor,
    int,
    int,
    std::vector<float> &values,
    std::string &error)
{
  const auto found = g_accessors.find(accessor);
  if (found == g_accessors.end()) {
    error = "no accessor " + std::to_string(accessor);
    return false;
  }
  values = found->second;
  return true;
}

// A model of one node animated along `path` by one sampler (times in
// accessor 0, values in accessor 1).
tinygltf::Model animated(const std::string &path,
    const std::string &interpolation,
    std::vector<float> times,
    std::vector<float> values)
{
  g_accessors = {{0, std::move(times)}, {1, std::move(values)}};
  tinygltf::Model model;
  model.nodes.resize(1);
  tinygltf::Animation animation;
  tinygltf::AnimationSampler sampler;
  sampler.input = 0;
  sampler.output = 1;
  sampler.interpolation = interpolation;
  animation.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = 0;
  channel.target_node = 0;
  channel.target_path = path;
  animation.channels.push_back(channel);
  model.animations.push_back(animation);
  return model;
}

std::vector<double> poseAt(tinygltf::Model model, double time)
{
  std::string error;
  EXPECT_TRUE(poseAtTime(model, time, readCanned, error)) << error;
  const tinygltf::Node &n = model.nodes[0];
  return !n.translation.empty() ? n.translation
         : !n.rotation.empty()  ? n.rotation
         : !n.scale.empty()     ? n.scale
                                : n.weights;
}

TEST(GltfAnimation, LinearStepAndClamping)
{
  const auto linear =
      animated("translation", "LINEAR", {1.f, 3.f}, {0, 0, 0, 4, 2, -2});
  EXPECT_EQ(poseAt(linear, 2.0), (std::vector<double>{2, 1, -1}));
  EXPECT_EQ(poseAt(linear, 0.0), (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(poseAt(linear, 9.0), (std::vector<double>{4, 2, -2}));
  const auto step = animated("scale", "STEP", {1.f, 3.f}, {1, 1, 1, 2, 2, 2});
  EXPECT_EQ(poseAt(step, 2.9), (std::vector<double>{1, 1, 1}));
  EXPECT_EQ(poseAt(step, 3.0), (std::vector<double>{2, 2, 2}));
}

TEST(GltfAnimation, RotationsAreSpherical)
{
  // 0 to 90 degrees about z: halfway is 45 degrees, a unit quaternion (a
  // plain lerp would be 0.924 long).
  const float h = std::sqrt(0.5f);
  const auto r =
      animated("rotation", "LINEAR", {0.f, 1.f}, {0, 0, 0, 1, 0, 0, h, h});
  const std::vector<double> q = poseAt(r, 0.5);
  EXPECT_NEAR(q[2], std::sin(M_PI / 8), 1e-6);
  EXPECT_NEAR(q[3], std::cos(M_PI / 8), 1e-6);
}

TEST(GltfAnimation, CubicSplineIsHermite)
{
  // Keys 0 and 1 at t 0 and 2, tangents zero: smoothstep, 0.5 at t = 1 and
  // 0.15625 at t = 0.5; with an out-tangent of 1 at key 0 the curve gains
  // (t^3 - 2t^2 + t) * 2 (the keys' distance).
  const auto flat =
      animated("weights", "CUBICSPLINE", {0.f, 2.f}, {0, 0, 0, /**/ 0, 1, 0});
  EXPECT_NEAR(poseAt(flat, 1.0)[0], 0.5, 1e-9);
  EXPECT_NEAR(poseAt(flat, 0.5)[0], 0.15625, 1e-9);
  const auto sloped =
      animated("weights", "CUBICSPLINE", {0.f, 2.f}, {0, 0, 1, /**/ 0, 1, 0});
  const double t = 0.25;
  EXPECT_NEAR(poseAt(sloped, 0.5)[0],
      0.15625 + (t * t * t - 2 * t * t + t) * 2.0,
      1e-6);
}

TEST(GltfAnimation, MalformedChannelsAreRefused)
{
  std::string error;
  auto wrongWidth =
      animated("rotation", "LINEAR", {0.f, 1.f}, {0, 0, 0, 1, 0, 0});
  EXPECT_FALSE(poseAtTime(wrongWidth, 0.5, readCanned, error));
  EXPECT_NE(
      error.find("animates rotation with 3 values a key"), std::string::npos)
      << error;
  auto noNode = animated("translation", "LINEAR", {0.f}, {1, 2, 3});
  noNode.animations[0].channels[0].target_node = 7;
  EXPECT_FALSE(poseAtTime(noNode, 0.0, readCanned, error));
  EXPECT_NE(error.find("node 7, which does not exist"), std::string::npos)
      << error;
  auto uneven = animated("translation", "LINEAR", {0.f, 1.f}, {1, 2, 3, 4});
  EXPECT_FALSE(poseAtTime(uneven, 0.0, readCanned, error));
  // A time that is no number (Python's load_scene passes what it is given).
  auto fine = animated("translation", "LINEAR", {0.f, 1.f}, {0, 0, 0, 1, 1, 1});
  for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    EXPECT_FALSE(poseAtTime(fine, bad, readCanned, error)) << bad;
    EXPECT_NE(error.find("is not finite"), std::string::npos) << error;
  }
  EXPECT_EQ(poseAt(fine, 1e30), (std::vector<double>{1, 1, 1})); // clamped
}

} // namespace
