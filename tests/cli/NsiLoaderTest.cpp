// NSI streams through scene_io::loadScene on the prism device
// (NsiLoader.h): floor-lamp.nsi's floor, lit by a hidden quad lamp above
// it, seen through the stream's own camera; a broken stream is one error.
#include "DeviceTestSupport.h"
#include "NsiLoader.h"
#include "SceneLoader.h"

#include <anari/anari.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace prism::scene_io;

const std::string kData = PRISM_CLI_DATA;

class NsiLoader : public LibraryDeviceTest
{
 protected:
  NsiLoader() : LibraryDeviceTest("prism") {}

  // The path tracer's colour through the scene's camera, 48 x 36, row 0 at
  // the bottom (ANARI's order).
  std::vector<float> render(const prism::scenes::Scene &scene)
  {
    ANARIDevice d = m_device;
    ANARICamera camera = anariNewCamera(d, "perspective");
    const auto &c = scene.camera;
    const float direction[3] = {
        c.at[0] - c.eye[0], c.at[1] - c.eye[1], c.at[2] - c.eye[2]};
    const float aspect = float(kWidth) / kHeight,
                fovy = c.fovyDegrees * float(M_PI) / 180.f;
    anariSetParameter(d, camera, "position", ANARI_FLOAT32_VEC3, c.eye.data());
    anariSetParameter(d, camera, "direction", ANARI_FLOAT32_VEC3, direction);
    anariSetParameter(d, camera, "up", ANARI_FLOAT32_VEC3, c.up.data());
    anariSetParameter(d, camera, "aspect", ANARI_FLOAT32, &aspect);
    anariSetParameter(d, camera, "fovy", ANARI_FLOAT32, &fovy);
    anariCommitParameters(d, camera);
    ANARIRenderer renderer = anariNewRenderer(d, "pathtracer");
    anariSetParameter(
        d, renderer, "background", ANARI_FLOAT32_VEC4, scene.background.data());
    anariCommitParameters(d, renderer);
    ANARIFrame frame = anariNewFrame(d);
    const uint32_t size[2] = {kWidth, kHeight};
    const ANARIDataType color = ANARI_FLOAT32_VEC4;
    anariSetParameter(d, frame, "size", ANARI_UINT32_VEC2, size);
    anariSetParameter(d, frame, "channel.color", ANARI_DATA_TYPE, &color);
    anariSetParameter(d, frame, "world", ANARI_WORLD, &scene.world);
    anariSetParameter(d, frame, "camera", ANARI_CAMERA, &camera);
    anariSetParameter(d, frame, "renderer", ANARI_RENDERER, &renderer);
    anariCommitParameters(d, frame);
    for (int pass = 0; pass < 8; ++pass) { // accumulated: 8 samples a pixel
      anariRenderFrame(d, frame);
      anariFrameReady(d, frame, ANARI_WAIT);
    }
    uint32_t width = 0, height = 0;
    ANARIDataType type = ANARI_UNKNOWN;
    const auto *pixels = static_cast<const float *>(
        anariMapFrame(d, frame, "channel.color", &width, &height, &type));
    std::vector<float> image;
    if (pixels && width == kWidth && height == kHeight)
      image.assign(pixels, pixels + size_t(width) * height * 4);
    anariUnmapFrame(d, frame, "channel.color");
    anariRelease(d, frame);
    anariRelease(d, renderer);
    anariRelease(d, camera);
    return image;
  }

  // The mean of red, green and blue over rows [y0, y1) of the whole width.
  static float rowsMean(const std::vector<float> &image, int y0, int y1)
  {
    double sum = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < int(kWidth); ++x)
        for (int c = 0; c < 3; ++c)
          sum += image[(size_t(y) * kWidth + x) * 4 + c];
    return float(sum / (3.0 * kWidth * (y1 - y0)));
  }

  static constexpr uint32_t kWidth = 48, kHeight = 36;
};

TEST_F(NsiLoader, FloorLampLoadsWithItsCameraAndRendersLit)
{
  LoadResult loaded = loadScene(m_device, kData + "/floor-lamp.nsi");
  ASSERT_TRUE(loaded.ok()) << loaded.error;
  prism::scenes::Scene &scene = loaded.scene;
  ASSERT_NE(scene.world, nullptr);
  // The stream's camera: at (0, 1, 6) looking down -Z, fov 45 degrees.
  ASSERT_TRUE(scene.camera.valid);
  EXPECT_NEAR(scene.camera.eye[1], 1.f, 1e-5);
  EXPECT_NEAR(scene.camera.eye[2], 6.f, 1e-5);
  EXPECT_LT(scene.camera.at[2], scene.camera.eye[2]);
  EXPECT_NEAR(scene.camera.fovyDegrees, 45.f, 0.5f);
  // The floor (6 x 6 at y = 0) is the outline; the hidden lamp is in too.
  EXPECT_NEAR(scene.bounds.lower[0], -3.f, 1e-5);
  EXPECT_NEAR(scene.bounds.upper[0], 3.f, 1e-5);
  EXPECT_NEAR(scene.bounds.lower[1], 0.f, 1e-5);
  EXPECT_FALSE(scene.outline.empty());

  const std::vector<float> image = render(scene);
  ASSERT_EQ(image.size(), size_t(kWidth) * kHeight * 4);
  // The floor fills the lower rows (row 0 at the bottom), lit by the lamp;
  // above the horizon the black background.
  const float floor = rowsMean(image, 0, 10);
  const float sky = rowsMean(image, kHeight - 6, kHeight);
  std::printf("floor mean %.4f, sky mean %.4f\n", floor, sky);
  EXPECT_GT(floor, 0.05f); // measured 0.147
  EXPECT_LT(sky, 0.005f);
  prism::scenes::releaseScene(m_device, scene);
}

TEST_F(NsiLoader, BrokenStreamIsOneError)
{
  LoadResult loaded = loadScene(m_device, kData + "/broken.nsi");
  EXPECT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.scene.world, nullptr);
  EXPECT_NE(loaded.error.find("broken.nsi"), std::string::npos) << loaded.error;
  EXPECT_NE(loaded.error.find("Frobnicate"), std::string::npos) << loaded.error;
  EXPECT_EQ(loaded.error.find('\n'), std::string::npos) << loaded.error;
  std::printf("%s\n", loaded.error.c_str());
}

TEST_F(NsiLoader, MissingStreamIsAnError)
{
  const LoadResult loaded = loadNsi(m_device, kData + "/no-such-stream.nsi");
  EXPECT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error.find("no-such-stream.nsi"), std::string::npos);
}

TEST(NsiRenderControl, StatementsAreBlankedLinesKept)
{
  const std::string text =
      "Create \"a\" \"mesh\"\nRenderControl\n"
      "  \"action\" \"string\" 1 \"start\"\n"
      "Connect \"a\" \"\" \".root\" \"objects\"\n";
  const std::string out = withoutRenderControl(text);
  EXPECT_EQ(out.size(), text.size());
  EXPECT_EQ(out.find("RenderControl"), std::string::npos);
  EXPECT_EQ(out.find("start"), std::string::npos);
  EXPECT_NE(out.find("Create \"a\" \"mesh\"\n"), std::string::npos);
  EXPECT_NE(out.find("\nConnect \"a\""), std::string::npos);
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 4);
  // The word inside a string or a comment is no statement.
  const std::string quoted = "# RenderControl\nCreate \"RenderControl\" \"x\"";
  EXPECT_EQ(withoutRenderControl(quoted), quoted);
}

} // namespace
