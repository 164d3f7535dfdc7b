// The session on the prism device, without a window: parameter panels from
// introspection, progressive frames through the pipeline, picking, the
// script's set, and failures that leave the session usable.
#include "ScriptRunner.h"
#include "ViewerSession.h"

#include <gtest/gtest.h>

#include "ImageIO.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

namespace prism::viewer {
namespace {

// Polls as the UI loop does until `done` (ctest's timeout bounds it).
template <typename Done>
void pollUntil(ViewerSession &session, Done done)
{
  while (!done()) {
    session.update();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

class ViewerSessionTest : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    open("default", 64, 48);
  }

  void open(const std::string &renderer, uint32_t width, uint32_t height)
  {
    m_options.renderer = renderer;
    m_session = std::make_unique<ViewerSession>(m_options);
    ASSERT_EQ(m_session->open(), "");
    m_session->setViewport(width, height, 1.f);
  }

  ViewerOptions m_options;
  std::unique_ptr<ViewerSession> m_session;
};

TEST_F(ViewerSessionTest, RendererPanelComesFromIntrospection)
{
  const ParameterSet &renderer = m_session->rendererParameters();
  const ParameterWidget *depth = renderer.find("maxPathLength");
  ASSERT_NE(depth, nullptr);
  EXPECT_EQ(depth->kind, WidgetKind::Integer);
  EXPECT_EQ(depth->minimum, 1.0);
  EXPECT_EQ(depth->maximum, 1024.0);
  ASSERT_TRUE(renderer.value("maxPathLength"));
  EXPECT_EQ(renderer.value("maxPathLength")->numbers.at(0), 8.0);
  const ParameterWidget *background = renderer.find("background");
  ASSERT_NE(background, nullptr);
  EXPECT_EQ(background->kind, WidgetKind::Color);
  EXPECT_EQ(background->components, 4);
}

TEST_F(ViewerSessionTest, EnumsListTheirValues)
{
  m_session->setRenderer("debug");
  const ParameterWidget *mode = m_session->rendererParameters().find("mode");
  ASSERT_NE(mode, nullptr);
  EXPECT_EQ(mode->kind, WidgetKind::Choice);
  EXPECT_NE(std::find(mode->choices.begin(), mode->choices.end(), "objectId"),
      mode->choices.end());
  EXPECT_EQ(m_session->setParameter("renderer", 0, "mode", {"uv"}), "");
  EXPECT_EQ(m_session->rendererParameters().value("mode")->text, "uv");
  EXPECT_NE(m_session->setParameter("renderer", 0, "mode", {"sideways"}), "");
}

TEST_F(ViewerSessionTest, SetChecksNamesTypesAndRanges)
{
  EXPECT_EQ(m_session->setParameter("renderer", 0, "maxPathLength", {"2"}), "");
  EXPECT_EQ(
      m_session->rendererParameters().value("maxPathLength")->numbers.at(0),
      2.0);
  EXPECT_NE(m_session->setParameter("renderer", 0, "maxPathLength", {"0"}), "");
  EXPECT_NE(
      m_session->setParameter("renderer", 0, "maxPathLength", {"1.5"}), "");
  EXPECT_NE(m_session->setParameter("renderer", 0, "noSuchThing", {"1"}), "");
  EXPECT_NE(m_session->setParameter("renderer", 1, "maxPathLength", {"2"}), "");
  EXPECT_NE(m_session->setParameter("light", 5, "intensity", {"2"}), "");
  EXPECT_EQ(m_session->setParameter("camera", 0, "fovy", {"0.5"}), "");
  EXPECT_NEAR(m_session->camera().pose().fovyDegrees, 28.6479f, 1e-3f);
  // The pose sets the position on every move: the script may not.
  EXPECT_NE(
      m_session->setParameter("camera", 0, "position", {"0", "0", "0"}), "");
}

TEST_F(ViewerSessionTest, ThePickedObjectIsTintedInTheShownImageOnly)
{
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  FramePipeline &pipeline = m_session->pipeline();
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 1; });
  pipeline.finish();
  const std::optional<Pick> picked = m_session->pick(32, 24);
  ASSERT_TRUE(picked && picked->hit);
  const Rgba8Image plain = pipeline.image();
  const Rgba8Image shown = m_session->shownImage();
  const std::vector<bool> mask = pickedMask(pipeline.ids(), *picked);
  ASSERT_EQ(shown.pixels.size(), plain.pixels.size());
  size_t tinted = 0, untouched = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    const bool same = std::equal(
        &shown.pixels[4 * i], &shown.pixels[4 * i + 3], &plain.pixels[4 * i]);
    tinted += mask[i] && !same;
    untouched += !mask[i] && same;
  }
  const size_t inMask = std::count(mask.begin(), mask.end(), true);
  EXPECT_GT(inMask, 0u);
  EXPECT_GT(tinted, inMask / 2); // pure orange pixels do not change
  EXPECT_EQ(untouched, mask.size() - inMask);
}

TEST_F(ViewerSessionTest, FramesRefineAndPickingFindsTheBoxes)
{
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  FramePipeline &pipeline = m_session->pipeline();
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 3; });
  EXPECT_EQ(pipeline.image().width, 64u);
  // The path tracer counts its rays: a rate over the last frame.
  EXPECT_TRUE(pipeline.status().countsRays);
  EXPECT_GT(pipeline.status().raysPerSecond, 0.0);
  EXPECT_GT(pipeline.status().frameSeconds, 0.f);
  EXPECT_EQ(pipeline.image().pixels.size(), 64u * 48u * 4u);
  // The middle of the framed box shows a wall or a block; a corner of the
  // window shows nothing.
  const std::optional<Pick> middle = m_session->pick(32, 24);
  ASSERT_TRUE(middle);
  EXPECT_TRUE(middle->hit);
  EXPECT_NE(middle->objectId, kNoId);
  EXPECT_TRUE(middle->depth);
  ASSERT_TRUE(m_session->selection());
  // A change restarts accumulation: samples count from zero again.
  m_session->camera().orbit(10.f, 0.f);
  m_session->cameraChanged();
  EXPECT_EQ(pipeline.status().samples, 0u);
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 1; });
}

// demo:cornell-box under the raycast renderer (one ray through each pixel
// centre, color = baseColor * eye-light cosine term: linear in the color,
// the same on every run) at 320x240, where pixel (70, 120) shows the red
// wall (surface id 1, a matte 0.65 0.05 0.05).
class PickedSurfaceTest : public ViewerSessionTest
{
 protected:
  void SetUp() override
  {
    open("raycast", 320, 240);
    ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  }

  LinearColorImage render()
  {
    FramePipeline &pipeline = m_session->pipeline();
    pollUntil(*m_session, [&] { return pipeline.status().samples >= 1; });
    pipeline.finish();
    return pipeline.linearColor();
  }
};

TEST_F(PickedSurfaceTest, TheSceneListsItsSurfacesAndLights)
{
  render();
  ASSERT_TRUE(m_session->pick(70, 120));
  const std::optional<SelectedSurface> &surface = m_session->selectedSurface();
  ASSERT_TRUE(surface);
  EXPECT_EQ(surface->label, "surface 1: triangle geometry, matte material");
  const ParameterWidget *color = surface->material.find("color");
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->kind, WidgetKind::Color);
  EXPECT_NE(surface->geometry.find("vertex.position"), nullptr);
  // The box's quad light, with its own panel (the raycast renderer gets no
  // environment).
  ASSERT_EQ(m_session->lights().size(), 1u);
  EXPECT_EQ(m_session->lights()[0].label, "light 0 (quad)");
  EXPECT_NE(m_session->lights()[0].parameters.find("edge1"), nullptr);
  // Nothing picked: no surface to edit.
  m_session->pick(1, 1);
  EXPECT_FALSE(m_session->selectedSurface());
  EXPECT_NE(
      m_session->setParameter("material", 0, "color", {"1", "0", "0"}), "");
}

TEST_F(PickedSurfaceTest, EditingTheMaterialRecolorsThatSurfaceOnly)
{
  const LinearColorImage before = render();
  ASSERT_TRUE(m_session->pick(70, 120));
  ASSERT_EQ(m_session->selection()->objectId, 1u);
  const std::vector<bool> wall =
      pickedMask(m_session->pipeline().ids(), *m_session->selection());
  // Red and blue swapped: each wall pixel's red and blue swap, as the
  // color is linear in the base color; every other pixel stays.
  ASSERT_EQ(
      m_session->setParameter("material", 0, "color", {"0.05", "0.05", "0.65"}),
      "");
  EXPECT_EQ(m_session->pipeline().status().samples, 0u);
  const LinearColorImage after = render();
  ASSERT_EQ(after.pixels.size(), before.pixels.size());
  ASSERT_EQ(wall.size() * 4, before.pixels.size());
  size_t wallPixels = 0, others = 0, othersSame = 0;
  for (size_t i = 0; i < wall.size(); ++i) {
    const float *b = &before.pixels[4 * i], *a = &after.pixels[4 * i];
    if (wall[i]) {
      ++wallPixels;
      EXPECT_GT(b[0], 2.f * b[2]) << i;
      EXPECT_NEAR(a[0], b[2], 1e-5f + 1e-5f * b[2]) << i;
      EXPECT_NEAR(a[1], b[1], 1e-5f + 1e-5f * b[1]) << i;
      EXPECT_NEAR(a[2], b[0], 1e-5f + 1e-5f * b[0]) << i;
    } else {
      ++others;
      othersSame += std::equal(a, a + 4, b);
    }
  }
  EXPECT_GT(wallPixels, 320u * 240u / 20);
  EXPECT_EQ(othersSame, others);
}

TEST_F(PickedSurfaceTest, ExrScreenshotsKeepTheLinearFloats)
{
  // A background of 4 2 0.5 shows in the corners: above what 8 bits hold.
  ASSERT_EQ(m_session->setParameter(
                "renderer", 0, "background", {"4", "2", "0.5", "1"}),
      "");
  const LinearColorImage shown = render();
  const std::string path = ::testing::TempDir() + "viewer-hdr.exr";
  ASSERT_EQ(m_session->screenshot(path), "");
  const image::ReadResult read = image::read(path);
  ASSERT_TRUE(read.ok()) << read.error;
  ASSERT_EQ(read.image.width, 320u);
  ASSERT_EQ(read.image.height, 240u);
  for (size_t i = 0; i < read.image.pixels.size(); ++i)
    for (int c = 0; c < 4; ++c)
      ASSERT_EQ(read.image.pixels[i][c], shown.pixels[4 * i + c]) << i;
  const image::Rgba &corner = read.image.pixels[0];
  EXPECT_EQ(corner[0], 4.f);
  EXPECT_EQ(corner[1], 2.f);
  EXPECT_EQ(corner[2], 0.5f);
  std::remove(path.c_str());
}

TEST_F(ViewerSessionTest, TheSampleLimitStopsRefinement)
{
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  FramePipeline &pipeline = m_session->pipeline();
  pipeline.setSampleLimit(2);
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 2; });
  for (int i = 0; i < 50; ++i) {
    m_session->update();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  pipeline.finish();
  EXPECT_EQ(pipeline.status().samples, 2u);
}

TEST_F(ViewerSessionTest, AFileThatFailsKeepsTheSceneShown)
{
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  const std::string error = m_session->loadScene("/nonexistent/model.glb");
  EXPECT_NE(error.find("/nonexistent/model.glb"), std::string::npos) << error;
  EXPECT_EQ(m_session->sceneName(), "demo:cornell-box");
  EXPECT_NE(m_session->loadScene("demo:no-such-demo"), "");
  FramePipeline &pipeline = m_session->pipeline();
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 1; });
}

TEST_F(ViewerSessionTest, ScriptsRunThroughTheSession)
{
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  ScriptRunner runner(
      parseScript("orbit 20\n"
                  "set renderer 0 maxPathLength 1\n"
                  "wait-samples 2\n"
                  "channel objectId\n"
                  "set renderer 0 maxPathLength 0\n"));
  ScriptState state = ScriptState::Running;
  pollUntil(*m_session, [&] {
    state = runner.step(*m_session);
    return state != ScriptState::Running;
  });
  EXPECT_EQ(state, ScriptState::Failed);
  EXPECT_EQ(runner.error().rfind("script line 5 'set renderer 0 "
                                 "maxPathLength 0': ",
                0),
      0u)
      << runner.error();
  EXPECT_EQ(m_session->pipeline().channel(), Channel::ObjectId);
}

TEST_F(ViewerSessionTest, TheVolumeIsRestyledKeepingTheView)
{
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  EXPECT_FALSE(m_session->hasVolume());
  EXPECT_NE(m_session->restyleVolume({}), "");
  ASSERT_EQ(m_session->loadScene("demo:volume"), "");
  ASSERT_TRUE(m_session->hasVolume());
  FramePipeline &pipeline = m_session->pipeline();
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 1; });
  m_session->camera().orbit(40.f, 0.f);
  m_session->cameraChanged();
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 4; });
  const CameraPose before = m_session->camera().pose();
  const Rgba8Image styled = pipeline.image();
  TransferFunctionEdit edit;
  edit.opacities = {0.f, 0.f}; // invisible: the environment shows through
  ASSERT_EQ(m_session->restyleVolume(edit), "");
  EXPECT_EQ(m_session->camera().pose().eye, before.eye);
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 4; });
  const Rgba8Image &clear = pipeline.image();
  ASSERT_EQ(clear.pixels.size(), styled.pixels.size());
  // The window's border shows the environment either way; its middle,
  // the volume, changes.
  auto difference = [&](uint32_t x, uint32_t y) {
    const size_t i = 4 * (size_t(y) * clear.width + x);
    int d = 0;
    for (int c = 0; c < 3; ++c)
      d += std::abs(int(clear.pixels[i + c]) - int(styled.pixels[i + c]));
    return d;
  };
  EXPECT_LE(difference(0, 0), 3);
  EXPECT_GT(difference(32, 24), 30);
  edit.opacities = {0.f, 2.f};
  EXPECT_EQ(m_session->restyleVolume(edit), "opacities are between 0 and 1");
  edit.opacities = {1.f};
  edit.customRange = true;
  edit.range = {1.f, 1.f};
  EXPECT_EQ(m_session->restyleVolume(edit), "the value range needs low < high");
}

TEST_F(ViewerSessionTest, TheFileCamerasAreViewedThrough)
{
  const std::string file =
      std::string(PRISM_VIEWER_TEST_DATA) + "/fresnel-plane.gltf";
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  EXPECT_FALSE(m_session->hasFileCameras());
  ASSERT_EQ(m_session->loadScene(file), "");
  ASSERT_TRUE(m_session->hasFileCameras());
  m_session->camera().orbit(90.f, 0.f);
  m_session->cameraChanged();
  const Vec3 moved = m_session->camera().pose().eye;
  ASSERT_EQ(m_session->viewFileCamera(0), "");
  EXPECT_NE(m_session->camera().pose().eye, moved); // back at the file's
  const std::string error = m_session->viewFileCamera(1);
  EXPECT_NE(error.find("the file has 1 camera"), std::string::npos) << error;
  EXPECT_EQ(m_session->fileCamera(), 0);
  EXPECT_EQ(m_session->sceneName(), file);
}

// mirrored-quads.gltf's orthographic camera at z = 3 over [-1, 1]^2 looks
// at quads at z = 0 and z = 0.5 facing it: every ray is parallel, so the
// depth of each quad is the same in all its pixels (in perspective it
// would grow towards the edges), 3 or 2.5.
TEST_F(ViewerSessionTest, OrthographicFileCamerasAreOrthographic)
{
  ASSERT_EQ(m_session->loadScene(
                std::string(PRISM_VIEWER_TEST_DATA) + "/mirrored-quads.gltf"),
      "");
  EXPECT_EQ(m_session->cameraParameters().subtype(), "orthographic");
  EXPECT_TRUE(m_session->camera().pose().orthographic);
  EXPECT_FLOAT_EQ(m_session->camera().pose().height, 2.f);
  FramePipeline &pipeline = m_session->pipeline();
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 1; });
  pipeline.finish();
  size_t hits = 0, onAQuad = 0;
  for (float depth : pipeline.ids().depth) {
    if (!std::isfinite(depth))
      continue;
    ++hits;
    onAQuad += std::abs(depth - 3.f) < 1e-4f || std::abs(depth - 2.5f) < 1e-4f;
  }
  EXPECT_GT(hits, 64u * 48u / 4);
  EXPECT_EQ(onAQuad, hits);
  // Back to a perspective scene: a perspective camera again.
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  EXPECT_EQ(m_session->cameraParameters().subtype(), "perspective");
}

// The MPI mirror without MPI: what one session sends, another makes.
TEST_F(ViewerSessionTest, AMirroredSessionFollowsEveryChange)
{
  std::vector<std::string> lines;
  m_session->mirrorTo([&](const std::string &line) { lines.push_back(line); });
  ASSERT_EQ(m_session->loadScene("demo:cornell-box"), "");
  m_session->camera().orbit(25.f, 10.f);
  m_session->cameraChanged();
  ASSERT_EQ(m_session->setParameter("renderer", 0, "maxPathLength", {"3"}), "");
  ASSERT_EQ(m_session->setParameter("camera", 0, "fovy", {"0.7"}), "");
  FramePipeline &pipeline = m_session->pipeline();
  pollUntil(*m_session, [&] { return pipeline.status().samples >= 1; });
  pipeline.finish();
  // Nested changes are not sent again: one load, no frame of its own.
  EXPECT_EQ(std::count_if(lines.begin(),
                lines.end(),
                [](const std::string &l) { return l.rfind("load ", 0) == 0; }),
      1);
  EXPECT_EQ(std::count(lines.begin(), lines.end(), "frame"), 0);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "render"), lines.end());
  EXPECT_NE(
      std::find(lines.begin(), lines.end(), "set renderer 0 maxPathLength 3"),
      lines.end());

  ViewerSession follower(m_options);
  ASSERT_EQ(follower.open(), "");
  for (const std::string &line : lines)
    ASSERT_TRUE(follower.applyMirrored(line)) << line;
  EXPECT_FALSE(follower.applyMirrored("quit"));
  EXPECT_EQ(follower.sceneName(), "demo:cornell-box");
  const CameraPose &a = m_session->camera().pose(),
                   &b = follower.camera().pose();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.eye[i], b.eye[i], 1e-5f);
    EXPECT_NEAR(a.at[i], b.at[i], 1e-5f);
  }
  EXPECT_NEAR(a.fovyDegrees, b.fovyDegrees, 1e-4f);
  EXPECT_EQ(
      follower.rendererParameters().value("maxPathLength")->numbers.at(0), 3.0);
  EXPECT_EQ(follower.pipeline().width(), pipeline.width());
}

TEST(ViewerSessionOpen, ALibraryThatFailsIsNamed)
{
  ViewerOptions options;
  options.library = "no_such_library";
  ViewerSession session(options);
  const std::string error = session.open();
  EXPECT_NE(error.find("no_such_library"), std::string::npos) << error;
}

} // namespace
} // namespace prism::viewer
