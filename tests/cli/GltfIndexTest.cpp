// glTF indices checked as the JSON writes them (GltfIndexCheck), and how
// it reads the JSON (nlohmann's parser, integers exact, literals kept).
#include "GltfIndexCheck.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace {

using namespace prism::scene_io;

// A file with one of everything that holds an index; each $name is replaced
// by the value the test gives, or 0. (The extras hold 1e308, not 1e999:
// nlohmann's parser, tinygltf's too, refuses a float that overflows.)
const char *kTemplate = R"({
  "asset": {"version": "2.0"},
  "scene": $scene,
  "scenes": [{"nodes": [$sceneNode]}],
  "nodes": [
    {"children": [$child], "mesh": $mesh, "camera": $camera, "skin": $skin,
     "extensions": {"KHR_lights_punctual": {"light": $light}}},
    {}
  ],
  "meshes": [{"primitives": [{
    "attributes": {"POSITION": $position},
    "indices": $indices, "material": $material, "mode": $mode,
    "targets": [{"POSITION": $target}]}]}],
  "materials": [{
    "pbrMetallicRoughness": {"baseColorTexture": {"index": $baseTexture,
                                                  "texCoord": $texCoord}},
    "extensions": {"KHR_materials_clearcoat": {
      "clearcoatTexture": {"index": $clearcoatTexture}}},
    "extras": {"anything": [1e308, "\u0000", {"index": -5}]}}],
  "textures": [{"sampler": $sampler, "source": $source,
                "extensions": {"EXT_texture_webp": {"source": $webp}}}],
  "samplers": [{"magFilter": $magFilter}],
  "images": [{"bufferView": $imageView}],
  "accessors": [{"bufferView": $accessorView, "componentType": $componentType,
    "count": 1, "type": "SCALAR",
    "sparse": {"count": 1, "indices": {"bufferView": $sparseIndices,
                                       "componentType": 5125},
               "values": {"bufferView": $sparseValues}}}],
  "bufferViews": [{"buffer": $buffer, "byteLength": 4}],
  "buffers": [{"byteLength": 4}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 1, "znear": 1}}],
  "skins": [{"joints": [$joint], "skeleton": $skeleton,
             "inverseBindMatrices": $inverseBind}],
  "animations": [{"channels": [{"sampler": $channelSampler,
                                "target": {"node": $targetNode}}],
                  "samplers": [{"input": $input, "output": $output}]}],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}}
})";

std::string document(const std::map<std::string, std::string> &values = {})
{
  std::string text = kTemplate;
  for (size_t at = text.find('$'); at != std::string::npos;
       at = text.find('$', at)) {
    size_t end = at + 1;
    while (end < text.size() && std::isalnum((unsigned char)text[end]))
      end++;
    const std::string name = text.substr(at + 1, end - at - 1);
    auto found = values.find(name);
    const std::string value = found == values.end() ? "0" : found->second;
    text.replace(at, end - at, value);
    at += value.size();
  }
  return text;
}

TEST(GltfIndexCheck, EveryIndexInRangePasses)
{
  EXPECT_EQ(checkGltfIndices(document()), "");
  // The second node and a mode of 4 are in range too.
  EXPECT_EQ(checkGltfIndices(document({{"child", "1"}, {"mode", "4"}})), "");
}

// Each index, one past its array, 2^32 (tinygltf's int cast made it 0),
// negative and fractional, must fail with a message naming it.
TEST(GltfIndexCheck, EveryIndexOutOfRangeFails)
{
  const std::pair<const char *, const char *> indices[] = {
      {"scene", "scene is $, but the file has 1 scene"},
      {"sceneNode", "scenes[0].nodes[0] is $, but the file has 2 nodes"},
      {"child", "nodes[0].children[0] is $, but the file has 2 nodes"},
      {"mesh", "nodes[0].mesh is $, but the file has 1 mesh"},
      {"camera", "nodes[0].camera is $, but the file has 1 camera"},
      {"skin", "nodes[0].skin is $, but the file has 1 skin"},
      {"light",
          "nodes[0].extensions.KHR_lights_punctual.light is $, but the file "
          "has 1 light"},
      {"position",
          "meshes[0].primitives[0].attributes.POSITION is $, but the file has "
          "1 accessor"},
      {"indices", "meshes[0].primitives[0].indices is $"},
      {"material", "meshes[0].primitives[0].material is $, but the file has"},
      {"target", "meshes[0].primitives[0].targets[0].POSITION is $"},
      {"baseTexture",
          "materials[0].pbrMetallicRoughness.baseColorTexture.index is $, but "
          "the file has 1 texture"},
      {"clearcoatTexture",
          "materials[0].extensions.KHR_materials_clearcoat.clearcoatTexture."
          "index is $"},
      {"sampler", "textures[0].sampler is $, but the file has 1 sampler"},
      {"source", "textures[0].source is $, but the file has 1 image"},
      {"webp", "textures[0].extensions.EXT_texture_webp.source is $"},
      {"imageView",
          "images[0].bufferView is $, but the file has 1 buffer view"},
      {"accessorView", "accessors[0].bufferView is $"},
      {"sparseIndices", "accessors[0].sparse.indices.bufferView is $"},
      {"sparseValues", "accessors[0].sparse.values.bufferView is $"},
      {"buffer", "bufferViews[0].buffer is $, but the file has 1 buffer"},
      {"joint", "skins[0].joints[0] is $, but the file has 2 nodes"},
      {"skeleton", "skins[0].skeleton is $"},
      {"inverseBind", "skins[0].inverseBindMatrices is $"},
      {"channelSampler",
          "animations[0].channels[0].sampler is $, but the "
          "file has 1 sampler"},
      {"targetNode", "animations[0].channels[0].target.node is $"},
      {"input", "animations[0].samplers[0].input is $"},
      {"output", "animations[0].samplers[0].output is $"},
  };
  for (const auto &[name, pattern] : indices) {
    // Past the end of each array (2 nodes, 1 of everything else).
    const std::string pastEnd =
        std::string(name).find("ode") != std::string::npos
                || std::string(name) == "child" || std::string(name) == "joint"
                || std::string(name) == "skeleton"
            ? "2"
            : "1";
    for (const std::string &value : {pastEnd,
             std::string("4294967296"),
             std::string("-1"),
             std::string("18446744073709551617")}) {
      std::string expected = pattern;
      expected.replace(expected.find('$'), 1, value);
      const std::string error = checkGltfIndices(document({{name, value}}));
      EXPECT_NE(error.find(expected), std::string::npos)
          << name << " = " << value << " gave: '" << error << "'";
    }
    const std::string error = checkGltfIndices(document({{name, "0.5"}}));
    EXPECT_NE(error.find("is 0.5, which is not an index"), std::string::npos)
        << name << " gave: '" << error << "'";
    const std::string text = checkGltfIndices(document({{name, "\"0\""}}));
    EXPECT_NE(text.find("is not an index"), std::string::npos)
        << name << " gave: '" << text << "'";
  }
}

// Integers tinygltf casts to int that are not indices: 2^32 + 5126 would
// read as FLOAT, 2^32 + 4 as TRIANGLES.
TEST(GltfIndexCheck, NarrowedIntegersMustFitAnInt)
{
  EXPECT_NE(checkGltfIndices(document({{"componentType", "4294972422"}}))
                .find("accessors[0].componentType is 4294972422, out of range"),
      std::string::npos);
  EXPECT_NE(checkGltfIndices(document({{"mode", "4294967300"}}))
                .find("meshes[0].primitives[0].mode is 4294967300"),
      std::string::npos);
  EXPECT_NE(checkGltfIndices(document({{"texCoord", "4294967297"}}))
                .find("baseColorTexture.texCoord is 4294967297"),
      std::string::npos);
  EXPECT_NE(checkGltfIndices(document({{"magFilter", "-9728"}}))
                .find("samplers[0].magFilter is -9728"),
      std::string::npos);
  EXPECT_EQ(checkGltfIndices(document({{"componentType", "2147483647"}})), "");
}

// A key spelled with escapes is the same key to tinygltf's JSON parser.
TEST(GltfIndexCheck, EscapedKeysAndLastDuplicateCount)
{
  std::string text = document({{"mesh", "0"}});
  text.replace(text.find("\"mesh\""), 6, "\"\\u006desh\"");
  text.replace(text.find("\"\\u006desh\": 0"), 14, "\"\\u006desh\": 7");
  EXPECT_NE(
      checkGltfIndices(text).find("nodes[0].mesh is 7"), std::string::npos);
  // Every duplicate is checked, the last one (the one tinygltf keeps) too.
  std::string twice = document();
  twice.replace(twice.find("\"mesh\": 0"), 9, "\"mesh\": 0, \"mesh\": 3");
  EXPECT_NE(
      checkGltfIndices(twice).find("nodes[0].mesh is 3"), std::string::npos);
}

TEST(GltfIndexCheck, GlbJsonChunk)
{
  const std::string json = R"({"asset":{"version":"2.0"},"scene":1})";
  auto le32 = [](uint32_t v) {
    return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
  };
  const std::string glb = "glTF" + le32(2) + le32(20 + uint32_t(json.size()))
                          + le32(uint32_t(json.size())) + "JSON" + json;
  EXPECT_EQ(glbJsonChunk(glb), json);
  EXPECT_EQ(checkGltfIndices(glbJsonChunk(glb)),
      "scene is 1, but the file has 0 scenes");
  EXPECT_EQ(glbJsonChunk(glb.substr(0, glb.size() - 1)), "");
  EXPECT_EQ(glbJsonChunk("glTF"), "");
}

TEST(GltfJson, KeepsIntegersExactly)
{
  const GltfJson d = parseGltfJson(
      "\xEF\xBB\xBF{\"a\": [0, -3, 18446744073709551615, "
      "18446744073709551616, 1.0, 2e3, -0], \"s\": "
      "\"x\\\"\\u00e9\\ud83d\\ude00\"}");
  ASSERT_TRUE(d.ok()) << d.error;
  const nlohmann::json &a = d.root.at("a");
  ASSERT_TRUE(a.is_array());
  ASSERT_EQ(a.size(), 7u);
  EXPECT_TRUE(a[0].is_number_unsigned());
  EXPECT_EQ(a[0].get<uint64_t>(), 0u);
  EXPECT_TRUE(a[1].is_number_integer() && !a[1].is_number_unsigned());
  EXPECT_EQ(a[1].get<int64_t>(), -3);
  EXPECT_TRUE(a[2].is_number_unsigned());
  EXPECT_EQ(a[2].get<uint64_t>(), UINT64_MAX);
  // Beyond 64 bits: a float, quoted as written.
  EXPECT_TRUE(a[3].is_number_float());
  EXPECT_EQ(d.text(a[3]), "18446744073709551616");
  EXPECT_EQ(d.text(a[2]), "18446744073709551615");
  EXPECT_TRUE(a[4].is_number_float());
  EXPECT_EQ(d.text(a[4]), "1.0");
  EXPECT_EQ(d.text(a[5]), "2e3");
  EXPECT_EQ(d.text(a[6]), "0");
  // Strings are decoded; long ones keep their first 256 bytes.
  EXPECT_EQ(d.root.at("s").get<std::string>(), "x\"\u00e9\U0001F600");
  const GltfJson uri =
      parseGltfJson("{\"uri\": \"data:" + std::string(100000, 'A') + "\"}");
  ASSERT_TRUE(uri.ok()) << uri.error;
  EXPECT_EQ(
      uri.root.at("uri").get<std::string>(), "data:" + std::string(251, 'A'));
}

// The text of a duplicated key's float is the kept (last) one's.
TEST(GltfJson, LiteralsFollowTheKeptDuplicate)
{
  const GltfJson d = parseGltfJson(R"({"a": 1.50, "b": [2.0], "a": 3.25})");
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_EQ(d.text(d.root.at("a")), "3.25");
  EXPECT_EQ(d.text(d.root.at("b")[0]), "2.0");
}

TEST(GltfJson, RejectsWhatIsNotJson)
{
  for (const char *bad : {"",
           "{",
           "[1,]",
           "{\"a\" 1}",
           "01",
           "1.",
           "-",
           "\"\\x\"",
           "\"a",
           "[1 2]",
           "{} x",
           "nul",
           "\"\t\""})
    EXPECT_FALSE(parseGltfJson(bad).ok()) << bad;
  EXPECT_NE(checkGltfIndices("{\"scene\": ").find("cannot check its indices"),
      std::string::npos);
  // Nesting is bounded.
  EXPECT_TRUE(
      parseGltfJson(std::string(100, '[') + std::string(100, ']')).ok());
  const GltfJson deep =
      parseGltfJson(std::string(100000, '[') + std::string(100000, ']'));
  EXPECT_NE(
      deep.error.find("nested deeper than 512 levels"), std::string::npos);
}

} // namespace
