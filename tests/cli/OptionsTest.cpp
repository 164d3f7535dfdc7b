// prism-render's pieces that need no device: the command line (the --tf-*
// transfer function among it), --param value parsing, camera framing and
// the progress line.
#include "CameraFraming.h"
#include "ColorMaps.h"
#include "Math.h"
#include "Options.h"
#include "Progress.h"
#include "RendererParameters.h"
#include "VolumeStyle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace {

using namespace prism::render;
using namespace prism::scene_io;
namespace scenes = prism::scenes;

ParseResult parse(std::vector<const char *> arguments)
{
  arguments.insert(arguments.begin(), "prism-render");
  return parseOptions(int(arguments.size()), arguments.data());
}

TEST(Options, Defaults)
{
  const ParseResult r = parse({"demo:cornell-box"});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.options.scene, "demo:cornell-box");
  EXPECT_EQ(r.options.width, 1024u);
  EXPECT_EQ(r.options.height, 768u);
  EXPECT_EQ(r.options.samplesPerPixel, 1u);
  EXPECT_EQ(r.options.renderer, "default");
  EXPECT_EQ(r.options.library, "prism");
  EXPECT_TRUE(r.options.output.empty());
}

TEST(Options, EverySpelling)
{
  const ParseResult r = parse({"--scene=model.glb",
      "-o",
      "out.exr",
      "--size",
      "640x480",
      "--spp=16",
      "-r",
      "debug",
      "-p",
      "mode=Ng",
      "--eye",
      "-1,2.5,3e1",
      "--fovy",
      "35",
      "--library",
      "recording",
      "--threads",
      "2",
      "--raw-dims",
      "4x5x6",
      "--raw-type",
      "UINT16"});
  ASSERT_TRUE(r.ok()) << r.error;
  const Options &o = r.options;
  EXPECT_EQ(o.scene, "model.glb");
  EXPECT_EQ(o.output, "out.exr");
  EXPECT_EQ(o.width, 640u);
  EXPECT_EQ(o.height, 480u);
  EXPECT_EQ(o.samplesPerPixel, 16u);
  EXPECT_EQ(o.renderer, "debug");
  ASSERT_EQ(o.rendererParameters.size(), 1u);
  EXPECT_EQ(o.rendererParameters[0].first, "mode");
  EXPECT_EQ(o.rendererParameters[0].second, "Ng");
  ASSERT_TRUE(o.eye.has_value());
  EXPECT_FLOAT_EQ((*o.eye)[0], -1.f);
  EXPECT_FLOAT_EQ((*o.eye)[2], 30.f);
  EXPECT_FLOAT_EQ(o.fovyDegrees.value_or(0.f), 35.f);
  EXPECT_EQ(o.library, "recording");
  EXPECT_EQ(o.threads, 2u);
  ASSERT_TRUE(o.rawDimensions.has_value());
  EXPECT_EQ((*o.rawDimensions)[2], 6u);
  EXPECT_EQ(o.rawType, "uint16");
}

TEST(Options, BadValuesNameTheOption)
{
  const std::vector<std::pair<std::vector<const char *>, const char *>> cases =
      {{{"s.glb", "--size", "0x4"}, "--size"},
          {{"s.glb", "--size", "4x"}, "--size"},
          {{"s.glb", "--size", "70000x4"}, "--size"},
          {{"s.glb", "--spp", "-1"}, "--spp"},
          {{"s.glb", "--spp", "1.5"}, "--spp"},
          {{"s.glb", "--eye", "1,2,nan"}, "--eye"},
          {{"s.glb", "--up", "0,0,0"}, "--up"},
          {{"s.glb", "--fovy", "0"}, "--fovy"},
          {{"s.glb", "--background", "1,2"}, "--background"},
          {{"s.glb", "--param", "=3"}, "--param"},
          {{"s.glb", "--depth", "d.tif"}, "--depth"},
          {{"s.glb", "--bench", "0"}, "--bench"},
          {{"s.glb", "--threads", "x"}, "--threads"},
          {{"s.glb", "--raw-dims", "4x4"}, "--raw-dims"},
          {{"s.raw", "--tf-range", "1"}, "--tf-range"},
          {{"s.raw", "--tf-range", "2,1"}, "--tf-range"},
          {{"s.raw", "--tf-range", "1,1"}, "--tf-range"},
          {{"s.raw", "--tf-range", "0,inf"}, "--tf-range"},
          {{"s.raw", "--tf-map", "jet"}, "--tf-map"},
          {{"s.raw", "--tf-map", ""}, "--tf-map"},
          {{"s.raw", "--tf-opacity", "0,1.5"}, "--tf-opacity"},
          {{"s.raw", "--tf-opacity", "-0.1"}, "--tf-opacity"},
          {{"s.raw", "--tf-opacity", "0,,1"}, "--tf-opacity"},
          {{"s.raw", "--tf-opacity", "0,nan"}, "--tf-opacity"},
          {{"s.raw", "--tf-opacity", ""}, "--tf-opacity"},
          {{"s.raw", "--tf-unit-distance", "0"}, "--tf-unit-distance"},
          {{"s.raw", "--tf-unit-distance", "-1"}, "--tf-unit-distance"},
          {{"s.raw", "--tf-unit-distance", "1e39"}, "--tf-unit-distance"},
          {{"s.nvdb", "--grid", ""}, "--grid"},
          {{"s.glb", "--quiet=yes"}, "--quiet"},
          {{"s.glb", "--output"}, "--output"},
          {{"s.glb", "--nope"}, "--nope"},
          {{"a.glb", "b.glb"}, "more than one scene"},
          {{"-o", "x.png"}, "no scene"}};
  for (const auto &[arguments, fragment] : cases) {
    const ParseResult r = parse(arguments);
    EXPECT_FALSE(r.ok()) << fragment;
    EXPECT_NE(r.error.find(fragment), std::string::npos)
        << "'" << r.error << "' should name " << fragment;
  }
}

TEST(Options, TransferFunction)
{
  const ParseResult defaults = parse({"v.raw"});
  ASSERT_TRUE(defaults.ok()) << defaults.error;
  const TransferFunctionOptions &d = defaults.options.transferFunction;
  EXPECT_FALSE(d.given);
  EXPECT_FALSE(d.valueRange.has_value());
  EXPECT_EQ(d.colorMap, "");
  EXPECT_TRUE(d.opacities.empty());
  EXPECT_FALSE(d.unitDistance.has_value());

  const ParseResult r = parse({"v.nvdb",
      "--tf-range",
      "-1.5,2e3",
      "--tf-map=Viridis",
      "--tf-opacity",
      "0,0.25,1",
      "--tf-unit-distance",
      "0.5",
      "--grid",
      "density"});
  ASSERT_TRUE(r.ok()) << r.error;
  const TransferFunctionOptions &tf = r.options.transferFunction;
  EXPECT_TRUE(tf.given);
  ASSERT_TRUE(tf.valueRange.has_value());
  EXPECT_FLOAT_EQ((*tf.valueRange)[0], -1.5f);
  EXPECT_FLOAT_EQ((*tf.valueRange)[1], 2000.f);
  EXPECT_EQ(tf.colorMap, "viridis");
  EXPECT_EQ(tf.opacities, (std::vector<float>{0.f, 0.25f, 1.f}));
  EXPECT_FLOAT_EQ(tf.unitDistance.value_or(0.f), 0.5f);
  EXPECT_EQ(r.options.gridName, "density");
  // One opacity is a constant; a thousand and twenty-five is too many.
  EXPECT_TRUE(parse({"v.raw", "--tf-opacity", "0.3"}).ok());
  std::string many = "0";
  for (int i = 0; i < 1024; i++)
    many += ",1";
  EXPECT_FALSE(parse({"v.raw", "--tf-opacity", many.c_str()}).ok());
}

TEST(TransferFunction, FromOptionsAndData)
{
  TransferFunctionOptions options;
  scenes::TransferFunction tf = transferFunctionFor(options, 2.f, 10.f);
  EXPECT_EQ(tf.valueRange, (std::array<float, 2>{2.f, 10.f}));
  EXPECT_EQ(tf.colors.size(), 5u); // coolwarm's control points
  EXPECT_EQ(tf.opacities, (std::vector<float>{0.f, 0.05f, 0.2f, 0.5f, 1.f}));
  EXPECT_FLOAT_EQ(tf.unitDistance, 1.f);
  // A constant field still gets a range the device accepts.
  tf = transferFunctionFor(options, 3.f, 3.f);
  EXPECT_LT(tf.valueRange[0], tf.valueRange[1]);

  options.valueRange = std::array<float, 2>{-1.f, 1.f};
  options.colorMap = "grayscale";
  options.opacities = {0.5f};
  options.unitDistance = 4.f;
  tf = transferFunctionFor(options, 2.f, 10.f);
  EXPECT_EQ(tf.valueRange, (std::array<float, 2>{-1.f, 1.f}));
  ASSERT_EQ(tf.colors.size(), 2u);
  EXPECT_EQ(tf.colors[0], (scenes::Vec3{0.f, 0.f, 0.f}));
  EXPECT_EQ(tf.colors[1], (scenes::Vec3{1.f, 1.f, 1.f}));
  EXPECT_EQ(tf.opacities, (std::vector<float>{0.5f}));
  EXPECT_FLOAT_EQ(tf.unitDistance, 4.f);

  // Over a volume's own style, only what is given changes.
  scenes::TransferFunction own;
  own.colors = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  own.opacities = {0.f, 0.3f};
  own.valueRange = {0.f, 1.f};
  own.unitDistance = 0.1f;
  TransferFunctionOptions onlyMap;
  onlyMap.colorMap = "grayscale";
  applyTransferFunctionOptions(onlyMap, own);
  EXPECT_EQ(own.colors.size(), 2u);
  EXPECT_EQ(own.opacities, (std::vector<float>{0.f, 0.3f}));
  EXPECT_EQ(own.valueRange, (std::array<float, 2>{0.f, 1.f}));
  EXPECT_FLOAT_EQ(own.unitDistance, 0.1f);
}

TEST(ColorMaps, NamedMapsDecodeToLinear)
{
  EXPECT_EQ(scenes::colorMapNames(), "coolwarm, viridis, inferno, grayscale");
  for (const scenes::ColorMap &map : scenes::colorMaps()) {
    EXPECT_GE(map.srgbControlPoints.size(), 2u) << map.name;
    for (const scenes::Vec3 &c : scenes::linearColors(map))
      for (float v : c)
        EXPECT_TRUE(v >= 0.f && v <= 1.f) << map.name;
  }
  // sRGB 0.5 is linear 0.214.
  const scenes::ColorMap half{"half", {{0.5f, 0.5f, 0.5f}}};
  EXPECT_NEAR(scenes::linearColors(half)[0][0], 0.2140f, 1e-4f);
  EXPECT_EQ(scenes::findColorMap("jet"), nullptr);
}

TEST(Options, HelpAndListNeedNoScene)
{
  EXPECT_TRUE(parse({"--help"}).ok());
  EXPECT_TRUE(parse({"--list-demos"}).ok());
  EXPECT_NE(helpText().find("Examples"), std::string::npos);
}

TEST(ParameterValues, ParseByDeclaredType)
{
  std::vector<unsigned char> bytes;
  ASSERT_TRUE(parseParameterValue(ANARI_FLOAT32_VEC3, "0.5,1,-2", bytes));
  float v[3];
  ASSERT_EQ(bytes.size(), sizeof(v));
  std::memcpy(v, bytes.data(), sizeof(v));
  EXPECT_FLOAT_EQ(v[0], 0.5f);
  EXPECT_FLOAT_EQ(v[2], -2.f);

  ASSERT_TRUE(parseParameterValue(ANARI_UINT32, "4000000000", bytes));
  uint32_t u = 0;
  std::memcpy(&u, bytes.data(), sizeof(u));
  EXPECT_EQ(u, 4000000000u);
  EXPECT_FALSE(parseParameterValue(ANARI_UINT32, "-1", bytes));
  EXPECT_FALSE(parseParameterValue(ANARI_INT8, "200", bytes));
  EXPECT_FALSE(parseParameterValue(ANARI_FLOAT32, "1,2", bytes));
  EXPECT_FALSE(parseParameterValue(ANARI_FLOAT32, "1e40", bytes));
  EXPECT_FALSE(parseParameterValue(ANARI_ARRAY2D, "1", bytes));

  ASSERT_TRUE(parseParameterValue(ANARI_BOOL, "on", bytes));
  EXPECT_EQ(bytes[0], 1);
  EXPECT_FALSE(parseParameterValue(ANARI_BOOL, "maybe", bytes));
  ASSERT_TRUE(parseParameterValue(ANARI_STRING, "Ng", bytes));
  EXPECT_STREQ((const char *)bytes.data(), "Ng");
}

TEST(CameraFraming, FitsTheBoundsAndHonoursOverrides)
{
  prism::scenes::Bounds bounds;
  bounds.extend(prism::scenes::Vec3{-1.f, -1.f, -1.f});
  bounds.extend(prism::scenes::Vec3{1.f, 1.f, 1.f});
  CameraOverrides options;
  // A box, a flat panel and a long rod, in wide and tall images: every
  // corner inside the frame's kFill, the tighter direction filled to it,
  // the projection centred.
  auto check = [&](const prism::scenes::Bounds &box, float aspect) {
    const CameraSetup framed = frameCamera({}, box, aspect, options);
    EXPECT_TRUE(framed.framed);
    using prism::scenes::Vec3;
    auto sub = [](const Vec3 &a, const Vec3 &b) {
      return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    };
    const Vec3 forward = prism::scenes::normalize(sub(framed.at, framed.eye));
    const Vec3 right =
        prism::scenes::normalize(prism::scenes::cross(forward, framed.up));
    const Vec3 up = prism::scenes::cross(right, forward);
    const float tanY = std::tan(framed.fovyDegrees * 3.14159265f / 360.f);
    const float tanX = tanY * aspect;
    float lowX = 1e9f, highX = -1e9f, lowY = 1e9f, highY = -1e9f;
    for (int c = 0; c < 8; c++) {
      const Vec3 corner{(c & 1) ? box.upper[0] : box.lower[0],
          (c & 2) ? box.upper[1] : box.lower[1],
          (c & 4) ? box.upper[2] : box.lower[2]};
      const Vec3 p = sub(corner, framed.eye);
      const float depth = prism::scenes::dot(p, forward);
      ASSERT_GT(depth, 0.f);
      const float x = prism::scenes::dot(p, right) / (depth * tanX);
      const float y = prism::scenes::dot(p, up) / (depth * tanY);
      lowX = std::min(lowX, x), highX = std::max(highX, x);
      lowY = std::min(lowY, y), highY = std::max(highY, y);
    }
    // Inside the fill (a little slack for the centring's last shift).
    EXPECT_LE(std::max({-lowX, highX, -lowY, highY}), kFill + 0.01f);
    // Tight: the box spans kFill of the frame along one direction.
    EXPECT_GT(std::max(highX - lowX, highY - lowY), 2.f * kFill - 0.03f);
    EXPECT_NEAR(lowX + highX, 0.f, 0.02f);
    EXPECT_NEAR(lowY + highY, 0.f, 0.02f);
  };
  check(bounds, 1.f);
  check(bounds, 16.f / 9.f);
  prism::scenes::Bounds panel;
  panel.extend(prism::scenes::Vec3{-3.f, -2.f, 0.f});
  panel.extend(prism::scenes::Vec3{3.f, 2.f, 0.f});
  check(panel, 4.f / 3.f);
  prism::scenes::Bounds rod;
  rod.extend(prism::scenes::Vec3{-0.1f, -5.f, 10.f});
  rod.extend(prism::scenes::Vec3{0.1f, 5.f, 10.2f});
  check(rod, 0.5f);

  prism::scenes::SuggestedCamera suggested;
  suggested.valid = true;
  suggested.eye = {0.f, 0.f, 5.f};
  suggested.at = {0.f, 0.f, 0.f};
  options.at = prism::scenes::Vec3{1.f, 0.f, 0.f};
  const CameraSetup moved = frameCamera(suggested, bounds, 1.f, options);
  EXPECT_FALSE(moved.framed);
  // A new target keeps the direction: the eye moves with it.
  EXPECT_FLOAT_EQ(moved.eye[0], 1.f);
  EXPECT_FLOAT_EQ(moved.eye[2], 5.f);
}

TEST(Progress, Line)
{
  const std::string line = Progress::format(16, 64, "samples", 2.0, 10);
  EXPECT_NE(line.find("16/64 samples"), std::string::npos) << line;
  EXPECT_NE(line.find("[###.......]"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 6.00 s"), std::string::npos) << line;
  EXPECT_EQ(Progress::format(64, 64, "samples", 2.0, 10).find("ETA"),
      std::string::npos);
}

} // namespace
