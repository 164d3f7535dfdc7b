// RenderSession on the prism device: a suspended render issues no frames
// until resumed, and a progressive one writes its outputs after every
// frame, the last of them the full render.
#include "ImageIO.h"
#include "NsiTestSupport.h"
#include "RenderSession.h"

#include <atomic>
#include <cmath>
#include <filesystem>
#include <future>

namespace {

using namespace prism::nsi;

constexpr int kFrames = 8;

// A grey ball under a hidden white environment, 32x32, kFrames frames
// accumulated into the EXR `file`.
ResolvedScene ballScene(const std::string &file)
{
  ResolvedScene scene;
  GeometryData ball;
  ball.spheres = true;
  ball.positions = {0, 0, -5};
  ball.radii = {1.5f};
  scene.geometries["ball"] = ball;
  SurfaceItem surface;
  surface.geometryHandle = "ball";
  surface.worldFromObject = {Placement{kIdentity}};
  scene.surfaces.push_back(surface);
  LightItem sky;
  sky.kind = LightItem::Kind::Ambient;
  sky.shader.color = {1, 1, 1};
  sky.visibleToCamera = false;
  scene.lights.push_back(sky);
  CameraItem camera;
  camera.handle = "cam";
  camera.screen.width = camera.screen.height = 32;
  camera.oversampling = kFrames;
  OutputItem output;
  output.layerHandle = "beauty";
  output.variableName = "Ci";
  output.driverName = "exr";
  output.fileName = file;
  camera.outputs.push_back(output);
  scene.cameras.push_back(camera);
  return scene;
}

class Session : public NsiTest
{
 protected:
  ReportFunction recorder()
  {
    return [this](int level, const std::string &message) {
      if (level >= NSIErrWarning)
        m_problems += message + "\n";
    };
  }
  static prism::image::Image read(const std::string &file)
  {
    auto result = prism::image::read(file);
    EXPECT_TRUE(result.ok()) << file << ": " << result.error;
    return result.image;
  }
  static float largestDifference(
      const prism::image::Image &a, const prism::image::Image &b)
  {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    float largest = 0;
    for (size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
      largest = std::max({largest,
          std::abs(a.pixels[i].r - b.pixels[i].r),
          std::abs(a.pixels[i].g - b.pixels[i].g),
          std::abs(a.pixels[i].b - b.pixels[i].b)});
    return largest;
  }

  std::string m_problems; // written by the render thread until it is joined
};

TEST_F(Session, SuspendedProgressiveRenderWaitsForResume)
{
  const std::string file = path("progressive.exr");
  RenderSession session(recorder(), nullptr);
  // Suspended right after its first frame, on the render thread.
  session.setFrameDone([&session](uint64_t frames) {
    if (frames == 1)
      session.suspend();
  });
  // The render thread says when it stops at the suspension: from then on
  // no frame can start until resume(), so counting frames now proves that
  // none was issued while suspended (without sleeping and hoping).
  std::promise<uint64_t> parked;
  std::atomic<int> parkings{0};
  session.setParked([&](uint64_t frames) {
    if (parkings++ == 0)
      parked.set_value(frames);
  });
  ASSERT_TRUE(session.start("prism", ballScene(file), true));
  EXPECT_EQ(parked.get_future().get(), 1u);
  EXPECT_EQ(session.framesRendered(), 1u); // no frame while suspended
  EXPECT_TRUE(session.running());
  ASSERT_TRUE(std::filesystem::exists(file)); // the first frame's output
  const prism::image::Image firstFrame = read(file);

  session.resume();
  session.wait();
  EXPECT_EQ(session.framesRendered(), uint64_t(kFrames));
  EXPECT_EQ(m_problems, "");
  const prism::image::Image progressive = read(file);
  // Each frame's file was written beside it and renamed over it.
  EXPECT_FALSE(std::filesystem::exists(path("progressive.partial.exr")));

  // The last output is the full render, as a render written once gives it.
  const std::string onceFile = path("once.exr");
  RenderSession once(recorder(), nullptr);
  ASSERT_TRUE(once.start("prism", ballScene(onceFile)));
  once.wait();
  const prism::image::Image full = read(onceFile);
  EXPECT_LT(largestDifference(progressive, full), 1e-4f);
  EXPECT_GT(largestDifference(firstFrame, full), 1e-3f); // one frame is noisy
}

// wait() on a suspended render returns, saying so, instead of waiting for
// a resume; once resumed, it waits for the end as before.
TEST_F(Session, WaitReturnsOnASuspendedRender)
{
  RenderSession session(recorder(), nullptr);
  session.setFrameDone([&session](uint64_t frames) {
    if (frames == 1)
      session.suspend();
  });
  ASSERT_TRUE(session.start("prism", ballScene(path("waited.exr"))));
  EXPECT_EQ(session.wait(), RenderSession::Waited::kSuspended);
  EXPECT_EQ(session.framesRendered(), 1u);
  EXPECT_TRUE(session.running());
  session.resume();
  EXPECT_EQ(session.wait(), RenderSession::Waited::kEnded);
  EXPECT_EQ(session.framesRendered(), uint64_t(kFrames));
  EXPECT_FALSE(session.running());
}

// The render's own callbacks may wait and stop: neither joins the thread
// it runs on.
TEST_F(Session, CallbacksMayWaitAndStop)
{
  std::atomic<int> waitedOnRenderThread{0};
  RenderSession session(recorder(), nullptr);
  session.setFrameDone([&](uint64_t) {
    waitedOnRenderThread +=
        session.wait() == RenderSession::Waited::kOnRenderThread;
    session.stop();
  });
  ASSERT_TRUE(session.start("prism", ballScene(path("callback.exr"))));
  EXPECT_EQ(session.wait(), RenderSession::Waited::kEnded);
  EXPECT_EQ(waitedOnRenderThread, 1);
  EXPECT_EQ(session.framesRendered(), 1u); // stopped after the first frame
}

TEST_F(Session, StopEndsASuspendedRender)
{
  RenderSession session(recorder(), nullptr);
  session.setFrameDone([&session](uint64_t) { session.suspend(); });
  ASSERT_TRUE(session.start("prism", ballScene(path("stopped.exr"))));
  // Returns once the render is suspended after its first frame.
  ASSERT_EQ(session.wait(), RenderSession::Waited::kSuspended);
  session.stop();
  EXPECT_FALSE(session.running());
  EXPECT_EQ(session.framesRendered(), 1u);
  // Not progressive: the one frame is written when the render ends.
  EXPECT_TRUE(std::filesystem::exists(path("stopped.exr")));
}

} // namespace
