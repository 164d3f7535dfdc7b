// Scenes rendered through libnsi on the prism device, checked by pixels:
// the facts file's Example 1, and the camera-framing scene whose lit pixels
// are predicted from NSI's fov / screenwindow / crop formulas.
#include "NsiTestSupport.h"

#include "ImageIO.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <random>
#include <thread>

namespace {

using prism::image::Image;

// How the camera and mesh motion scenes are rendered: samples at t = 0
// and 1 with the shutter open over [0, 1], the same samples without a
// shutter range, or a plain value (the pose at t = 0 or t = 1).
enum class Motion { Shutter, NoShutter, StillOpen, StillClose };

class Render : public NsiTest
{
 protected:
  // The image of each Motion of a scene (`scene(context, motion,
  // output)`), each rendered in a context of its own, reporting nothing.
  std::map<Motion, Image> everyMotion(
      const std::function<Image(NSIContext_t, Motion, const std::string &)>
          &scene)
  {
    std::map<Motion, Image> images;
    for (Motion motion : {Motion::Shutter,
             Motion::NoShutter,
             Motion::StillOpen,
             Motion::StillClose}) {
      NSIContext_t ctx = beginRender();
      images[motion] =
          scene(ctx, motion, path(std::to_string(int(motion)) + ".exr"));
      NSIEnd(ctx);
      EXPECT_EQ(m_messages.problems(), "") << int(motion);
    }
    return images;
  }
  Image readImage(const std::string &file)
  {
    auto result = prism::image::read(file);
    EXPECT_TRUE(result.ok()) << file << ": " << result.error;
    return result.image;
  }
  // Luminance of the pixel in column x, row y counted from the TOP.
  static float value(const Image &image, uint32_t x, uint32_t yFromTop)
  {
    const auto &p = image.at(x, image.height - 1 - yFromTop);
    return (p.r + p.g + p.b) / 3.f;
  }
};

// Example 1 at 64x48 (the facts file's text otherwise unchanged).
const char *kExample1 = R"(# Floor lit by a hidden quad light, written as a PNG.
Create "cam_xf" "transform"
SetAttribute "cam_xf"
  "transformationmatrix" "doublematrix" 1 [ 1 0 0 0  0 1 0 0  0 0 1 0  0 1 6 1 ]
Connect "cam_xf" "" ".root" "objects"
Create "cam" "perspectivecamera"
SetAttribute "cam"
  "fov" "float" 1 45
Connect "cam" "" "cam_xf" "objects"
Create "scr" "screen"
SetAttribute "scr"
  "resolution" "int[2]" 1 [ 64 48 ]
  "oversampling" "int" 1 16
Connect "scr" "" "cam" "screens"
Create "beauty" "outputlayer"
SetAttribute "beauty"
  "variablename" "string" 1 "Ci"
  "scalarformat" "string" 1 "uint8"
Connect "beauty" "" "scr" "outputlayers"
Create "file" "outputdriver"
SetAttribute "file"
  "drivername" "string" 1 "png"
  "imagefilename" "string" 1 "${PRISM_NSI_OUT}/example1.png"
Connect "file" "" "beauty" "outputdrivers"
Create "floor" "mesh"
SetAttribute "floor"
  "nvertices" "int" 1 4
  "P" "point" 4 [ -3 0 3  3 0 3  3 0 -3  -3 0 -3 ]
Connect "floor" "" ".root" "objects"
Create "grey" "shader"
SetAttribute "grey"
  "shaderfilename" "string" 1 "${DELIGHT}/osl/dlPrincipled.oso"
  "i_color" "color" 1 [ 0.6 0.6 0.6 ]
Create "floor_attr" "attributes"
Connect "grey" "" "floor_attr" "surfaceshader"
Connect "floor_attr" "" "floor" "geometryattributes"
Create "lamp_xf" "transform"
SetAttribute "lamp_xf"
  "transformationmatrix" "doublematrix" 1 [ 1 0 0 0  0 1 0 0  0 0 1 0  0 3 0 1 ]
Connect "lamp_xf" "" ".root" "objects"
Create "lamp" "mesh"
SetAttribute "lamp"
  "nvertices" "int" 1 4
  "P" "point" 4 [ -0.5 0 -0.5  0.5 0 -0.5  0.5 0 0.5  -0.5 0 0.5 ]
Connect "lamp" "" "lamp_xf" "objects"
Create "glow" "shader"
SetAttribute "glow"
  "shaderfilename" "string" 1 "emitter"
  "power" "float" 1 100
Create "lamp_attr" "attributes"
SetAttribute "lamp_attr"
  "visibility.camera" "int" 1 0
Connect "glow" "" "lamp_attr" "surfaceshader"
Connect "lamp_attr" "" "lamp_xf" "geometryattributes"
RenderControl
  "action" "string" 1 "start"
RenderControl
  "action" "string" 1 "wait"
)";

TEST_F(Render, Example1)
{
  const std::string scene = writeFile("example1.nsi", kExample1);
  ::setenv("PRISM_NSI_OUT", m_dir.c_str(), 1);
  NSIContext_t ctx = beginRender();
  include(ctx, scene);
  NSIEnd(ctx);
  ::unsetenv("PRISM_NSI_OUT");
  EXPECT_EQ(m_messages.problems(), "");
  const Image image = readImage(path("example1.png"));
  ASSERT_EQ(image.width, 64u);
  ASSERT_EQ(image.height, 48u);
  // Camera at height 1 looking along -Z with a 45 degree vertical fov
  // (tan 22.5 = 0.414): the floor runs from its far edge (z = -3, row 30.4)
  // to its near edge (z = 3, row 43.3); the point under the lamp (z = 0) is
  // row 33.7. Above and below the floor, the black background.
  const float floorUnderLamp = value(image, 32, 34);
  EXPECT_GT(floorUnderLamp, 0.05f);
  for (uint32_t row : {0u, 12u, 24u, 29u, 45u, 47u})
    EXPECT_EQ(value(image, 32, row), 0.f) << "row " << row;
  for (uint32_t row = 32; row <= 42; ++row)
    EXPECT_GT(value(image, 32, row), 0.f) << "row " << row;
  // The lamp (rows 3-6, columns 29-35) is hidden from the camera: black,
  // though seen directly it would be far brighter than anything.
  for (uint32_t y = 3; y <= 6; ++y)
    for (uint32_t x = 29; x <= 35; ++x)
      EXPECT_EQ(value(image, x, y), 0.f) << x << "," << y;
  // Light falls off away from the lamp: the floor under it is brighter
  // than the floor near the camera.
  EXPECT_GT(floorUnderLamp, 2 * value(image, 32, 42));
}

// What the stopped callback saw.
struct StopRecord
{
  std::mutex mutex;
  std::vector<std::pair<NSIContext_t, int>> calls;

  static void callback(void *data, NSIContext_t ctx, int status)
  {
    auto *self = static_cast<StopRecord *>(data);
    std::lock_guard lock(self->mutex);
    self->calls.emplace_back(ctx, status);
  }
};

// A camera, screen and one PNG output; `oversampling` frames per render.
void minimalScene(
    NSIContext_t ctx, int size, int oversampling, const std::string &output)
{
  NSICreate(ctx, "cam", "perspectivecamera", 0, nullptr);
  NSIConnect(ctx, "cam", "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  NSICreate(ctx, "scr", "screen", 0, nullptr);
  NSI::ArgumentList screen;
  const int resolution[2] = {size, size};
  screen.add("resolution", NSITypeInteger, resolution, 1, 2, NSIParamIsArray);
  screen.addInteger("oversampling", oversampling);
  NSISetAttribute(ctx, "scr", screen.size(), screen.data());
  NSIConnect(ctx, "scr", "", "cam", "screens", 0, nullptr);
  NSICreate(ctx, "layer", "outputlayer", 0, nullptr);
  NSIConnect(ctx, "layer", "", "scr", "outputlayers", 0, nullptr);
  NSICreate(ctx, "driver", "outputdriver", 0, nullptr);
  NSI::ArgumentList driver;
  driver.addString("drivername", "png")
      .addString("imagefilename", output.c_str());
  NSISetAttribute(ctx, "driver", driver.size(), driver.data());
  NSIConnect(ctx, "driver", "", "layer", "outputdrivers", 0, nullptr);
}

void renderControl(NSIContext_t ctx,
    const char *action,
    StopRecord *record = nullptr,
    bool progressive = false)
{
  NSI::ArgumentList args;
  args.addString("action", action);
  if (progressive)
    args.addInteger("progressive", 1);
  if (record) {
    args.addPointer("stoppedcallback",
        reinterpret_cast<const void *>(&StopRecord::callback));
    args.addPointer("stoppedcallbackdata", record);
  }
  NSIRenderControl(ctx, args.size(), args.data());
}

// A glowing square seen by a camera, built with the C API...
void squareScene(NSIContext_t ctx, const std::string &output)
{
  minimalScene(ctx, 24, 4, output);
  NSICreate(ctx, "square", "mesh", 0, nullptr);
  {
    const float P[12] = {-1, -1, -4, 1, -1, -4, 1, 1, -4, -1, 1, -4};
    NSI::ArgumentList args;
    args.addInteger("nvertices", 4);
    args.add("P", NSITypePoint, P, 4);
    NSISetAttribute(ctx, "square", args.size(), args.data());
  }
  NSIConnect(ctx, "square", "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  NSICreate(ctx, "glow", "shader", 0, nullptr);
  {
    NSI::ArgumentList args;
    args.addString("shaderfilename", "emitter").addFloat("power", 1);
    NSISetAttribute(ctx, "glow", args.size(), args.data());
  }
  NSICreate(ctx, "attr", "attributes", 0, nullptr);
  NSIConnect(ctx, "glow", "", "attr", "surfaceshader", 0, nullptr);
  NSIConnect(ctx, "attr", "", "square", "geometryattributes", 0, nullptr);
}

// ... and with Lua, the output named by a script parameter.
const char *kSquareLua = R"(
local out = nsi.scriptparameters.output.data
nsi.Create("cam", "perspectivecamera")
nsi.Connect("cam", "", ".root", "objects")
nsi.Create("scr", "screen")
nsi.SetAttribute("scr", {
  {name="resolution", data={24, 24}, type=nsi.TypeInteger, arraylength=2},
  {name="oversampling", data=4}})
nsi.Connect("scr", "", "cam", "screens")
nsi.Create("layer", "outputlayer")
nsi.Connect("layer", "", "scr", "outputlayers")
nsi.Create("driver", "outputdriver")
nsi.SetAttribute("driver", {name="drivername", data="png"},
  {name="imagefilename", data=out})
nsi.Connect("driver", "", "layer", "outputdrivers")
nsi.Create("square", "mesh")
nsi.SetAttribute("square", {name="nvertices", data=4},
  {name="P", type=nsi.TypePoint, data={-1,-1,-4, 1,-1,-4, 1,1,-4, -1,1,-4}})
nsi.Connect("square", "", ".root", "objects")
nsi.Create("glow", "shader")
nsi.SetAttribute("glow", {name="shaderfilename", data="emitter"},
  {name="power", data=1.0})
nsi.Create("attr", "attributes")
nsi.Connect("glow", "", "attr", "surfaceshader")
nsi.Connect("attr", "", "square", "geometryattributes")
)";

TEST_F(Render, LuaSceneMatchesTheCApi)
{
  NSIContext_t ctx = beginRender();
  squareScene(ctx, path("c.png"));
  renderControl(ctx, "start");
  renderControl(ctx, "wait");
  NSIEnd(ctx);
  ASSERT_EQ(m_messages.problems(), "");

  ctx = beginRender();
  NSI::ArgumentList args;
  args.addString("type", "lua")
      .addString("script", kSquareLua)
      .addString("output", path("lua.png").c_str());
  NSIEvaluate(ctx, args.size(), args.data());
  if (m_messages.problems().find("not available") != std::string::npos) {
    NSIEnd(ctx);
    GTEST_SKIP() << "libnsi was built without Lua";
  }
  renderControl(ctx, "start");
  renderControl(ctx, "wait");
  NSIEnd(ctx);
  ASSERT_EQ(m_messages.problems(), "");

  const Image c = readImage(path("c.png"));
  const Image lua = readImage(path("lua.png"));
  ASSERT_EQ(c.width, 24u);
  ASSERT_EQ(c.height, 24u);
  ASSERT_EQ(lua.width, c.width);
  ASSERT_EQ(lua.height, c.height);
  // The square fills the middle; the corners see the black background.
  EXPECT_GT(value(c, 12, 12), 0.05f);
  EXPECT_EQ(value(c, 0, 0), 0.f);
  for (uint32_t y = 0; y < c.height; ++y)
    for (uint32_t x = 0; x < c.width; ++x)
      EXPECT_EQ(value(lua, x, y), value(c, x, y)) << x << "," << y;
}

TEST_F(Render, StoppedCallbackReportsCompletion)
{
  StopRecord record;
  NSIContext_t ctx = beginRender();
  minimalScene(ctx, 8, 2, path("done.png"));
  renderControl(ctx, "start", &record);
  renderControl(ctx, "wait");
  {
    std::lock_guard lock(record.mutex);
    ASSERT_EQ(record.calls.size(), 1u);
    EXPECT_EQ(record.calls[0].first, ctx);
    EXPECT_EQ(record.calls[0].second, NSIRenderCompleted);
  }
  EXPECT_TRUE(std::filesystem::exists(path("done.png")));
  // A second start after the first ended renders again.
  renderControl(ctx, "start", &record);
  renderControl(ctx, "wait");
  NSIEnd(ctx);
  EXPECT_EQ(record.calls.size(), 2u);
  EXPECT_EQ(m_messages.problems(), "");
}

TEST_F(Render, StopAbortsALongRender)
{
  StopRecord record;
  NSIContext_t ctx = beginRender();
  // 4096 samples of 256x256: far longer than the test waits.
  minimalScene(ctx, 256, 4096, path("stopped.png"));
  renderControl(ctx, "start", &record);
  renderControl(ctx, "start"); // while running: refused
  EXPECT_TRUE(reportedOnce(m_messages, {"'start' while a render is running"}));
  renderControl(ctx, "stop");
  {
    std::lock_guard lock(record.mutex);
    ASSERT_EQ(record.calls.size(), 1u);
    EXPECT_EQ(record.calls[0].second, NSIRenderAborted);
  }
  NSIEnd(ctx);
}

TEST_F(Render, SynchronizeRestartsARunningRender)
{
  StopRecord record;
  NSIContext_t ctx = beginRender();
  minimalScene(ctx, 256, 4096, path("restarted.png"));
  renderControl(ctx, "start", &record);
  renderControl(ctx, "synchronize"); // the callback given at start stays
  renderControl(ctx, "stop");
  NSIEnd(ctx);
  std::lock_guard lock(record.mutex);
  ASSERT_EQ(record.calls.size(), 2u);
  EXPECT_EQ(record.calls[0].second, NSIRenderRestarted);
  EXPECT_EQ(record.calls[1].second, NSIRenderAborted);
}

TEST_F(Render, EndWhileRenderingStopsCleanly)
{
  NSIContext_t ctx = beginRender();
  minimalScene(ctx, 256, 4096, path("ended.png"));
  renderControl(ctx, "start");
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
}

TEST_F(Render, BadSceneDataIsReportedNotRendered)
{
  const std::string scene = writeFile("bad.nsi", R"(
Create "cam" "perspectivecamera" Connect "cam" "" ".root" "objects"
SetAttribute "cam" "fov" "float" 1 nan
Create "scr" "screen" Connect "scr" "" "cam" "screens"
SetAttribute "scr" "resolution" "int[2]" 1 [ 1000000 1000000 ]
  "oversampling" "float" 1 nan
Create "huge" "mesh" Connect "huge" "" ".root" "objects"
SetAttribute "huge" "nvertices" "double" 1 1e300 "P" "point" 3 [ 0 0 0 1 0 0 0 1 0 ]
Create "outside" "mesh" Connect "outside" "" ".root" "objects"
SetAttribute "outside" "nvertices" "int" 1 3 "P" "point" 3 [ 0 0 0 1 0 0 0 1 0 ]
  "P.indices" "int" 3 [ 0 1 7 ]
Create "short" "mesh" Connect "short" "" ".root" "objects"
SetAttribute "short" "nvertices" "int" 2 [ 3 3 ] "P" "point" 3 [ 0 0 0 1 0 0 0 1 0 ]
Create "dust" "particles" Connect "dust" "" ".root" "objects"
SetAttribute "dust" "P" "point" 2 [ 0 0 -5 1 0 -5 ] "width" "float" 3 [ 1 1 1 ]
Create "knot" "curves" Connect "knot" "" ".root" "objects"
Create "fog" "volume" Connect "fog" "" ".root" "objects"
RenderControl "action" "string" 1 "start"
RenderControl "action" "string" 1 "wait"
)");
  NSIContext_t ctx = beginRender();
  include(ctx, scene);
  NSIEnd(ctx);
  const std::string problems = m_messages.problems();
  for (const char *expected : {"mesh 'huge': 'nvertices' holds 1e+300;",
           "mesh 'outside': 'P.indices' holds 7, outside 'P'",
           "mesh 'short': 'nvertices' adds up to 6 but there are 3",
           "particles 'dust': 'width' count does not match 'P'",
           "curves 'knot': no 'P'",
           "volume 'fog' has no vdbfilename",
           "bad 'resolution'"})
    EXPECT_NE(problems.find(expected), std::string::npos) << expected << "\n"
                                                          << problems;
  EXPECT_EQ(m_messages.problems(NSIErrError), "");
}

TEST_F(Render, OutputLayersWriteTheirChannels)
{
  // A white square facing the camera 10 units away, filling the middle.
  std::string layers;
  for (auto [variable, file] : {std::pair{"Ci", "color.exr"},
           {"z", "depth.exr"},
           {"N.world", "normal.exr"},
           {"albedo", "albedo.pfm"},
           {"mystery", "mystery.png"}}) {
    layers += std::string("Create \"") + variable + "\" \"outputlayer\"\n"
        + "SetAttribute \"" + variable + "\" \"variablename\" \"string\" 1 \""
        + variable + "\"\n" + "Connect \"" + variable
        + "\" \"\" \"scr\" \"outputlayers\"\n" + "Create \"" + file
        + "\" \"outputdriver\"\n" + "SetAttribute \"" + file
        + "\" \"drivername\" \"string\" 1 \"exr\" \"imagefilename\" "
          "\"string\" 1 \"${PRISM_NSI_OUT}/"
        + file + "\"\n" + "Connect \"" + file + "\" \"\" \"" + variable
        + "\" \"outputdrivers\"\n";
  }
  layers += "SetAttribute \"z\" \"scalarformat\" \"string\" 1 \"half\"\n";
  const std::string scene =
      writeFile("layers.nsi",
          R"(Create "cam" "perspectivecamera" Connect "cam" "" ".root" "objects"
SetAttribute "cam" "fov" "float" 1 30
Create "scr" "screen" Connect "scr" "" "cam" "screens"
SetAttribute "scr" "resolution" "int[2]" 1 [ 16 16 ] "oversampling" "int" 1 2
Create "sq" "mesh" Connect "sq" "" ".root" "objects"
SetAttribute "sq" "nvertices" "int" 1 4
  "P" "point" 4 [ -1 -1 -10  1 -1 -10  1 1 -10  -1 1 -10 ]
Create "white" "shader" SetAttribute "white" "shaderfilename" "string" 1 "lambert"
  "i_color" "color" 1 [ 1 1 1 ]
Create "attr" "attributes" Connect "white" "" "attr" "surfaceshader"
Connect "attr" "" "sq" "geometryattributes"
)" + layers + R"(RenderControl "action" "string" 1 "start"
RenderControl "action" "string" 1 "wait"
)");
  ::setenv("PRISM_NSI_OUT", m_dir.c_str(), 1);
  NSIContext_t ctx = beginRender();
  include(ctx, scene);
  NSIEnd(ctx);
  ::unsetenv("PRISM_NSI_OUT");
  const std::string problems = m_messages.problems();
  EXPECT_NE(problems.find("variable 'mystery' has no ANARI channel"),
      std::string::npos)
      << problems;
  EXPECT_EQ(std::count(problems.begin(), problems.end(), '\n'), 1) << problems;

  // The middle pixels see the square's centre region, straight ahead.
  const Image depth = readImage(path("depth.exr"));
  const Image normal = readImage(path("normal.exr"));
  const Image albedo = readImage(path("albedo.pfm"));
  const Image mystery = readImage(path("mystery.png"));
  ASSERT_EQ(depth.width, 16u);
  ASSERT_EQ(normal.width, 16u);
  ASSERT_EQ(albedo.width, 16u);
  ASSERT_EQ(mystery.width, 16u);
  const auto &d = depth.at(8, 8);
  EXPECT_NEAR(d.r, 10.0f, 0.05f); // distance along a ray 1 degree off axis
  // Written as half floats (scalarformat "half"): 10.0014 became a multiple
  // of 2^-7, the step of halves between 8 and 16.
  EXPECT_EQ(d.r * 128, std::round(d.r * 128)) << d.r;
  EXPECT_EQ(d.r, d.g);
  EXPECT_TRUE(std::isinf(depth.at(0, 0).r))
      << depth.at(0, 0).r; // the corner misses
  EXPECT_NEAR(normal.at(8, 8).b, 1.0f, 1e-4f);
  EXPECT_NEAR(normal.at(8, 8).r, 0.0f, 1e-4f);
  EXPECT_NEAR(albedo.at(8, 8).g, 1.0f, 1e-4f);
  EXPECT_EQ(mystery.at(8, 8).r, 0.f);
}

// The white 2x2 square 10 units ahead, hung under `parent`.
std::string whiteSquare(const std::string &parent)
{
  return R"(Create "shape" "mesh" Connect "shape" "" ")" + parent
         + R"(" "objects"
SetAttribute "shape" "nvertices" "int" 1 4 "P" "point" 4 [ -1 -1 -10  1 -1 -10  1 1 -10  -1 1 -10 ]
)";
}

// White geometry (`shape`, made by the `geometry` statements) under a
// uniform environment (hidden from the camera, seen, or none at all),
// seen by a camera at the origin with fov 30 plus `camera` attributes and a
// screen with `screen` attributes; rendered to the EXR `output`, which is
// read back.
enum class Sky { None, Hidden, Visible };

Image renderWhite(NSIContext_t ctx,
    const std::string &geometry,
    const std::string &camera,
    const std::string &screen,
    const std::string &output,
    Sky lighting = Sky::Hidden)
{
  std::string sky;
  if (lighting != Sky::None) {
    sky = R"(Create "sky" "environment" Connect "sky" "" ".root" "objects"
Create "light" "shader" SetAttribute "light" "shaderfilename" "string" 1 "environmentLight"
Create "sky_attr" "attributes" Connect "light" "" "sky_attr" "surfaceshader"
Connect "sky_attr" "" "sky" "geometryattributes"
)";
  }
  if (lighting == Sky::Hidden)
    sky += R"(SetAttribute "sky_attr" "visibility.camera" "int" 1 0
)";
  const std::string text =
      R"(Create "cam" "perspectivecamera" Connect "cam" "" ".root" "objects"
SetAttribute "cam" "fov" "float" 1 30 )"
      + camera + R"(
Create "scr" "screen" Connect "scr" "" "cam" "screens"
SetAttribute "scr" )"
      + screen + R"(
Create "layer" "outputlayer" Connect "layer" "" "scr" "outputlayers"
Create "file" "outputdriver" Connect "file" "" "layer" "outputdrivers"
SetAttribute "file" "drivername" "string" 1 "exr" "imagefilename" "string" 1 ")"
      + output + R"("

)" + geometry
      + R"(
Create "white" "shader" SetAttribute "white" "shaderfilename" "string" 1 "lambert"
  "i_color" "color" 1 [ 1 1 1 ]
Create "attr" "attributes" Connect "white" "" "attr" "surfaceshader"
Connect "attr" "" "shape" "geometryattributes"
)" + sky
      + R"(RenderControl "action" "string" 1 "start" RenderControl "action" "string" 1 "wait"
)";
  const std::string file = output + ".nsi";
  std::ofstream(file) << text;
  NSI::ArgumentList args;
  args.addString("type", "apistream").addString("filename", file.c_str());
  NSIEvaluate(ctx, args.size(), args.data());
  auto result = prism::image::read(output);
  EXPECT_TRUE(result.ok()) << result.error;
  return result.image;
}

// The square moving from x = -2 to x = 2 (transform samples at t = 0 and
// 1), at 64x16, with the shutter open over [0, 1] or no shutter at all.
Image movingSquare(NSIContext_t ctx, bool shutter, const std::string &output)
{
  NSICreate(ctx, "xf", "transform", 0, nullptr);
  NSIConnect(ctx, "xf", "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  for (double t : {0.0, 1.0}) {
    const double m[16] = {
        1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4 * t - 2, 0, 0, 1};
    NSI::ArgumentList args;
    args.add("transformationmatrix", NSITypeDoubleMatrix, m);
    NSISetAttributeAtTime(ctx, "xf", t, args.size(), args.data());
  }
  return renderWhite(ctx,
      whiteSquare("xf"),
      shutter ? R"("shutterrange" "double" 2 [ 0 1 ])" : "",
      R"("resolution" "int[2]" 1 [ 64 16 ] "oversampling" "int" 1 256)",
      output);
}

TEST_F(Render, TransformSamplesBlurAcrossTheShutter)
{
  NSIContext_t ctx = beginRender();
  const Image blurred = movingSquare(ctx, true, path("blurred.exr"));
  NSIEnd(ctx);
  ctx = beginRender();
  const Image still = movingSquare(ctx, false, path("still.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  ASSERT_EQ(blurred.width, 64u);
  ASSERT_EQ(still.width, 64u);
  // World x of a column's centre on the square's plane: the window is
  // [-4, 4] wide (64 / 16), times tan(15 deg), at distance 10.
  const double s = std::tan(15 * M_PI / 180);
  auto worldX = [&](uint32_t col) {
    return (-4 + 8 * (col + 0.5) / 64) * s * 10;
  };
  int checked = 0;
  for (uint32_t col = 0; col < 64; ++col) {
    const double x = worldX(col);
    // The share of the shutter during which the square (centre -2 + 4t,
    // half width 1) covers x.
    const double covered =
        std::max(0.0, std::min(x + 1, 2.0) - std::max(x - 1, -2.0)) / 4;
    float blur = 0, plain = 0;
    for (uint32_t row = 6; row < 10; ++row) {
      blur += blurred.at(col, row).r / 4;
      plain += still.at(col, row).r / 4;
    }
    // Pixels are a third of a unit wide: away from the ends of each ramp.
    if (std::abs(std::abs(x) - 3) > 0.5 && std::abs(std::abs(x) - 1) > 0.5) {
      EXPECT_NEAR(blur, covered, 0.12) << "column " << col << ", x " << x;
      ++checked;
    }
    // Without a shutter the first sample holds: the square at x = -2.
    if (std::abs(std::abs(x + 2) - 1) > 0.5) {
      EXPECT_EQ(plain > 0.5f, std::abs(x + 2) < 1)
          << "column " << col << ", x " << x;
    }
  }
  EXPECT_GT(checked, 30);
}

// The 64x16 renders below: a white 1 x 1 square 10 units ahead of a
// camera with fov 30, so a column's centre is at world x
// (-4 + 8 (col + 0.5) / 64) tan(15 deg) 10 on the square's plane (a
// third of a unit per pixel), and rows 7 and 8 lie inside the square.
double columnX(uint32_t col)
{
  return (-4 + 8 * (col + 0.5) / 64) * std::tan(15 * M_PI / 180) * 10;
}

float middleRows(const Image &image, uint32_t col)
{
  return (image.at(col, 7).r + image.at(col, 8).r) / 2;
}

// The 1 x 1 square's corners around x = `x` (camera space), as P.
std::vector<float> squareAt(double x)
{
  const float l = float(x - 0.5), r = float(x + 0.5);
  return {l, -0.5f, -10, r, -0.5f, -10, r, 0.5f, -10, l, 0.5f, -10};
}

const char *kSmallScreen =
    R"("resolution" "int[2]" 1 [ 64 16 ] "oversampling" "int" 1 256)";

// The share of the shutter during which the square, its centre moving
// linearly from `from` to `to`, covers x.
double shutterShare(double x, double from, double to)
{
  const double lo = std::min(from, to), hi = std::max(from, to);
  return std::max(0.0, std::min(x + 0.5, hi) - std::max(x - 0.5, lo))
         / (hi - lo);
}

// `blurred` is the square moving from `from` to `to` across the shutter,
// `open` and `close` still renders of it there: the smear covers the
// columns between the two, each as bright as the share of the shutter the
// square covers it, and the square's light is spread, not lost.
void expectSmear(const Image &blurred,
    const Image &open,
    const Image &close,
    double from,
    double to)
{
  ASSERT_EQ(blurred.width, 64u);
  ASSERT_EQ(open.width, 64u);
  ASSERT_EQ(close.width, 64u);
  float blurredSum = 0, openSum = 0, closeSum = 0, blurredPeak = 0;
  int between = 0;
  for (uint32_t col = 0; col < 64; ++col) {
    const double x = columnX(col);
    const float b = middleRows(blurred, col);
    const float o = middleRows(open, col), c = middleRows(close, col);
    blurredSum += b;
    openSum += o;
    closeSum += c;
    blurredPeak = std::max(blurredPeak, b);
    // The noise of 256 samples is about 0.02 here.
    EXPECT_NEAR(b, shutterShare(x, from, to), 0.07)
        << "column " << col << ", x " << x;
    // The stills: lit inside the square, dark outside (away from edges).
    if (std::abs(std::abs(x - from) - 0.5) > 0.2) {
      EXPECT_EQ(o > 0.5f, std::abs(x - from) < 0.5) << "column " << col;
    }
    if (std::abs(std::abs(x - to) - 0.5) > 0.2) {
      EXPECT_EQ(c > 0.5f, std::abs(x - to) < 0.5) << "column " << col;
    }
    // Between the two still positions: dark in both, lit in the smear.
    if (x > std::min(from, to) + 0.7 && x < std::max(from, to) - 0.7) {
      EXPECT_LT(std::max(o, c), 0.02f) << "column " << col;
      EXPECT_GT(b, 0.15f) << "column " << col;
      ++between;
    }
  }
  EXPECT_GE(between, 6);
  EXPECT_NEAR(openSum, 3.0, 0.3); // a unit is three pixels wide
  EXPECT_NEAR(closeSum, openSum, 0.3);
  EXPECT_NEAR(blurredSum, openSum, 0.3);
  EXPECT_LT(blurredPeak, 0.4f); // a quarter of the shutter, at most
}

bool samePixels(const Image &a, const Image &b)
{
  if (a.width != b.width || a.height != b.height)
    return false;
  for (uint32_t y = 0; y < a.height; ++y) {
    for (uint32_t x = 0; x < a.width; ++x) {
      const auto &p = a.at(x, y), &q = b.at(x, y);
      if (p.r != q.r || p.g != q.g || p.b != q.b)
        return false;
    }
  }
  return true;
}

// A camera under `cam_xf` moving from x = -2 to x = 2 (samples set
// latest first) past the square at x = 0: in the image the square moves
// from x = 2 to x = -2.
Image panningCamera(NSIContext_t ctx, Motion motion, const std::string &output)
{
  NSICreate(ctx, "cam_xf", "transform", 0, nullptr);
  NSIConnect(ctx, "cam_xf", "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  auto at = [](double x) {
    return std::array<double, 16>{
        1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, 0, 0, 1};
  };
  if (motion == Motion::StillOpen || motion == Motion::StillClose) {
    const auto m = at(motion == Motion::StillOpen ? -2 : 2);
    NSI::ArgumentList args;
    args.add("transformationmatrix", NSITypeDoubleMatrix, m.data());
    NSISetAttribute(ctx, "cam_xf", args.size(), args.data());
  } else {
    for (double t : {1.0, 0.0}) {
      const auto m = at(4 * t - 2);
      NSI::ArgumentList args;
      args.add("transformationmatrix", NSITypeDoubleMatrix, m.data());
      NSISetAttributeAtTime(ctx, "cam_xf", t, args.size(), args.data());
    }
  }
  const auto p = squareAt(0);
  std::string geometry =
      R"(Create "shape" "mesh" Connect "shape" "" ".root" "objects"
Disconnect "cam" "" ".root" "objects" Connect "cam" "" "cam_xf" "objects"
SetAttribute "shape" "nvertices" "int" 1 4 "P" "point" 4 [ )";
  for (float v : p)
    geometry += std::to_string(v) + " ";
  geometry += "]\n";
  return renderWhite(ctx,
      geometry,
      motion == Motion::Shutter ? R"("shutterrange" "double" 2 [ 0 1 ])" : "",
      kSmallScreen,
      output);
}

TEST_F(Render, CameraMotionSmearsAcrossTheShutter)
{
  std::map<Motion, Image> images = everyMotion(panningCamera);
  expectSmear(images[Motion::Shutter],
      images[Motion::StillOpen],
      images[Motion::StillClose],
      2,
      -2);
  // Without a shutter range the earliest sample holds, pixel for pixel.
  EXPECT_TRUE(samePixels(images[Motion::NoShutter], images[Motion::StillOpen]));
}

// The square's P set at t = 0 (centred on x = -2) and t = 1 (x = 2),
// latest first; `pointsAtClose` points at t = 1 (4, or 5 to mismatch).
Image deformingMesh(NSIContext_t ctx,
    Motion motion,
    const std::string &output,
    int pointsAtClose = 4)
{
  NSICreate(ctx, "shape", "mesh", 0, nullptr);
  NSIConnect(ctx, "shape", "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  const int nvertices = 4;
  NSI::ArgumentList count;
  count.add("nvertices", NSITypeInteger, &nvertices);
  NSISetAttribute(ctx, "shape", count.size(), count.data());
  auto setP = [&](double x, int points, const double *time) {
    std::vector<float> p = squareAt(x);
    p.resize(3 * size_t(points), 0.f);
    NSI::ArgumentList args;
    args.add("P", NSITypePoint, p.data(), size_t(points));
    if (time)
      NSISetAttributeAtTime(ctx, "shape", *time, args.size(), args.data());
    else
      NSISetAttribute(ctx, "shape", args.size(), args.data());
  };
  const double open = 0, close = 1;
  if (motion == Motion::StillOpen) {
    setP(-2, 4, nullptr);
  } else if (motion == Motion::StillClose) {
    setP(2, 4, nullptr);
  } else {
    setP(2, pointsAtClose, &close);
    setP(-2, 4, &open);
  }
  return renderWhite(ctx,
      "",
      motion == Motion::Shutter ? R"("shutterrange" "double" 2 [ 0 1 ])" : "",
      kSmallScreen,
      output);
}

TEST_F(Render, VertexMotionSmearsAcrossTheShutter)
{
  std::map<Motion, Image> images =
      everyMotion([](NSIContext_t ctx, Motion motion, const std::string &out) {
        return deformingMesh(ctx, motion, out);
      });
  expectSmear(images[Motion::Shutter],
      images[Motion::StillOpen],
      images[Motion::StillClose],
      -2,
      2);
  EXPECT_TRUE(samePixels(images[Motion::NoShutter], images[Motion::StillOpen]));
}

TEST_F(Render, VertexSamplesOfDifferentCountsRenderTheFirst)
{
  NSIContext_t ctx = beginRender();
  const Image mismatched =
      deformingMesh(ctx, Motion::Shutter, path("mismatched.exr"), 5);
  NSIEnd(ctx);
  EXPECT_TRUE(reportedOnce(m_messages,
      {"mesh 'shape'",
          "'P' time samples have different counts",
          "4 at time 0",
          "5 at time 1",
          "the first sample is rendered"}));
  ctx = beginRender();
  const Image still = deformingMesh(ctx, Motion::StillOpen, path("still.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  ASSERT_EQ(mismatched.width, 64u);
  EXPECT_GT(middleRows(mismatched, 25), 0.9f); // x = -2.2: lit
  EXPECT_TRUE(samePixels(mismatched, still));
}

TEST_F(Render, ClippingRangeAndDepthOfField)
{
  auto render = [&](const std::string &attributes, const char *name) {
    NSIContext_t ctx = beginRender();
    Image image = renderWhite(ctx,
        whiteSquare(NSI_SCENE_ROOT),
        attributes,
        R"("resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 64)",
        path(name));
    NSIEnd(ctx);
    return image;
  };
  const Image sharp = render("", "sharp.exr");
  const Image near =
      render(R"("clippingrange" "double" 2 [ 11 100 ])", "near.exr");
  const Image far =
      render(R"("clippingrange" "double" 2 [ 0.1 9 ])", "far.exr");
  const Image kept =
      render(R"("clippingrange" "double" 2 [ 9 11 ])", "kept.exr");
  // Focused at 1 with a 0.1 aperture radius (focal length 0.2, f/1): at 10
  // a point spreads over a disk of 0.09 / (2 tan 15 / 32) = 5.4 pixels.
  const Image blurred = render(
      R"("depthoffield.enable" "int" 1 1 "depthoffield.fstop" "double" 1 1
      "depthoffield.focallength" "double" 1 0.2 "depthoffield.focaldistance" "double" 1 1)",
      "blurred.exr");
  const Image focused = render(
      R"("depthoffield.enable" "int" 1 1 "depthoffield.fstop" "double" 1 1
      "depthoffield.focallength" "double" 1 0.2 "depthoffield.focaldistance" "double" 1 10)",
      "focused.exr");
  EXPECT_EQ(m_messages.problems(), "");
  // The square spans columns 10 to 22 (16 +- 16 / (10 tan 15)).
  EXPECT_GT(value(sharp, 16, 16), 0.8f);
  EXPECT_EQ(value(near, 16, 16), 0.f);
  EXPECT_EQ(value(far, 16, 16), 0.f);
  EXPECT_GT(value(kept, 16, 16), 0.8f);
  // Column 6 lies 4 pixels outside: black when sharp or focused on the
  // square, reached by the blur when focused at 1; column 11, just inside,
  // loses light to it.
  EXPECT_EQ(value(sharp, 6, 16), 0.f);
  EXPECT_LT(value(focused, 6, 16), 0.02f);
  EXPECT_GT(value(blurred, 6, 16), 0.05f); // about 8 % of the disk reaches
  EXPECT_LT(value(blurred, 11, 16), 0.9f * value(sharp, 11, 16));
}

TEST_F(Render, CurvesAreRoundSegments)
{
  // A linear curve of width 1 across the view at distance 10, and a
  // catmull-rom one above it (extrapolated, so it spans its points).
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      R"(Create "shape" "transform" Connect "shape" "" ".root" "objects"
Create "line" "linearcurves" Connect "line" "" "shape" "objects"
SetAttribute "line" "nvertices" "int" 1 2 "P" "point" 2 [ -5 0 -10  5 0 -10 ] "width" "float" 1 1
Create "wave" "curves" Connect "wave" "" "shape" "objects"
SetAttribute "wave" "nvertices" "int" 1 4 "extrapolate" "int" 1 1 "width" "float" 1 0.5
  "P" "point" 4 [ -2 2 -10  -1 2 -10  1 2 -10  2 2 -10 ])",
      "",
      R"("resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 16)",
      path("curves.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  // Pixels are 2 tan 15 * 10 / 32 = 0.167 units: the line covers rows
  // 13-18 (half width 0.5 = 3 pixels), the wave rows 6-8 around y = 2,
  // columns 4-28 (x from -2 to 2).
  EXPECT_GT(value(image, 3, 16), 0.8f);
  EXPECT_GT(value(image, 28, 15), 0.8f);
  EXPECT_EQ(value(image, 16, 11), 0.f);
  EXPECT_EQ(value(image, 16, 21), 0.f);
  EXPECT_GT(value(image, 16, 4), 0.8f) << "the wave";
  EXPECT_EQ(value(image, 1, 4), 0.f) << "left of the wave";
}

TEST_F(Render, InstancesPlaceTheirModels)
{
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      R"(Create "shape" "instances" Connect "shape" "" ".root" "objects"
Create "big" "mesh" SetAttribute "big" "nvertices" "int" 1 4
  "P" "point" 4 [ -1 -1 -10  1 -1 -10  1 1 -10  -1 1 -10 ]
Create "small" "mesh" SetAttribute "small" "nvertices" "int" 1 4
  "P" "point" 4 [ -0.25 -0.25 -10  0.25 -0.25 -10  0.25 0.25 -10  -0.25 0.25 -10 ]
Connect "big" "" "shape" "sourcemodels" "index" "int" 1 0
Connect "small" "" "shape" "sourcemodels" "index" "int" 1 1
SetAttribute "shape" "transformationmatrices" "doublematrix" 4 [
  1 0 0 0 0 1 0 0 0 0 1 0 -3 0 0 1   1 0 0 0 0 1 0 0 0 0 1 0 3 0 0 1
  1 0 0 0 0 1 0 0 0 0 1 0 0 3 0 1    1 0 0 0 0 1 0 0 0 0 1 0 0 -3 0 1 ]
  "modelindices" "int" 4 [ 0 1 0 -1 ] "disabledinstances" "int" 1 2)",
      R"("fov" "float" 1 60)",
      R"("resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 4)",
      path("instances.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  // tan 30 * 10 = 5.77 units per half image (16 pixels): the small model
  // is 1.4 pixels wide, so it covers about 0.7 of pixel (24, 16).
  EXPECT_GT(value(image, 7, 16), 0.8f) << "model 0 at x = -3";
  EXPECT_GT(value(image, 24, 16), 0.5f) << "model 1 at x = 3";
  EXPECT_EQ(value(image, 21, 16), 0.f) << "model 1 is the small one";
  EXPECT_EQ(value(image, 16, 7), 0.f) << "instance 2 is disabled";
  EXPECT_EQ(value(image, 16, 24), 0.f) << "instance 3 has model -1";
  EXPECT_EQ(value(image, 16, 16), 0.f) << "nothing at the origin";
}

// Streams of the particle light tests: a camera 10 above the origin looking
// down, and a white floor lit only by one particle 3 above it carrying a
// light `shader` (with its `attributes`), its normal `normal`.
const char *kCameraLookingDown = R"(Disconnect "cam" "" ".root" "objects"
Create "up" "transform" Connect "up" "" ".root" "objects"
SetAttribute "up" "transformationmatrix" "doublematrix" 1 [ 1 0 0 0  0 0 -1 0  0 1 0 0  0 10 0 1 ]
Connect "cam" "" "up" "objects")";

std::string particleLightOverFloor(const std::string &shader,
    const std::string &attributes,
    const std::string &normal)
{
  return R"(Create "shape" "mesh" Connect "shape" "" ".root" "objects"
SetAttribute "shape" "nvertices" "int" 1 4 "P" "point" 4 [ -5 0 5  5 0 5  5 0 -5  -5 0 -5 ]
Create "bulb" "particles" Connect "bulb" "" ".root" "objects"
SetAttribute "bulb" "P" "point" 1 [ 0 3 0 ] "width" "float" 1 0.01 "N" "normal" 1 [ )"
         + normal + R"( ]
Create "bulb_shader" "shader" SetAttribute "bulb_shader" "shaderfilename" "string" 1 ")"
         + shader + R"(" "intensity" "float" 1 10 )" + attributes + R"(
Create "bulb_attr" "attributes" Connect "bulb_shader" "" "bulb_attr" "surfaceshader"
Connect "bulb_attr" "" "bulb" "geometryattributes")";
}

TEST_F(Render, ParticleLights)
{
  // The floor under a spot pointing down (cone 20 degrees: a disk of
  // radius 3 tan 10 = 0.53), or a point light.
  auto render = [&](const char *shader,
                    const char *name,
                    const char *normal = "0 -1 0") {
    NSIContext_t ctx = beginRender();
    Image image = renderWhite(ctx,
        particleLightOverFloor(shader, R"("coneAngle" "float" 1 20)", normal),
        kCameraLookingDown,
        R"("resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 4)",
        path(name),
        Sky::None);
    NSIEnd(ctx);
    return image;
  };
  const Image spot = render("spotLight", "spot.exr");
  const Image point = render("pointLight", "point.exr");
  // An area light on a particle with N is a ring facing N: the floor is lit
  // when it faces down, not when it faces up.
  const Image ringDown = render("areaLight", "ring-down.exr");
  const Image ringUp = render("areaLight", "ring-up.exr", "0 1 0");
  EXPECT_EQ(m_messages.problems(), "");
  EXPECT_GT(value(ringDown, 16, 16), 0.1f);
  EXPECT_GT(value(ringDown, 22, 16), 0.1f);
  EXPECT_EQ(value(ringUp, 16, 16), 0.f);
  // 2.68 units per half image: the spot's disk is 3 pixels in radius.
  EXPECT_GT(value(spot, 16, 16), 0.1f);
  EXPECT_EQ(value(spot, 16, 22), 0.f);
  EXPECT_EQ(value(spot, 22, 16), 0.f);
  EXPECT_GT(value(point, 16, 22), 0.1f);
  EXPECT_GT(value(point, 22, 16), 0.1f);
}

TEST_F(Render, UnwritableOutputPathsFallBackToTheCurrentFolder)
{
  // A stream exported elsewhere names its author's folder: the image is
  // written under its file name in the current folder, with one warning
  // before the render; a display driver is named in a warning too.
  const std::filesystem::path here = std::filesystem::current_path();
  std::filesystem::current_path(m_dir);
  NSIContext_t ctx = beginRender();
  minimalScene(ctx, 8, 1, "/nonexistent-prism-folder/shots/beauty.png");
  NSICreate(ctx, "window", "outputdriver", 0, nullptr);
  NSI::ArgumentList window;
  window.addString("drivername", "idisplay")
      .addString("imagefilename", "beauty");
  NSISetAttribute(ctx, "window", window.size(), window.data());
  NSIConnect(ctx, "window", "", "layer", "outputdrivers", 0, nullptr);
  renderControl(ctx, "start");
  renderControl(ctx, "wait");
  NSIEnd(ctx);
  std::filesystem::current_path(here);
  const std::string problems = m_messages.problems();
  EXPECT_NE(problems.find("cannot write "
                          "'/nonexistent-prism-folder/shots/beauty.png' "
                          "(folder '/nonexistent-prism-folder/shots' does not "
                          "exist); the image goes to 'beauty.png' in the "
                          "current folder instead"),
      std::string::npos)
      << problems;
  EXPECT_NE(problems.find("output driver 'idisplay' of layer 'layer' shows "
                          "images in a window"),
      std::string::npos)
      << problems;
  EXPECT_TRUE(std::filesystem::is_regular_file(path("beauty.png")));
}

TEST_F(Render, PointLightDecayRate)
{
  // A point light 3 above a white floor seen from 10 above: right below it,
  // 3Delight's decayRate 0 (none), 1 (linear) and 2 (quadratic, the
  // default) light the floor as I, I / 3 and I / 9 (PRISM_LIGHT_DECAY).
  auto render = [&](const std::string &decay, const char *name) {
    NSIContext_t ctx = beginRender();
    Image image = renderWhite(ctx,
        particleLightOverFloor("pointLight", decay, "0 -1 0"),
        kCameraLookingDown,
        R"("resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 4)",
        path(name),
        Sky::None);
    NSIEnd(ctx);
    return image;
  };
  const Image quadratic = render("", "decay-default.exr");
  const Image none = render(R"("decayRate" "int" 1 0)", "decay-0.exr");
  const Image linear = render(R"("decayRate" "int" 1 1)", "decay-1.exr");
  EXPECT_EQ(m_messages.problems(), "");
  const float below = value(quadratic, 16, 16);
  ASSERT_GT(below, 0.f);
  EXPECT_NEAR(value(none, 16, 16) / below, 9.f, 0.05f);
  EXPECT_NEAR(value(linear, 16, 16) / below, 3.f, 0.02f);
}

TEST_F(Render, UniformEnvironmentIsSeenUnlessHidden)
{
  auto render = [&](Sky sky, const char *name) {
    NSIContext_t ctx = beginRender();
    Image image = renderWhite(ctx,
        whiteSquare(NSI_SCENE_ROOT),
        "",
        R"("resolution" "int[2]" 1 [ 16 16 ] "oversampling" "int" 1 4)",
        path(name),
        sky);
    NSIEnd(ctx);
    return image;
  };
  const Image seen = render(Sky::Visible, "seen.exr");
  const Image hidden = render(Sky::Hidden, "hidden.exr");
  EXPECT_EQ(m_messages.problems(), "");
  EXPECT_FLOAT_EQ(value(seen, 0, 0), 1.f); // the environment's colour
  EXPECT_EQ(value(hidden, 0, 0), 0.f);
  EXPECT_GT(value(hidden, 8, 8), 0.8f); // the square, lit either way
  EXPECT_GT(value(seen, 8, 8), 0.8f);
}

TEST_F(Render, SynchronizeShowsEdits)
{
  // The white square rendered, then turned red and moved right, then
  // synchronized: the output file shows the edit.
  NSIContext_t ctx = beginRender();
  const std::string output = path("edited.exr");
  const Image before = renderWhite(ctx,
      whiteSquare("move"),
      R"(Create "move" "transform" Connect "move" "" ".root" "objects")",
      R"("resolution" "int[2]" 1 [ 16 16 ] "oversampling" "int" 1 4)",
      output);
  NSI::ArgumentList red;
  const float color[3] = {1, 0, 0};
  red.add("i_color", NSITypeColor, color);
  NSISetAttribute(ctx, "white", red.size(), red.data());
  NSI::ArgumentList right;
  const double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1.5, 0, 0, 1};
  right.add("transformationmatrix", NSITypeDoubleMatrix, m);
  NSISetAttribute(ctx, "move", right.size(), right.data());
  StopRecord record;
  renderControl(ctx, "synchronize", &record);
  renderControl(ctx, "wait");
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  ASSERT_EQ(record.calls.size(), 1u);
  EXPECT_EQ(record.calls[0].second, NSIRenderSynchronized);
  const Image after = readImage(output);
  ASSERT_EQ(after.width, 16u);
  // 0.335 units per pixel: the square covered columns 5-10 (x from -1 to
  // 1), and covers 9-15 (x from 0.5 to 2.5) after the edit.
  EXPECT_GT(before.at(5, 8).g, 0.8f);
  EXPECT_EQ(after.at(5, 8).r, 0.f);
  EXPECT_GT(after.at(12, 8).r, 0.8f);
  EXPECT_EQ(after.at(12, 8).g, 0.f);
}

// Three white squares side by side, each under its own transform with its
// own shader, 10 units ahead of a camera with fov 30, on a 32 x 16 screen.
const char *kThreeSquares = R"(
Create "cam" "perspectivecamera" Connect "cam" "" ".root" "objects"
SetAttribute "cam" "fov" "float" 1 30
Create "scr" "screen" Connect "scr" "" "cam" "screens"
SetAttribute "scr" "resolution" "int[2]" 1 [ 32 16 ] "oversampling" "int" 1 4
Create "layer" "outputlayer" Connect "layer" "" "scr" "outputlayers"
Create "file" "outputdriver" Connect "file" "" "layer" "outputdrivers"
SetAttribute "file" "drivername" "string" 1 "exr"
  "imagefilename" "string" 1 "${PRISM_NSI_OUT}/live.exr"
Create "sky" "environment" Connect "sky" "" ".root" "objects"
Create "light" "shader" SetAttribute "light" "shaderfilename" "string" 1 "environmentLight"
Create "sky_attr" "attributes" Connect "light" "" "sky_attr" "surfaceshader"
Connect "sky_attr" "" "sky" "geometryattributes"
SetAttribute "sky_attr" "visibility.camera" "int" 1 0
)";

std::string squareAt(const std::string &name, double x)
{
  std::ostringstream text;
  text << "Create \"" << name << "_xf\" \"transform\" Connect \"" << name
       << "_xf\" \"\" \".root\" \"objects\"\n"
       << "SetAttribute \"" << name
       << "_xf\" \"transformationmatrix\" \"doublematrix\" 1 [ 1 0 0 0 0 1 0 "
          "0 0 0 1 0 "
       << x << " 0 0 1 ]\n"
       << "Create \"" << name << "\" \"mesh\" Connect \"" << name
       << "\" \"\" \"" << name << "_xf\" \"objects\"\n"
       << "SetAttribute \"" << name
       << "\" \"nvertices\" \"int\" 1 4 \"P\" \"point\" 4 [ -1 -1 -10  1 -1 "
          "-10  1 1 -10  -1 1 -10 ]\n"
       << "Create \"" << name << "_shader\" \"shader\" SetAttribute \"" << name
       << "_shader\" \"shaderfilename\" \"string\" 1 \"lambert\" \"i_color\" "
          "\"color\" 1 [ 1 1 1 ]\n"
       << "Create \"" << name << "_attr\" \"attributes\" Connect \"" << name
       << "_shader\" \"\" \"" << name << "_attr\" \"surfaceshader\"\n"
       << "Connect \"" << name << "_attr\" \"\" \"" << name
       << "\" \"geometryattributes\"\n";
  return text.str();
}

// The message a synchronize reports about the ANARI objects it touched.
std::string synchronizeCounts(MessageRecorder &messages)
{
  std::string found;
  for (auto &m : messages.take()) {
    const std::string prefix =
        "NSIRenderControl: synchronize updated the ANARI objects: ";
    if (m.level == NSIErrInfo && m.text.rfind(prefix, 0) == 0)
      found = m.text.substr(prefix.size());
    else if (m.level >= NSIErrWarning)
      ADD_FAILURE() << m.text;
  }
  return found;
}

// `wait` on a suspended render returns with a warning (it waited for a
// resume that the waiting caller alone could send: it never returned), and
// the render still stops. 100,000 frames: the render is surely running.
TEST_F(Render, WaitOnASuspendedRenderReturns)
{
  NSIContext_t ctx = beginRender();
  minimalScene(ctx, 8, 100000, path("suspended.png"));
  StopRecord record;
  renderControl(ctx, "start", &record);
  renderControl(ctx, "suspend");
  const std::string warning =
      "2: NSIRenderControl: 'wait' on a suspended render returns at once";
  renderControl(ctx, "wait");
  EXPECT_EQ(m_messages.problems().rfind(warning, 0), 0u);
  renderControl(ctx, "wait"); // again: the same
  EXPECT_EQ(m_messages.problems().rfind(warning, 0), 0u);
  renderControl(ctx, "stop");
  ASSERT_EQ(record.calls.size(), 1u);
  EXPECT_EQ(record.calls[0].second, int(NSIRenderAborted));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
}

// Two threads send every render control action in a scrambled order: each
// call returns, and the only errors are the refusals of a start or a
// synchronize that met a render under way.
TEST_F(Render, RenderControlFromTwoThreadsAlwaysReturns)
{
  NSIContext_t ctx = beginRender();
  minimalScene(ctx, 8, 50, path("scrambled.png"));
  const char *actions[] = {
      "start", "wait", "synchronize", "suspend", "resume", "stop"};
  auto send = [&](unsigned seed) {
    std::mt19937 random(seed);
    for (int i = 0; i < 60; ++i)
      renderControl(ctx, actions[random() % 6]);
  };
  std::thread other(send, 1u);
  send(2u);
  other.join();
  renderControl(ctx, "stop");
  NSIEnd(ctx);
  for (const auto &message : m_messages.take()) {
    if (message.level < NSIErrError)
      continue;
    EXPECT_TRUE(message.text.find("'start' while a render is running")
                    != std::string::npos
                || message.text.find("'synchronize' while a render is starting")
                       != std::string::npos)
        << message.text;
  }
}

TEST_F(Render, InteractiveEditsTouchOnlyTheirObjects)
{
  ::setenv("PRISM_NSI_OUT", m_dir.c_str(), 1);
  const std::string scene = writeFile("live.nsi",
      kThreeSquares + squareAt("left", -3) + squareAt("middle", 0)
          + squareAt("right", 3));
  NSIContext_t ctx = beginRender();
  include(ctx, scene);
  StopRecord record;
  NSI::ArgumentList start;
  start.addString("action", "start").addInteger("interactive", 1);
  start.addPointer(
      "stoppedcallback", reinterpret_cast<const void *>(&StopRecord::callback));
  start.addPointer("stoppedcallbackdata", &record);
  NSIRenderControl(ctx, start.size(), start.data());
  renderControl(ctx, "wait");
  EXPECT_EQ(m_messages.problems(), "");
  const Image before = readImage(path("live.exr"));
  ASSERT_EQ(before.width, 32u);

  // Move the middle square up 1.5 and turn the right one red.
  NSI::ArgumentList up;
  const double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1.5, 0, 1};
  up.add("transformationmatrix", NSITypeDoubleMatrix, m);
  NSISetAttribute(ctx, "middle_xf", up.size(), up.data());
  NSI::ArgumentList red;
  const float color[3] = {1, 0, 0};
  red.add("i_color", NSITypeColor, color);
  NSISetAttribute(ctx, "right_shader", red.size(), red.data());
  renderControl(ctx, "synchronize");
  renderControl(ctx, "wait");
  // One material and one instance set anew; nothing else made or changed.
  EXPECT_EQ(synchronizeCounts(m_messages),
      "created geometry 0 material 0 surface 0 group 0 instance 0 light 0 "
      "volume 0 "
      "world 0; committed geometry 0 material 1 surface 0 group 0 instance 1 "
      "light 0 volume 0 world 0; released geometry 0 material 0 surface 0 "
      "group 0 "
      "instance 0 light 0 volume 0 world 0");
  const Image edited = readImage(path("live.exr"));

  // Nothing edited: nothing touched, the same image.
  renderControl(ctx, "synchronize");
  renderControl(ctx, "wait");
  EXPECT_EQ(synchronizeCounts(m_messages),
      "created geometry 0 material 0 surface 0 group 0 instance 0 light 0 "
      "volume 0 "
      "world 0; committed geometry 0 material 0 surface 0 group 0 instance 0 "
      "light 0 volume 0 world 0; released geometry 0 material 0 surface 0 "
      "group 0 "
      "instance 0 light 0 volume 0 world 0");

  // The left square deleted: its objects released, the world told.
  NSI::ArgumentList recursive;
  recursive.addInteger("recursive", 1);
  NSIDelete(ctx, "left_xf", recursive.size(), recursive.data());
  renderControl(ctx, "synchronize");
  renderControl(ctx, "wait");
  EXPECT_EQ(synchronizeCounts(m_messages),
      "created geometry 0 material 0 surface 0 group 0 instance 0 light 0 "
      "volume 0 "
      "world 0; committed geometry 0 material 0 surface 0 group 0 instance 0 "
      "light 0 volume 0 world 1; released geometry 1 material 1 surface 1 "
      "group 1 "
      "instance 1 light 0 volume 0 world 0");
  const Image deleted = readImage(path("live.exr"));
  NSIEnd(ctx);
  ::unsetenv("PRISM_NSI_OUT");

  {
    std::lock_guard lock(record.mutex);
    ASSERT_EQ(record.calls.size(), 4u);
    EXPECT_EQ(record.calls[0].second, NSIRenderCompleted);
    for (size_t i = 1; i < 4; ++i)
      EXPECT_EQ(record.calls[i].second, NSIRenderSynchronized);
  }
  // 0.335 units per pixel: the squares' centres are columns 7, 16 and 25;
  // the middle one covers rows 5-10 from the top, and rows 1-6 moved up.
  EXPECT_GT(value(before, 16, 10), 0.5f);
  EXPECT_EQ(value(before, 16, 2), 0.f);
  EXPECT_EQ(value(edited, 16, 10), 0.f);
  EXPECT_GT(value(edited, 16, 2), 0.5f);
  const auto &white = before.at(25, 8), &red_ = edited.at(25, 8);
  EXPECT_GT(white.g, 0.5f);
  EXPECT_GT(red_.r, 0.5f);
  EXPECT_EQ(red_.g, 0.f);
  // The untouched left square renders as it did, until deleted.
  EXPECT_NEAR(before.at(7, 8).g, edited.at(7, 8).g, 0.02f);
  EXPECT_GT(edited.at(7, 8).g, 0.5f);
  EXPECT_EQ(value(deleted, 7, 8), 0.f);
  EXPECT_GT(deleted.at(25, 8).r, 0.5f);
}

TEST_F(Render, ProceduralMeshRenders)
{
  // The test procedural's square, made at the start of the scene, is the
  // white square: seen in the middle, lit by the environment.
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      std::string(R"(Evaluate "type" "string" 1 "dynamiclibrary"
  "filename" "string" 1 ")")
          + PRISM_TEST_PROCEDURAL_SQUARE + R"(" "handle" "string" 1 "shape"
)",
      "",
      R"("resolution" "int[2]" 1 [ 16 16 ] "oversampling" "int" 1 4)",
      path("procedural.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  ASSERT_EQ(image.width, 16u);
  EXPECT_GT(value(image, 8, 8), 0.8f);
  EXPECT_EQ(value(image, 0, 0), 0.f);
}

TEST_F(Render, GlobalRayDepthBoundsBounces)
{
  // The white square under the hidden environment, whose light reaches it
  // by a bounce off the square (the path tracer meets the environment when
  // a ray escapes): lit at depth 1 and by default, black at depth 0.
  auto render = [&](const char *depth, const char *name) {
    NSIContext_t ctx = beginRender();
    std::string geometry = whiteSquare(NSI_SCENE_ROOT);
    if (depth)
      geometry +=
          std::string(
              R"(SetAttribute ".global" "maximumraydepth.diffuse" "int" 1 )")
          + depth + "\n";
    Image image = renderWhite(ctx,
        geometry,
        "",
        R"("resolution" "int[2]" 1 [ 16 16 ] "oversampling" "int" 1 4)",
        path(name));
    NSIEnd(ctx);
    return image;
  };
  const Image none = render("0", "none.exr");
  const Image one = render("1", "one.exr");
  const Image unset = render(nullptr, "unset.exr");
  EXPECT_EQ(m_messages.problems(), "");
  EXPECT_EQ(value(none, 8, 8), 0.f);
  EXPECT_GT(value(one, 8, 8), 0.8f);
  EXPECT_GT(value(unset, 8, 8), 0.8f);
}

TEST_F(Render, ProceduralNodeIsALocalRoot)
{
  // A procedural node running the test procedural: its square hangs under
  // the node, moved 1.5 right by the node's matrix and shaded by the
  // attributes on it. Editing the node remakes the square; a synchronize
  // with no edit does not run it again.
  NSIContext_t ctx = beginRender();
  const std::string output = path("procedural-node.exr");
  const Image before = renderWhite(ctx,
      std::string(
          R"(Create "shape" "procedural" Connect "shape" "" ".root" "objects"
SetAttribute "shape" "type" "string" 1 "dynamiclibrary"
  "filename" "string" 1 ")")
          + PRISM_TEST_PROCEDURAL_SQUARE + R"("
  "transformationmatrix" "doublematrix" 1 [ 1 0 0 0  0 1 0 0  0 0 1 0  1.5 0 0 1 ]
)",
      "",
      R"("resolution" "int[2]" 1 [ 16 16 ] "oversampling" "int" 1 4)",
      output);
  auto executions = [&] {
    size_t n = 0;
    for (auto &m : m_messages.take()) {
      n += m.text == "square procedural: executed";
      EXPECT_LT(m.level, NSIErrWarning) << m.text;
    }
    return n;
  };
  EXPECT_EQ(executions(), 1u);
  NSI::ArgumentList left;
  left.addFloat("x", -3);
  NSISetAttribute(ctx, "shape", left.size(), left.data());
  renderControl(ctx, "synchronize");
  renderControl(ctx, "wait");
  EXPECT_EQ(executions(), 1u);
  const Image after = readImage(output);
  renderControl(ctx, "synchronize");
  renderControl(ctx, "wait");
  EXPECT_EQ(executions(), 0u);
  NSIEnd(ctx);
  // 0.335 units per pixel: x from 0.5 to 2.5 is columns 9-15, x from -2.5
  // to -0.5 columns 1-6.
  ASSERT_EQ(after.width, 16u);
  EXPECT_GT(value(before, 12, 8), 0.8f);
  EXPECT_EQ(value(before, 4, 8), 0.f);
  EXPECT_EQ(value(after, 12, 8), 0.f);
  EXPECT_GT(value(after, 4, 8), 0.8f);
}

TEST_F(Render, Example3LiveEditsTouchTheirObjects)
{
  // The facts file's Example 3 after Example 1: the lamp's power and the
  // floor's colour edited, then the lamp deleted, each synchronized.
  const std::string example1 = writeFile("example1.nsi", kExample1);
  const std::string example3 = writeFile("example3.nsi", R"(
RenderControl "action" "string" 1 "start" "interactive" "int" 1 1
SetAttribute "glow" "power" "float" 1 250
SetAttribute "grey" "i_color" "color" 1 [ 0.8 0.2 0.2 ]
RenderControl "action" "string" 1 "synchronize"
Delete "lamp_xf" "recursive" "int" 1 1
RenderControl "action" "string" 1 "synchronize"
RenderControl "action" "string" 1 "stop"
)");
  ::setenv("PRISM_NSI_OUT", m_dir.c_str(), 1);
  NSIContext_t ctx = beginRender();
  include(ctx, example1);
  EXPECT_EQ(m_messages.problems(), "");
  include(ctx, example3);
  NSIEnd(ctx);
  ::unsetenv("PRISM_NSI_OUT");
  std::vector<std::string> counts;
  for (auto &m : m_messages.take()) {
    const std::string prefix =
        "NSIRenderControl: synchronize updated the ANARI objects: ";
    if (m.level == NSIErrInfo && m.text.rfind(prefix, 0) == 0)
      counts.push_back(m.text.substr(prefix.size()));
    else
      EXPECT_LT(m.level, NSIErrWarning) << m.text;
  }
  ASSERT_EQ(counts.size(), 2u);
  // The light and the material set in place; nothing else.
  EXPECT_EQ(counts[0],
      "created geometry 0 material 0 surface 0 group 0 instance 0 light 0 "
      "volume 0 "
      "world 0; committed geometry 0 material 1 surface 0 group 0 instance 0 "
      "light 1 volume 0 world 0; released geometry 0 material 0 surface 0 "
      "group 0 "
      "instance 0 light 0 volume 0 world 0");
  // The lamp (a quad light, no geometry) released, the world told.
  EXPECT_EQ(counts[1],
      "created geometry 0 material 0 surface 0 group 0 instance 0 light 0 "
      "volume 0 "
      "world 0; committed geometry 0 material 0 surface 0 group 0 instance 0 "
      "light 0 volume 0 world 1; released geometry 0 material 0 surface 0 "
      "group 0 "
      "instance 0 light 1 volume 0 world 0");
}

TEST_F(Render, SharedTransformsCannotExplode)
{
  // 40 levels, each transform hung twice under the next: 2^40 paths from
  // .root to the mesh. Resolving them all would never end.
  NSIContext_t ctx = beginRender();
  NSICreate(ctx, "m", "mesh", 0, nullptr);
  // A stream, not string concatenation: GCC 12 raises a false -Wrestrict.
  auto name = [](char prefix, int level) {
    std::ostringstream text;
    text << prefix << level;
    return text.str();
  };
  std::string below = "m";
  for (int level = 0; level < 40; ++level) {
    const std::string a = name('a', level), b = name('b', level);
    const std::string above = name('t', level);
    for (const std::string &handle : {a, b, above})
      NSICreate(ctx, handle.c_str(), "transform", 0, nullptr);
    for (const std::string &parent : {a, b}) {
      NSIConnect(ctx, below.c_str(), "", parent.c_str(), "objects", 0, nullptr);
      NSIConnect(ctx, parent.c_str(), "", above.c_str(), "objects", 0, nullptr);
    }
    below = above;
  }
  NSIConnect(ctx, below.c_str(), "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  renderControl(ctx, "start");
  renderControl(ctx, "wait");
  NSIEnd(ctx);
  EXPECT_NE(m_messages.problems().find("too many placements (over 2^21)"),
      std::string::npos);
}

TEST_F(Render, PlanesReachTheHorizon)
{
  // A plane turned to be the ground (its +Z up), the camera 1 above it
  // looking along -Z: everything below the horizon is ground, even where
  // the rays meet it 40 units away.
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      R"(Create "ground" "transform" Connect "ground" "" ".root" "objects"
SetAttribute "ground" "transformationmatrix" "doublematrix" 1 [ 1 0 0 0  0 0 -1 0  0 1 0 0  0 -1 0 1 ]
Create "shape" "plane" Connect "shape" "" "ground" "objects")",
      "",
      R"("resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 4)",
      path("plane.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  for (uint32_t row = 17; row < 32; ++row)
    EXPECT_GT(value(image, 16, row), 0.5f) << "row " << row;
  for (uint32_t row = 0; row < 16; ++row)
    EXPECT_EQ(value(image, 16, row), 0.f) << "row " << row;
}

TEST_F(Render, FacesetsTakeTheirOwnShader)
{
  // Two faces side by side; face 1 is in a faceset with a red shader, face
  // 0 keeps the mesh's white one.
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      R"(Create "shape" "mesh" Connect "shape" "" ".root" "objects"
SetAttribute "shape" "nvertices" "int" 2 [ 4 4 ]
  "P" "point" 8 [ -2 -1 -10  0 -1 -10  0 1 -10  -2 1 -10   0 -1 -10  2 -1 -10  2 1 -10  0 1 -10 ]
Create "right" "faceset" Connect "right" "" "shape" "facesets"
SetAttribute "right" "faces" "int" 1 1
Create "red" "shader" SetAttribute "red" "shaderfilename" "string" 1 "lambert"
  "i_color" "color" 1 [ 1 0 0 ]
Create "red_attr" "attributes" Connect "red" "" "red_attr" "surfaceshader"
Connect "red_attr" "" "right" "geometryattributes")",
      "",
      R"("resolution" "int[2]" 1 [ 32 16 ] "oversampling" "int" 1 4)",
      path("faceset.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  // 0.335 units per pixel (a window 4 wide): face 0 spans columns 10-16,
  // face 1 16-22.
  const auto &left = image.at(12, 8), &right = image.at(19, 8);
  EXPECT_GT(left.r, 0.8f);
  EXPECT_GT(left.g, 0.8f);
  EXPECT_GT(right.r, 0.8f);
  EXPECT_EQ(right.g, 0.f);
}

TEST_F(Render, MeshHolesStayOpen)
{
  // A 2x2 square with a 1x1 hole (nholes 1: two loops, one face) 10 ahead.
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      R"(Create "shape" "mesh" Connect "shape" "" ".root" "objects"
SetAttribute "shape" "nvertices" "int" 2 [ 4 4 ] "nholes" "int" 1 1
  "P" "point" 8 [ -1 -1 -10  1 -1 -10  1 1 -10  -1 1 -10
                  -0.5 -0.5 -10  -0.5 0.5 -10  0.5 0.5 -10  0.5 -0.5 -10 ])",
      "",
      R"("resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 4)",
      path("hole.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  // 0.1675 units per pixel: the hole spans columns 13-19, the ring 10-22.
  EXPECT_EQ(value(image, 16, 16), 0.f) << "the hole";
  EXPECT_GT(value(image, 20, 16), 0.8f) << "the ring right of it";
  EXPECT_GT(value(image, 16, 11), 0.8f) << "the ring above it";
  EXPECT_EQ(value(image, 25, 16), 0.f) << "outside";
}

TEST_F(Render, SpecListingMeshWithSeveralHoles)
{
  // The NSI spec's Listing 3.1: three squares, the first with a triangular
  // hole, the second with two square holes, the third with none (scaled by
  // 0.4 about the strip's centre, 10 ahead). The holes wind as the outlines
  // do, as the listing writes them.
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      R"(Create "shape" "mesh" Connect "shape" "" ".root" "objects"
SetAttribute "shape" "nholes" "int" 3 [ 1 2 0 ]
  "nvertices" "int" 6 [ 4 3  4 4 4  4 ]
  "P" "point" 23 [ -2.6 -0.6 -10  -1.4 -0.6 -10  -1.4 0.6 -10  -2.6 0.6 -10
    -2.2 -0.2 -10  -1.8 -0.2 -10  -2.2 0.2 -10
    -1 -0.6 -10  1 -0.6 -10  1 0.6 -10  -1 0.6 -10
    -0.6 -0.2 -10  -0.2 -0.2 -10  -0.2 0.2 -10  -0.6 0.2 -10
    0.2 -0.2 -10  0.6 -0.2 -10  0.6 0.2 -10  0.2 0.2 -10
    1.4 -0.6 -10  2.6 -0.6 -10  2.6 0.6 -10  1.4 0.6 -10 ])",
      "",
      R"("resolution" "int[2]" 1 [ 64 64 ] "oversampling" "int" 1 4)",
      path("holes.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  // 0.08375 units per pixel, the strip's centre at pixel (32, 32).
  auto at = [&](float x, float y) {
    return value(
        image, uint32_t(32.f + x / 0.08375f), uint32_t(32.f - y / 0.08375f));
  };
  EXPECT_EQ(at(-2.1f, -0.1f), 0.f) << "the first square's triangular hole";
  EXPECT_GT(at(-1.6f, 0.4f), 0.8f) << "the first square beside its hole";
  EXPECT_EQ(at(-0.4f, 0.f), 0.f) << "the second square's left hole";
  EXPECT_EQ(at(0.4f, 0.f), 0.f) << "the second square's right hole";
  EXPECT_GT(at(0.f, 0.f), 0.8f) << "between the two holes";
  EXPECT_GT(at(0.f, 0.45f), 0.8f) << "above the two holes";
  EXPECT_GT(at(2.f, 0.f), 0.8f) << "the third square, whole";
  EXPECT_EQ(at(-1.2f, 0.f), 0.f) << "between the first two squares";
}

TEST_F(Render, FaceVaryingColorsAreInterpolated)
{
  // The white square with a colour per corner (Cs through Cs.indices):
  // red, green, blue, white counter-clockwise from the bottom left.
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      whiteSquare(".root")
          + R"(SetAttribute "shape" "Cs" "color" 4 [ 1 0 0  0 1 0  0 0 1  1 1 1 ]
  "Cs.indices" "int" 4 [ 0 1 2 3 ])",
      "",
      R"("resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 4)",
      path("colors.exr"));
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  // 0.1675 units per pixel: the square spans columns and rows 10-22; these
  // pixels are 0.8 from the centre, near one corner each.
  auto at = [&](uint32_t x, uint32_t yFromTop) {
    return image.at(x, image.height - 1 - yFromTop);
  };
  const auto red = at(11, 20), green = at(20, 20), blue = at(20, 11),
             white = at(11, 11), middle = at(16, 16);
  EXPECT_GT(red.r, 0.6f);
  EXPECT_LT(red.g, 0.3f);
  EXPECT_GT(green.g, 0.6f);
  EXPECT_LT(green.r, 0.3f);
  EXPECT_GT(blue.b, 0.6f);
  EXPECT_LT(blue.g, 0.3f);
  EXPECT_GT(white.r + white.g + white.b, 2.f);
  // The centre lies on a diagonal, halfway between red and blue or green
  // and white: half red either way.
  EXPECT_NEAR(middle.r, 0.5f, 0.15f);
  EXPECT_GT(middle.b, 0.3f);
}

TEST_F(Render, FaceVaryingNormalsBendTheShading)
{
  // A sun behind the camera lights the square head on; normals tilted 60
  // degrees (one value for every corner through N.indices) halve that.
  const std::string sun =
      R"(Create "sun" "environment" Connect "sun" "" ".root" "objects"
SetAttribute "sun" "angle" "double" 1 1
Create "sunlight" "shader" SetAttribute "sunlight" "shaderfilename" "string" 1 "distantLight"
Create "sun_attr" "attributes" Connect "sunlight" "" "sun_attr" "surfaceshader"
Connect "sun_attr" "" "sun" "geometryattributes"
)";
  const std::string screen =
      R"("resolution" "int[2]" 1 [ 16 16 ] "oversampling" "int" 1 4)";
  NSIContext_t ctx = beginRender();
  const Image flat = renderWhite(
      ctx, whiteSquare(".root") + sun, "", screen, path("flat.exr"), Sky::None);
  NSIEnd(ctx);
  ctx = beginRender();
  const Image tilted = renderWhite(ctx,
      whiteSquare(".root") + sun
          + R"(SetAttribute "shape" "N" "normal" 1 [ 0.8660254 0 0.5 ]
  "N.indices" "int" 4 [ 0 0 0 0 ])",
      "",
      screen,
      path("tilted.exr"),
      Sky::None);
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  const float lit = value(flat, 8, 8), bent = value(tilted, 8, 8);
  EXPECT_GT(lit, 0.05f);
  EXPECT_NEAR(bent / lit, 0.5f, 0.1f);
}

TEST_F(Render, NormalSamplesTurnTheShadingAcrossTheShutter)
{
  // The sun behind the camera; N (one value through N.indices) turns
  // from facing it (t = 0) to 60 degrees off (t = 1) over the shutter.
  const std::string scene =
      whiteSquare(".root") +
      R"(Create "sun" "environment" Connect "sun" "" ".root" "objects"
SetAttribute "sun" "angle" "double" 1 1
Create "sunlight" "shader" SetAttribute "sunlight" "shaderfilename" "string" 1 "distantLight"
Create "sun_attr" "attributes" Connect "sunlight" "" "sun_attr" "surfaceshader"
Connect "sun_attr" "" "sun" "geometryattributes"
SetAttribute "shape" "N.indices" "int" 4 [ 0 0 0 0 ]
SetAttributeAtTime "shape" 1 "N" "normal" 1 [ 0.8660254 0 0.5 ]
SetAttributeAtTime "shape" 0 "N" "normal" 1 [ 0 0 1 ]
)";
  const std::string screen =
      R"("resolution" "int[2]" 1 [ 16 16 ] "oversampling" "int" 1 64)";
  NSIContext_t ctx = beginRender();
  const Image turning = renderWhite(ctx,
      scene,
      R"("shutterrange" "double" 2 [ 0 1 ])",
      screen,
      path("turning.exr"),
      Sky::None);
  NSIEnd(ctx);
  ctx = beginRender();
  const Image still =
      renderWhite(ctx, scene, "", screen, path("still.exr"), Sky::None);
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  // Normals interpolate linearly and are normalised: the mean of
  // cos(angle to the sun) over the shutter.
  double expected = 0;
  for (int i = 0; i < 1000; ++i) {
    const double t = (i + 0.5) / 1000;
    const double x = t * std::sin(M_PI / 3), z = 1 - t + t * 0.5;
    expected += z / std::hypot(x, z) / 1000;
  }
  const float lit = value(still, 8, 8); // the earliest sample: head on
  EXPECT_GT(lit, 0.05f);
  EXPECT_NEAR(value(turning, 8, 8) / lit, expected, 0.04) << expected;
}

TEST_F(Render, SetsStandForTheirMembers)
{
  // Two squares reach the root only as members of a set, which is also
  // given (unsupported) as the output layer's light set.
  NSIContext_t ctx = beginRender();
  const Image image = renderWhite(ctx,
      R"(Create "group" "set" Connect "group" "" ".root" "objects"
Create "shape" "mesh" Connect "shape" "" "group" "members"
SetAttribute "shape" "nvertices" "int" 1 4
  "P" "point" 4 [ -2 -1 -10  -0.5 -1 -10  -0.5 1 -10  -2 1 -10 ]
Create "other" "mesh" Connect "other" "" "group" "members"
SetAttribute "other" "nvertices" "int" 1 4
  "P" "point" 4 [ 0.5 -1 -10  2 -1 -10  2 1 -10  0.5 1 -10 ]
Connect "group" "" "layer" "lightset")",
      "",
      R"("resolution" "int[2]" 1 [ 32 16 ] "oversampling" "int" 1 4)",
      path("set.exr"));
  NSIEnd(ctx);
  const std::string problems = m_messages.problems();
  EXPECT_EQ(problems,
      "2: outputlayer 'layer': 'lightset' is not supported; every light is "
      "rendered\n");
  // 0.335 units per pixel: the squares span columns 10-14 and 17-22.
  EXPECT_GT(value(image, 12, 8), 0.8f) << "the white member";
  EXPECT_GT(value(image, 20, 8), 0.5f) << "the grey member";
  EXPECT_EQ(value(image, 16, 8), 0.f) << "between them";
}

struct FramingCase
{
  const char *name;
  bool orthographic;
  double fov;
  bool hasWindow;
  double window[4];        // left, bottom, right, top
  double crop[4];          // x0, y0, x1, y1 (y down)
  double squareX, squareY; // centre of the 2x2 square at distance 10
};

void PrintTo(const FramingCase &c, std::ostream *out)
{
  *out << c.name;
}

class Framing : public Render, public ::testing::WithParamInterface<FramingCase>
{};

// An NSI camera at the origin looking down -Z, a white 2x2 square at z = -10
// lit by a uniform environment, rendered at 64x48.
TEST_P(Framing, LightsThePredictedPixels)
{
  const FramingCase &c = GetParam();
  const uint32_t width = 64, height = 48;
  const std::string output = path("framing.png");

  NSI::Context nsi;
  NSI::ArgumentList begin;
  begin.addPointer("errorhandler",
      reinterpret_cast<const void *>(&MessageRecorder::handler));
  begin.addPointer("errorhandlerdata", &m_messages);
  ASSERT_TRUE(nsi.Begin(begin));
  nsi.Create(
      "cam", c.orthographic ? "orthographiccamera" : "perspectivecamera");
  nsi.Connect("cam", "", NSI_SCENE_ROOT, "objects");
  if (!c.orthographic)
    nsi.SetAttribute("cam", NSI::ArgumentList().addFloat("fov", float(c.fov)));
  nsi.Create("scr", "screen");
  NSI::ArgumentList screen;
  const int resolution[2] = {int(width), int(height)};
  screen.add("resolution", NSITypeInteger, resolution, 1, 2, NSIParamIsArray);
  screen.addInteger("oversampling", 4);
  if (c.hasWindow)
    screen.add("screenwindow", NSITypeDouble, c.window, 2, 2, NSIParamIsArray);
  const float crop[4] = {
      float(c.crop[0]), float(c.crop[1]), float(c.crop[2]), float(c.crop[3])};
  screen.add("crop", NSITypeFloat, crop, 2, 2, NSIParamIsArray);
  nsi.SetAttribute("scr", screen);
  nsi.Connect("scr", "", "cam", "screens");
  nsi.Create("layer", "outputlayer");
  nsi.SetAttribute(
      "layer", NSI::ArgumentList().addString("variablename", "Ci"));
  nsi.Connect("layer", "", "scr", "outputlayers");
  nsi.Create("driver", "outputdriver");
  nsi.SetAttribute("driver",
      NSI::ArgumentList()
          .addString("drivername", "png")
          .addString("imagefilename", output.c_str()));
  nsi.Connect("driver", "", "layer", "outputdrivers");

  nsi.Create("square", "mesh");
  const float x = float(c.squareX), y = float(c.squareY);
  const float points[12] = {x - 1,
      y - 1,
      -10,
      x + 1,
      y - 1,
      -10,
      x + 1,
      y + 1,
      -10,
      x - 1,
      y + 1,
      -10};
  nsi.SetAttribute("square",
      NSI::ArgumentList()
          .addInteger("nvertices", 4)
          .add("P", NSITypePoint, points, 4));
  nsi.Connect("square", "", NSI_SCENE_ROOT, "objects");
  nsi.Create("white", "shader");
  const float one[3] = {1, 1, 1};
  nsi.SetAttribute("white",
      NSI::ArgumentList()
          .addString("shaderfilename", "lambert")
          .add("i_color", NSITypeColor, one));
  nsi.Create("white_attr", "attributes");
  nsi.Connect("white", "", "white_attr", "surfaceshader");
  nsi.Connect("white_attr", "", "square", "geometryattributes");

  nsi.Create("sky", "environment");
  nsi.Connect("sky", "", NSI_SCENE_ROOT, "objects");
  nsi.Create("sky_shader", "shader");
  nsi.SetAttribute("sky_shader",
      NSI::ArgumentList()
          .addString("shaderfilename", "environmentLight")
          .addFloat("intensity", 1));
  nsi.Create("sky_attr", "attributes");
  nsi.Connect("sky_shader", "", "sky_attr", "surfaceshader");
  nsi.Connect("sky_attr", "", "sky", "geometryattributes");
  nsi.SetAttribute(
      "sky_attr", NSI::ArgumentList().addInteger("visibility.camera", 0));

  nsi.RenderControl(NSI::ArgumentList().addString("action", "start"));
  nsi.RenderControl(NSI::ArgumentList().addString("action", "wait"));
  nsi.End();
  EXPECT_EQ(m_messages.problems(), "");

  // The prediction, from the facts file's formulas: the window (default
  // [-a, a] x [-1, 1]) spans [l s, r s] x [b s, t s] at distance 1, with
  // s = tan(fov / 2) (1 for orthographic, the window then in camera units).
  double l = -double(width) / height, r = -l, b = -1, t = 1;
  if (c.hasWindow) {
    l = c.window[0];
    b = c.window[1];
    r = c.window[2];
    t = c.window[3];
  }
  const double s = c.orthographic ? 1.0 : std::tan(c.fov * M_PI / 360.0);
  const double distance = c.orthographic ? 1.0 : 10.0;
  // The crop keeps whole pixels: columns [cx0, cx1), rows [cy0, cy1) from the
  // top.
  const uint32_t cx0 = uint32_t(std::floor(c.crop[0] * width));
  const uint32_t cx1 = uint32_t(std::ceil(c.crop[2] * width));
  const uint32_t cy0 = uint32_t(std::floor(c.crop[1] * height));
  const uint32_t cy1 = uint32_t(std::ceil(c.crop[3] * height));

  const Image image = readImage(output);
  ASSERT_EQ(image.width, cx1 - cx0);
  ASSERT_EQ(image.height, cy1 - cy0);
  int predictedLit = 0, interiorMismatches = 0, edgeMismatches = 0;
  for (uint32_t row = cy0; row < cy1; ++row) {
    for (uint32_t col = cx0; col < cx1; ++col) {
      // Where the pixel centre's ray meets the square's plane.
      const double wx = l + (col + 0.5) / width * (r - l);
      const double wy = t - (row + 0.5) / height * (t - b);
      const double px = wx * s * distance, py = wy * s * distance;
      const bool inside = std::abs(px - x) < 1 && std::abs(py - y) < 1;
      // The distance to the square's outline, in pixels.
      const double pixelSize = (r - l) * s * distance / width;
      const double edge = std::min(std::abs(std::abs(px - x) - 1),
                              std::abs(std::abs(py - y) - 1))
                          / pixelSize;
      const bool lit = value(image, col - cx0, row - cy0) > 0.3f;
      predictedLit += inside;
      if (lit != inside)
        (edge < 1.0 ? edgeMismatches : interiorMismatches)++;
    }
  }
  EXPECT_GT(predictedLit, 20)
      << "the square must be in the picture for the test to mean anything";
  EXPECT_EQ(interiorMismatches, 0) << c.name;
  // Edge pixels may go either way, but most agree.
  EXPECT_LE(edgeMismatches, predictedLit / 3) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Nsi,
    Framing,
    ::testing::Values(
        FramingCase{"centred", false, 30, false, {}, {0, 0, 1, 1}, 0, 0},
        FramingCase{"narrow", false, 15, false, {}, {0, 0, 1, 1}, 0.3, -0.2},
        FramingCase{"offset_square", false, 40, false, {}, {0, 0, 1, 1}, 2, 1},
        FramingCase{"off_centre_window",
            false,
            30,
            true,
            {-0.5, -1, 1.5, 1},
            {0, 0, 1, 1},
            1,
            0},
        FramingCase{"tall_window",
            false,
            25,
            true,
            {-1, -0.5, 1, 1.5},
            {0, 0, 1, 1},
            0,
            1},
        FramingCase{
            "crop", false, 30, false, {}, {0.25, 0.1, 0.8, 0.7}, 0.5, 0.5},
        FramingCase{"crop_off_centre_window",
            false,
            30,
            true,
            {0, -1, 2, 1},
            {0.3, 0.3, 1, 0.9},
            3,
            0},
        FramingCase{"orthographic",
            true,
            0,
            true,
            {-3, -2, 3, 2},
            {0, 0, 1, 1},
            1,
            -0.5},
        FramingCase{"orthographic_crop",
            true,
            0,
            true,
            {-2, -3, 4, 1.5},
            {0.2, 0.1, 0.9, 0.6},
            1,
            0}),
    [](const auto &info) { return std::string(info.param.name); });

// suspend and resume reach a running progressive render, which then
// completes; with no render they only say so. (RenderSessionTest checks
// that no frame is issued while suspended.)
TEST_F(Render, SuspendAndResumeAProgressiveRender)
{
  NSIContext_t ctx = beginRender();
  renderControl(ctx, "suspend");
  auto before = m_messages.take();
  ASSERT_EQ(before.size(), 1u);
  EXPECT_EQ(before[0].level, NSIErrInfo);
  EXPECT_NE(before[0].text.find("no render running"), std::string::npos);

  squareScene(ctx, path("square.png"));
  StopRecord record;
  renderControl(ctx, "start", &record, true);
  renderControl(ctx, "suspend");
  renderControl(ctx, "resume");
  renderControl(ctx, "wait");
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  ASSERT_EQ(record.calls.size(), 1u);
  EXPECT_EQ(record.calls[0].second, NSIRenderCompleted);
  EXPECT_GT(value(readImage(path("square.png")), 12, 12), 0.f); // lit
}

} // namespace
