// Editing a world in place: moving one instance keeps the other instances'
// Embree geometry and every group's BVH (World::moveInstancesInPlace), and
// the picture must be the one a world built afresh with the new
// transforms draws; an edit to a group after that rebuilds as before, and
// so does an instance given another group or one that stops moving.
#include "RenderTest.h"

namespace {

const Vec3 kOrange{0.9f, 0.5f, 0.1f};

class WorldEdits : public RenderTest
{
 protected:
  // A square of two triangles at the origin, as a committed group.
  ANARIGroup square(float size,
      ANARIGeometry *geometryOut = nullptr,
      const Vec3 &color = kOrange)
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
    return newGroup({newSurface(g, newMatte(color))});
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

// Two instances trade groups and one moves: the placements are the same
// instances' in the same order, so only the groups' scenes tell the edit
// apart from a move.
TEST_F(WorldEdits, InstancesTradingGroupsDrawWhatAFreshWorldDraws)
{
  const Vec3 blue{0.1f, 0.3f, 0.9f};
  ANARIGroup small = square(0.5f);
  ANARIGroup large = square(0.9f, nullptr, blue);
  const Vec3 left{-1.2f, -0.4f, 0}, right{0.2f, -0.4f, 0};
  ANARIInstance first = placed(small, left);
  ANARIInstance second = placed(large, right);
  ANARIWorld world = newWorld({}, {first, second});
  draw(world);

  setObject(first, "group", ANARI_GROUP, large);
  setMat4(first, "transform", translation({-1.2f, -0.2f, 0}));
  anariCommitParameters(device(), first);
  setObject(second, "group", ANARI_GROUP, small);
  anariCommitParameters(device(), second);
  const prism::image::Image traded = draw(world);
  expectSameImage(traded,
      draw(newWorld(
          {}, {placed(large, {-1.2f, -0.2f, 0}), placed(small, right)})),
      "traded in place vs built afresh");
  EXPECT_GT(traded.at(12, 28).b, 0.5f); // the large blue square, left
  EXPECT_GT(traded.at(31, 21).r, 0.5f); // the small orange one, right
}

// A moving instance whose keys are unset stands still where its transform
// puts it: Embree's instance had time steps, so it is built anew.
TEST_F(WorldEdits, AnInstanceThatStopsMovingDrawsWhatAFreshWorldDraws)
{
  ANARIGroup group = square(0.5f);
  ANARIInstance moving = keep(anariNewInstance(device(), "motionTransform"));
  setObject(moving, "group", ANARI_GROUP, group);
  setArray(moving,
      "motion.transform",
      ANARI_FLOAT32_MAT4,
      std::vector<Mat4>{
          translation({-1.2f, -1.2f, 0}), translation({0.6f, -1.2f, 0})});
  anariCommitParameters(device(), moving);
  ANARIWorld world = newWorld({}, {moving, placed(group, {0.2f, 0.4f, 0})});
  draw(world);

  const Vec3 still{-1.2f, 0.6f, 0};
  anariUnsetParameter(device(), moving, "motion.transform");
  setMat4(moving, "transform", translation(still));
  anariCommitParameters(device(), moving);
  const prism::image::Image after = draw(world);
  expectSameImage(after,
      draw(
          newWorld({}, {placed(group, still), placed(group, {0.2f, 0.4f, 0})})),
      "stopped in place vs built afresh");
  EXPECT_GT(after.at(8, 36).r, 0.1f);
  EXPECT_LT(after.at(8, 8).r, 0.05f);
}

// A move that flattens an instance to 1e-17 of its width lowers the range
// rays are traced in (its inverse scales x by 1e17) to 18, short of a
// camera 50 away. The world must draw what a fresh world draws (nothing: the
// rays start beyond the range), not trace the old range through the new
// transform; moved back, the range rises again and the squares return.
TEST_F(WorldEdits, AMoveThatShrinksTheRayRangeDrawsWhatAFreshWorldDraws)
{
  ANARIGroup group = square(0.5f);
  ANARIInstance shrinking = placed(group, {-1.2f, -1.2f, 0});
  ANARIWorld world = newWorld({}, {shrinking, placed(group, {0.2f, 0.2f, 0})});
  draw(world); // the renderer
  ANARICamera far =
      newOrthographicCamera({0, 0, 50}, {0, 0, -1}, {0, 1, 0}, 3.f, 1.f);
  auto drawFromFar = [&](ANARIWorld w) {
    return render(w, far, m_renderer, 48, 48);
  };
  const prism::image::Image before = drawFromFar(world);
  EXPECT_GT(before.at(31, 31).r, 0.1f);

  const Mat4 flat = scaling({1e-17f, 1, 1});
  setMat4(shrinking, "transform", flat);
  anariCommitParameters(device(), shrinking);
  ANARIInstance fresh = newInstance(group);
  setMat4(fresh, "transform", flat);
  anariCommitParameters(device(), fresh);
  const prism::image::Image freshImage =
      drawFromFar(newWorld({}, {fresh, placed(group, {0.2f, 0.2f, 0})}));
  EXPECT_LT(freshImage.at(31, 31).r, 0.05f); // beyond the range
  expectSameImage(
      drawFromFar(world), freshImage, "shrunk in place vs built afresh");

  setMat4(shrinking, "transform", translation({-1.2f, -1.2f, 0}));
  anariCommitParameters(device(), shrinking);
  expectSameImage(drawFromFar(world), before, "moved back vs before");
}

} // namespace
