// glTF node hierarchies as deep as a file likes: a chain of 30,000 nodes,
// each moving its child a little, loads (no recursion over the file's
// depth) and places its mesh where the whole chain's transforms put it.
#include "GltfLoader.h"

#include <anari/anari.h>

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace prism::scene_io;

// One triangle, (0,0,0) (1,0,0) (0,1,0), as a base64 data URI.
const char *kTriangleBuffer =
    "data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

// `depth` nodes in a chain, each translated by `step` along x, the last
// holding the triangle.
std::string chain(int depth, double step)
{
  std::string nodes;
  for (int i = 0; i < depth; i++) {
    nodes += i ? "," : "";
    nodes += "{\"translation\":[" + std::to_string(step) + ",0,0]";
    nodes += i + 1 < depth ? ",\"children\":[" + std::to_string(i + 1) + "]"
                           : std::string(",\"mesh\":0");
    nodes += "}";
  }
  return std::string(R"({"asset":{"version":"2.0"},"scene":0,)")
         + R"("scenes":[{"nodes":[0]}],"nodes":[)" + nodes + "],"
         + R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
         + R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,)"
         + R"("type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
         + R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
         + R"("buffers":[{"byteLength":36,"uri":")" + kTriangleBuffer + "\"}]}";
}

class GltfDepth : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    m_library = anariLoadLibrary("prism", nullptr, nullptr);
    ASSERT_NE(m_library, nullptr);
    m_device = anariNewDevice(m_library, "default");
    ASSERT_NE(m_device, nullptr);
  }
  void TearDown() override
  {
    if (m_device)
      anariRelease(m_device, m_device);
    if (m_library)
      anariUnloadLibrary(m_library);
  }
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
};

TEST_F(GltfDepth, ThirtyThousandNodeChainLoads)
{
  const int depth = 30000;
  LoadResult loaded =
      loadGltfFromMemory(m_device, chain(depth, 0.001), "chain.gltf", {});
  ASSERT_TRUE(loaded.ok()) << loaded.error;
  // The triangle moved by the sum of the chain's steps: x from 30 to 31.
  const auto &bounds = loaded.scene.bounds;
  EXPECT_NEAR(bounds.lower[0], depth * 0.001, 1e-3);
  EXPECT_NEAR(bounds.upper[0], depth * 0.001 + 1.0, 1e-3);
  EXPECT_NEAR(bounds.lower[1], 0.0, 1e-6);
  EXPECT_NEAR(bounds.upper[1], 1.0, 1e-6);
  prism::scenes::releaseScene(m_device, loaded.scene);
}

TEST_F(GltfDepth, CycleInADeepChainIsRefused)
{
  std::string json = chain(5000, 0.001);
  // The last node names the first as its child: a cycle 5,000 deep.
  const std::string last = "\"mesh\":0}";
  json.replace(json.rfind(last), last.size(), "\"mesh\":0,\"children\":[0]}");
  LoadResult loaded = loadGltfFromMemory(m_device, json, "cycle.gltf", {});
  EXPECT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error.find("is its own ancestor"), std::string::npos)
      << loaded.error;
  prism::scenes::releaseScene(m_device, loaded.scene);
}

} // namespace
