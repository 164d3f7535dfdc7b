// A Catmull-Clark unit cube rendered face-on through an orthographic
// camera, its silhouette measured in the image: narrower than the cage's,
// at the limit surface's width (2 * 34/81 of the cage's), and converging
// as the level rises; sharp creases keep the cage's outline.
#include "NsiTestSupport.h"

#include "ImageIO.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace {

using prism::image::Image;

// 200 pixels across a window 2 units wide: 100 pixels per unit.
constexpr double kPixelsPerUnit = 100;
constexpr double kLimitWidth = 2 * 34.0 / 81.0;

const char *kCube = R"(Create "xf" "transform" Connect "xf" "" ".root" "objects"
SetAttribute "xf" "transformationmatrix" "doublematrix" 1
  [ 1 0 0 0  0 1 0 0  0 0 1 0  0 0 -5 1 ]
Create "shape" "mesh" Connect "shape" "" "xf" "objects"
SetAttribute "shape" "nvertices" "int" 6 [ 4 4 4 4 4 4 ]
  "P" "point" 8 [ -0.5 -0.5 -0.5  0.5 -0.5 -0.5  -0.5 0.5 -0.5  0.5 0.5 -0.5
                  -0.5 -0.5 0.5  0.5 -0.5 0.5  -0.5 0.5 0.5  0.5 0.5 0.5 ]
  "P.indices" "int" 24 [ 0 2 3 1  4 5 7 6  0 1 5 4  2 6 7 3  0 4 6 2  1 3 7 5 ]
)";

class SubdivisionRender : public NsiTest
{
 protected:
  // The cube with `extra` attributes on its mesh (and `global` on .global),
  // white under a hidden uniform sky: every pixel it covers is 1 (a convex
  // shape sees all the sky), so a row's sum is its width in pixels.
  Image render(const std::string &extra, const std::string &global = "")
  {
    const std::string output =
        path("cube" + std::to_string(m_count++) + ".exr");
    const std::string text =
        R"(Create "cam" "orthographiccamera" Connect "cam" "" ".root" "objects"
Create "scr" "screen" Connect "scr" "" "cam" "screens"
SetAttribute "scr" "resolution" "int[2]" 1 [ 200 200 ] "oversampling" "int" 1 16
  "screenwindow" "double[2]" 2 [ -1 -1 1 1 ]
Create "layer" "outputlayer" Connect "layer" "" "scr" "outputlayers"
Create "file" "outputdriver" Connect "file" "" "layer" "outputdrivers"
SetAttribute "file" "drivername" "string" 1 "exr" "imagefilename" "string" 1 ")"
        + output + "\"\n" + kCube + "SetAttribute \"shape\" " + extra + "\n"
        + (global.empty() ? "" : "SetAttribute \".global\" " + global + "\n")
        + R"(Create "white" "shader" SetAttribute "white" "shaderfilename" "string" 1 "lambert"
  "i_color" "color" 1 [ 1 1 1 ]
Create "attr" "attributes" Connect "white" "" "attr" "surfaceshader"
Connect "attr" "" "shape" "geometryattributes"
Create "sky" "environment" Connect "sky" "" ".root" "objects"
Create "light" "shader" SetAttribute "light" "shaderfilename" "string" 1 "environmentLight"
Create "sky_attr" "attributes" Connect "light" "" "sky_attr" "surfaceshader"
Connect "sky_attr" "" "sky" "geometryattributes"
SetAttribute "sky_attr" "visibility.camera" "int" 1 0
RenderControl "action" "string" 1 "start" RenderControl "action" "string" 1 "wait"
)";
    const std::string file = output + ".nsi";
    std::ofstream(file) << text;
    NSIContext_t ctx = beginRender();
    include(ctx, file);
    NSIEnd(ctx);
    EXPECT_EQ(m_messages.problems(), "");
    auto result = prism::image::read(output);
    EXPECT_TRUE(result.ok()) << result.error;
    return result.image;
  }
  // The middle row's covered width, in units.
  static double middleWidth(const Image &image)
  {
    double sum = 0;
    for (uint32_t x = 0; x < image.width; ++x) {
      const auto &p = image.at(x, image.height / 2);
      sum += (p.r + p.g + p.b) / 3;
    }
    return sum / kPixelsPerUnit;
  }
  // The covered area, in square units.
  static double area(const Image &image)
  {
    double sum = 0;
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = 0; x < image.width; ++x) {
        const auto &p = image.at(x, y);
        sum += (p.r + p.g + p.b) / 3;
      }
    return sum / (kPixelsPerUnit * kPixelsPerUnit);
  }

  int m_count{0};
};

const std::string kCatmullClark =
    R"("subdivision.scheme" "string" 1 "catmull-clark")";

std::string level(int n)
{
  return R"( "subdivision.level" "int" 1 )" + std::to_string(n);
}

TEST_F(SubdivisionRender, SilhouetteShrinksToTheLimitSurface)
{
  const Image cage = render(R"("clockwisewinding" "int" 1 0)");
  const Image one = render(kCatmullClark + level(1));
  const Image three = render(kCatmullClark); // the default level, 3
  const Image five = render(kCatmullClark, R"("subdivision.level" "int" 1 5)");
  ASSERT_EQ(cage.width, 200u);
  EXPECT_NEAR(middleWidth(cage), 1.0, 0.01);
  EXPECT_NEAR(middleWidth(three), kLimitWidth, 0.01);
  EXPECT_LT(middleWidth(three), middleWidth(cage) - 0.1);
  // Finer levels fill in the chords between limit points: the area grows
  // towards level 5's, level 3 much nearer than level 1.
  const double error1 = std::abs(area(one) - area(five));
  const double error3 = std::abs(area(three) - area(five));
  EXPECT_LT(error3, error1 / 4)
      << area(one) << " " << area(three) << " " << area(five);
  EXPECT_LT(error3 / area(five), 0.01);
  std::printf(
      "silhouette: cage width %.4f area %.4f; level 1 area %.4f; "
      "level 3 width %.4f area %.4f; level 5 area %.4f\n",
      middleWidth(cage),
      area(cage),
      area(one),
      middleWidth(three),
      area(three),
      area(five));
  EXPECT_LT(area(five), area(cage) - 0.1);
}

TEST_F(SubdivisionRender, SharpCreasesAndCornersKeepTheOutline)
{
  const Image creased =
      render(kCatmullClark + R"( "subdivision.creasevertices" "int" 24
  [ 0 1 2 3 4 5 6 7 0 2 1 3 4 6 5 7 0 4 1 5 2 6 3 7 ]
  "subdivision.creasesharpness" "float" 12 [ 10 10 10 10 10 10 10 10 10 10 10 10 ])");
  EXPECT_NEAR(middleWidth(creased), 1.0, 0.01);
  const Image cornered =
      render(kCatmullClark
             + R"( "subdivision.cornervertices" "int" 8 [ 0 1 2 3 4 5 6 7 ]
  "subdivision.cornersharpness" "float" 8 [ 10 10 10 10 10 10 10 10 ])");
  const Image smooth = render(kCatmullClark);
  // The square's corner (pixel 148, 148 is 0.485 units out on both axes)
  // is covered where the corners are sharp, empty where smooth.
  auto covered = [](const Image &image) {
    const auto &p = image.at(148, 148);
    return (p.r + p.g + p.b) / 3;
  };
  EXPECT_GT(covered(cornered), 0.9f);
  EXPECT_LT(covered(smooth), 0.1f);
  EXPECT_GT(covered(creased), 0.9f);
  // Smooth edges between the sharp corners still bow in.
  EXPECT_LT(middleWidth(cornered), 0.98);
}

} // namespace
