// Editing a world in place: moving one instance keeps the other instances'
// Embree geometry and every group's BVH (World::moveInstancesInPlace), and
// the picture must be the one a world built afresh with the new
// transforms draws; an edit to a group after that rebuilds as before.
#include "RenderTest.h"

namespace {

const Vec3 kOrange{0.9f, 0.5f, 0.1f};

class WorldEdits : public RenderTest
{
 protected:
  // A unit square of two triangles at the origin, as a committed group.
  ANARIGroup square(float size, ANARIGeometry *geometryOut = nullptr)
  {
    ANARIGeometry g = newGeometry("triangle");
    setArray(g,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{
            {0, 0, 0}, {size, 0, 0}, {size, size, 0}, {0, size, 0}});
    setArray(g,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    if (geometryOut)
      *geometryOut = g;
    return newGroup({newSurface(g, newMatte(kOrange))});
  }
  ANARIInstance placed(ANARIGroup group, const Vec3 &offset)
  {
    ANARIInstance instance = newInstance(group);
    setMat4(instance, "transform", translation(offset));
    anariCommitParameters(device(), instance);
    return instance;
  }
  // One camera and renderer for every picture (the edits are the world's).
  prism::image::Image draw(ANARIWorld world)
  {
    if (!m_camera) {
      m_camera =
          newOrthographicCamera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 3.f, 1.f);
      m_renderer = newRenderer("raycast");
    }
    return render(world, m_camera, m_renderer, 48, 48);
  }
  ANARICamera m_camera{nullptr};
  ANARIRenderer m_renderer{nullptr};
};

TEST_F(WorldEdits, MovingOneInstanceDrawsWhatAFreshWorldDraws)
{
  ANARIGeometry geometry = nullptr;
  ANARIGroup group = square(0.5f, &geometry);
  const std::vector<Vec3> offsets = {{-1.2f, -1.2f, 0}, {0.2f, 0.2f, 0}};
  ANARIInstance first = placed(group, offsets[0]);
  ANARIWorld world = newWorld({}, {first, placed(group, offsets[1])});
  const prism::image::Image before = draw(world);

  // The first square moves to the upper left; the world is not touched.
  const Vec3 moved{-1.2f, 0.6f, 0};
  setMat4(first, "transform", translation(moved));
  anariCommitParameters(device(), first);
  const prism::image::Image after = draw(world);
  expectSameImage(after,
      draw(newWorld({}, {placed(group, moved), placed(group, offsets[1])})),
      "moved in place vs built afresh");
  EXPECT_GT(after.at(8, 36).r, 0.1f); // the square's new place
  EXPECT_LT(after.at(8, 8).r, 0.05f); // and its old one, empty now
  EXPECT_GT(before.at(8, 8).r, 0.1f);

  // The group's geometry grows: every instance shows it (a rebuild).
  setArray(geometry,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {0, 0, 0}, {0.8f, 0, 0}, {0.8f, 0.8f, 0}, {0, 0.8f, 0}});
  anariCommitParameters(device(), geometry);
  const prism::image::Image grown = draw(world);
  expectSameImage(grown,
      draw(newWorld(
          {}, {placed(square(0.8f), moved), placed(square(0.8f), offsets[1])})),
      "grown group vs built afresh");
}

} // namespace
