// Image tests: a scene built through the public C API on the prism device
// (loaded by libanari), rendered small and compared with the committed
// reference references/<Scene>.<Renderer>.png under the tolerance that
// tolerances.txt gives it. See README.md.
#pragma once

#include "ImageIO.h"
#include "StatusRecorder.h"

#include <anari/anari.h>
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

using Vec2 = std::array<float, 2>;
using Vec3 = std::array<float, 3>;
using Vec4 = std::array<float, 4>;
using Mat4 = std::array<float, 16>;

// Column-major affine transforms for instances and samplers.
Mat4 translation(const Vec3 &offset);
Mat4 scaling(const Vec3 &factors);
// Rotation by `radians` about the z axis (counterclockwise seen from +z).
Mat4 rotationZ(float radians);
// a * b: b is applied first.
Mat4 operator*(const Mat4 &a, const Mat4 &b);

// The width x height block of `image` whose lower left pixel is (x, y).
prism::image::Image crop(const prism::image::Image &image,
    uint32_t x,
    uint32_t y,
    uint32_t width,
    uint32_t height);
// `image` mirrored left to right.
prism::image::Image mirrorHorizontally(const prism::image::Image &image);

// The fixture of every render test: TEST_F(<Scene>, <Renderer>) with
// `using <Scene> = RenderTest;`, so ctest names it render::<Scene>.<Renderer>.
class RenderTest : public ::testing::Test
{
 protected:
  void SetUp() override;
  // Releases the objects the fixture owns and fails on device problems.
  void TearDown() override;

  ANARIDevice device() const
  {
    return m_device;
  }

  // New objects, owned by the fixture and released in TearDown.
  ANARIWorld newWorld();
  // `subtype` empty: the renderer the test is named for ("PathTracer" ->
  // "pathTracer").
  ANARIRenderer newRenderer(const std::string &subtype = {});
  // A committed perspective camera; positions in world space, fovy in radians.
  ANARICamera newPerspectiveCamera(const std::array<float, 3> &position,
      const std::array<float, 3> &direction,
      const std::array<float, 3> &up,
      float aspect,
      float fovy = 3.14159265f / 3.f);
  // Managed arrays holding a copy of `data` (elements of `type`).
  ANARIArray1D newArray1D(ANARIDataType type, const void *data, uint64_t count);
  ANARIArray2D newArray2D(
      ANARIDataType type, const void *data, uint64_t width, uint64_t height);
  ANARIArray3D newArray3D(ANARIDataType type,
      const void *data,
      uint64_t width,
      uint64_t height,
      uint64_t depth);
  // A managed array of `values` read as elements of `type` (a vector of
  // floats becomes FLOAT32_VEC3 elements three at a time).
  template <typename T>
  ANARIArray1D newArray1D(ANARIDataType type, const std::vector<T> &values)
  {
    return newArray1D(
        type, values.data(), values.size() * sizeof(T) / elementSize(type));
  }
  // Hands any object to the fixture, to be released in TearDown.
  template <typename T>
  T keep(T object)
  {
    m_objects.push_back(object);
    return object;
  }

  // Scene building: uncommitted objects unless a comment says otherwise.
  ANARIGeometry newGeometry(const char *subtype);
  ANARISampler newSampler(const char *subtype);
  // A committed matte material with a constant color.
  ANARIMaterial newMatte(const Vec3 &color);
  // A committed matte material whose color is the surface attribute named.
  ANARIMaterial newMatte(const char *colorAttribute);
  // A committed surface; commits `geometry` first. `id` ~0u: not set.
  ANARISurface newSurface(
      ANARIGeometry geometry, ANARIMaterial material, uint32_t id = ~0u);
  // A committed group of surfaces.
  ANARIGroup newGroup(const std::vector<ANARISurface> &surfaces);
  // An uncommitted instance ("transform") of `group`.
  ANARIInstance newInstance(ANARIGroup group);
  // A committed world holding surfaces and instances directly.
  ANARIWorld newWorld(const std::vector<ANARISurface> &surfaces,
      const std::vector<ANARIInstance> &instances = {});
  // A committed orthographic camera; `height` of the view in world units.
  ANARICamera newOrthographicCamera(const Vec3 &position,
      const Vec3 &direction,
      const Vec3 &up,
      float height,
      float aspect);

  // Parameter setters (the device copies the value).
  void setFloat(ANARIObject object, const char *name, float value);
  void setUint32(ANARIObject object, const char *name, uint32_t value);
  void setVec2(ANARIObject object, const char *name, const Vec2 &value);
  void setVec3(ANARIObject object, const char *name, const Vec3 &value);
  void setVec4(ANARIObject object, const char *name, const Vec4 &value);
  // Column-major, as ANARI stores FLOAT32_MAT4.
  void setMat4(ANARIObject object, const char *name, const Mat4 &value);
  void setString(ANARIObject object, const char *name, const char *value);
  void setObject(ANARIObject object,
      const char *name,
      ANARIDataType type,
      ANARIObject value);
  // Sets `name` to a new managed array of `values` read as `type` elements.
  template <typename T>
  void setArray(ANARIObject object,
      const char *name,
      ANARIDataType type,
      const std::vector<T> &values)
  {
    setObject(object, name, ANARI_ARRAY1D, newArray1D(type, values));
  }

  // One frame's channel.color as linear float RGBA, row 0 at the bottom;
  // empty (after a test failure) when the device does not deliver it.
  // More than one accumulated frame renders that many samples per pixel
  // (KHR_FRAME_ACCUMULATION) and returns their mean.
  prism::image::Image render(ANARIWorld world,
      ANARICamera camera,
      ANARIRenderer renderer,
      uint32_t width,
      uint32_t height,
      uint32_t accumulatedFrames = 1);

  // Fails the test unless `a` and `b`, quantized like references, agree
  // within the default tolerance; `what` names the pair in the message.
  void expectSameImage(const prism::image::Image &a,
      const prism::image::Image &b,
      const std::string &what);

  // Renders (width, height <= 256) and compares with the reference `name`
  // (empty: "<Scene>.<Renderer>" of this test); every mismatch, missing
  // reference or device warning is a test failure. With
  // PRISM_UPDATE_REFERENCES=1 it rewrites the reference instead.
  bool renderAndCompare(ANARIWorld world,
      ANARICamera camera,
      ANARIRenderer renderer,
      uint32_t width,
      uint32_t height,
      const std::string &name = {},
      uint32_t accumulatedFrames = 1);

 private:
  // Fails the test for each message of warning severity or worse so far.
  void expectNoDeviceProblems(const char *when);
  static uint64_t elementSize(ANARIDataType type);

  StatusRecorder m_status;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  std::vector<ANARIObject> m_objects;
};
