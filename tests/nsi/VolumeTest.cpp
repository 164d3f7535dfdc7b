// The NSI `volume` node on the prism device: a NanoVDB density ball, made
// by the test, absorbs the visible environment behind it; files and grids
// that cannot be rendered are reported through the error handler.
#include "NsiTestSupport.h"

#include "ImageIO.h"
#include "NanoVdbTestGrids.h"

#include <nanovdb/util/IO.h>

namespace {

using prism::image::Image;

class Volume : public NsiTest
{
 protected:
  // A 16-voxel ball of density (voxels of 0.1, so 1.6 across) moved by
  // its transform to be centred on the origin, behind it a visible grey
  // environment, seen by an orthographic camera at z = 5 over [-1, 1]^2.
  // `volume` holds the volume node's and its shader's attributes.
  void render(const std::string &volume, const std::string &output)
  {
    const std::string text = R"(
Create "cam_xf" "transform" Connect "cam_xf" "" ".root" "objects"
SetAttribute "cam_xf" "transformationmatrix" "doublematrix" 1
  [ 1 0 0 0  0 1 0 0  0 0 1 0  0 0 5 1 ]
Create "cam" "orthographiccamera" Connect "cam" "" "cam_xf" "objects"
Create "scr" "screen" Connect "scr" "" "cam" "screens"
SetAttribute "scr" "resolution" "int[2]" 1 [ 32 32 ] "oversampling" "int" 1 4
Create "layer" "outputlayer" Connect "layer" "" "scr" "outputlayers"
SetAttribute "layer" "variablename" "string" 1 "Ci"
Create "drv" "outputdriver" Connect "drv" "" "layer" "outputdrivers"
SetAttribute "drv" "drivername" "string" 1 "exr"
  "imagefilename" "string" 1 ")"
                             + path(output) + R"("
Create "sky" "environment" Connect "sky" "" ".root" "objects"
Create "light" "shader" SetAttribute "light" "shaderfilename" "string" 1 "environmentLight"
SetAttribute "light" "intensity" "float" 1 0.5
Create "sky_attr" "attributes" Connect "light" "" "sky_attr" "surfaceshader"
Connect "sky_attr" "" "sky" "geometryattributes"
Create "vol_xf" "transform" Connect "vol_xf" "" ".root" "objects"
SetAttribute "vol_xf" "transformationmatrix" "doublematrix" 1
  [ 1 0 0 0  0 1 0 0  0 0 1 0  -0.75 -0.75 -0.75 1 ]
Create "vol" "volume" Connect "vol" "" "vol_xf" "objects"
Create "smoke" "shader" SetAttribute "smoke" "shaderfilename" "string" 1 "vdbVolume"
Create "vol_attr" "attributes" Connect "smoke" "" "vol_attr" "volumeshader"
Connect "vol_attr" "" "vol" "geometryattributes"
)" + volume + R"(
RenderControl "action" "string" 1 "start"
RenderControl "action" "string" 1 "wait"
)";
    NSIContext_t ctx = beginRender();
    include(ctx, writeFile("scene.nsi", text));
    NSIEnd(ctx);
  }
  std::string writeBall()
  {
    const std::string file = path("ball.nvdb");
    nanovdb::io::writeGrid(
        file, prism::render::test_grids::makeDensityBall(16, 0.1));
    return file;
  }
  static float value(const Image &image, uint32_t x, uint32_t y)
  {
    const auto &p = image.at(x, y);
    return (p.r + p.g + p.b) / 3.f;
  }
};

// A black absorber darkens the environment behind its centre, not beside.
TEST_F(Volume, AttenuatesWhatIsBehindIt)
{
  render(R"(SetAttribute "vol" "vdbfilename" "string" 1 ")" + writeBall()
             + R"(" "densitygrid" "string" 1 "density"
SetAttribute "smoke" "color" "color" 1 [ 0 0 0 ] "density" "float" 1 8)",
      "ball.exr");
  EXPECT_EQ(m_messages.problems(), "");
  auto read = prism::image::read(path("ball.exr"));
  ASSERT_TRUE(read.ok()) << read.error;
  const Image &image = read.image;
  const float beside = value(image, 1, 1), behind = value(image, 16, 16);
  EXPECT_NEAR(beside, 0.5f, 0.02f); // the environment, untouched
  EXPECT_LT(behind, 0.5f * beside);
}

// What cannot be rendered is one message naming it (an error for a file
// that cannot be read, a warning for none given); the render goes on.
TEST_F(Volume, ReportsFilesAndGridsItCannotRead)
{
  const std::string ball = writeBall();
  const std::string openVdb = writeFile("smoke.vdb", "not read");
  const struct
  {
    std::string attributes;
    std::vector<const char *> fragments;
  } cases[] = {
      {R"("vdbfilename" "string" 1 ")" + path("missing.nvdb") + R"(")",
          {"volume 'vol'", "missing.nvdb"}},
      {R"("vdbfilename" "string" 1 ")" + openVdb + R"(")",
          {"volume 'vol'", "smoke.vdb", "OpenVDB"}},
      {R"("vdbfilename" "string" 1 ")" + ball
              + R"(" "densitygrid" "string" 1 "smoke")",
          {"volume 'vol'", "no grid 'smoke'", "'density' (float)"}},
      {"", {"volume 'vol' has no vdbfilename"}},
  };
  for (const auto &c : cases) {
    const std::string output = "out.exr";
    std::filesystem::remove(path(output));
    render("SetAttribute \"vol\" " + c.attributes, output);
    const auto messages = m_messages.take();
    int errors = 0;
    std::string all;
    for (const NsiMessage &m : messages) {
      all += m.text + "\n";
      if (m.level < NSIErrWarning)
        continue;
      ++errors;
      for (const char *fragment : c.fragments)
        EXPECT_NE(m.text.find(fragment), std::string::npos)
            << fragment << " in " << m.text;
    }
    EXPECT_EQ(errors, 1) << all;
    EXPECT_TRUE(std::filesystem::exists(path(output))) << c.attributes;
  }
}

} // namespace
