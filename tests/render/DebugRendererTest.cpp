// The debug renderer's modes: primitiveId, objectId, instanceId (with
// transform arrays and their id arrays), Ng, Ns (vertex and face-varying
// normals), uv, attribute0..3, color, backface and opacityHeatmap. Ids show
// as a fixed pseudo-random color per value (dark grey for "no id", ~0u);
// vectors v in [-1, 1] as (v + 1) / 2; attributes and uv unchanged.
#include "RenderTest.h"

#include <cmath>

namespace {

constexpr float kPi = 3.14159265f;

class DebugScene : public RenderTest
{
 protected:
  // The debug renderer in `mode`.
  ANARIRenderer debugRenderer(const char *mode)
  {
    ANARIRenderer renderer = newRenderer();
    setString(renderer, "mode", mode);
    anariCommitParameters(device(), renderer);
    return renderer;
  }
  ANARICamera flatCamera(float height, float aspect)
  {
    return newOrthographicCamera(
        {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, height, aspect);
  }
  // A square of two triangles centred at (x, y) with side 0.8 (lower left,
  // lower right, upper right, upper left; the lower right triangle first).
  ANARIGeometry square(float x, float y, float z = 0.f)
  {
    ANARIGeometry geometry = newGeometry("triangle");
    setArray(geometry,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{x - 0.4f, y - 0.4f, z},
            {x + 0.4f, y - 0.4f, z},
            {x + 0.4f, y + 0.4f, z},
            {x - 0.4f, y + 0.4f, z}});
    setArray(geometry,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    return geometry;
  }

  // Four squares, left to right, each showing one kind of attribute:
  //   attribute0 from vertex.attribute0 (FLOAT32 0 to 1, left to right);
  //   attribute1 from primitive.attribute1 (lower right triangle yellow,
  //     upper left cyan);
  //   attribute2 from faceVarying.attribute2 (FLOAT32_VEC2: lower right
  //     triangle (1, 0), upper left (0, 1) at every corner but (1, 1) at
  //     the shared upper right corner);
  //   attribute3 as the uniform (0.8, 0.2, 0.8, 1) of the instance around
  //     the fourth square, whose geometry sets no attribute3;
  // and vertex.color on all of them (blue at the bottom, white at the
  // top). Each mode shows its attribute where set and the default
  // (0, 0, 0) elsewhere.
  ANARIWorld attributeWorld()
  {
    ANARIMaterial material = newMatte({0.8f, 0.8f, 0.8f});
    std::vector<ANARISurface> surfaces;
    std::vector<ANARIGeometry> squares;
    for (int i = 0; i < 4; i++) {
      ANARIGeometry g = square(-1.5f + float(i), 0);
      setArray(g,
          "vertex.color",
          ANARI_FLOAT32_VEC3,
          std::vector<Vec3>{{0.1f, 0.2f, 0.9f},
              {0.1f, 0.2f, 0.9f},
              {0.9f, 0.9f, 0.9f},
              {0.9f, 0.9f, 0.9f}});
      squares.push_back(g);
    }
    setArray(squares[0],
        "vertex.attribute0",
        ANARI_FLOAT32,
        std::vector<float>{0, 1, 1, 0});
    setArray(squares[1],
        "primitive.attribute1",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0.9f, 0.8f, 0.1f}, {0.1f, 0.8f, 0.8f}});
    setArray(squares[2],
        "faceVarying.attribute2",
        ANARI_FLOAT32_VEC2,
        std::vector<float>{1, 0, 1, 0, 1, 1, 0, 1, 1, 1, 0, 1});
    for (int i = 0; i < 3; i++)
      surfaces.push_back(newSurface(squares[i], material));
    ANARIInstance instance =
        newInstance(newGroup({newSurface(squares[3], material)}));
    setVec4(instance, "attribute3", {0.8f, 0.2f, 0.8f, 1});
    anariCommitParameters(device(), instance);
    return newWorld(surfaces, {instance});
  }
  void renderAttributeWorld(const char *mode)
  {
    renderAndCompare(
        attributeWorld(), flatCamera(1.f, 4.f), debugRenderer(mode), 128, 32);
  }
};

// Three squares of two triangles each (primitives 1 to 6 of one geometry,
// each square's lower right triangle first) above two spheres (primitives
// 1 and 2 of another): every primitive its
// own color, and each sphere the color of the triangle with the same
// index (ids count per geometry): the middle sphere matches the left
// square's lower right triangle, the right sphere its upper left one.
// Primitive 0 of each geometry (a triangle of no area, a sphere
// out of view) stays hidden: see DebugIdZero.
using DebugPrimitiveId = DebugScene;
TEST_F(DebugPrimitiveId, Debug)
{
  std::vector<Vec3> positions(3, Vec3{0, 0, 0});
  for (int i = 0; i < 3; i++) {
    const float x0 = -1.45f + float(i), x1 = x0 + 0.9f;
    positions.insert(positions.end(),
        {{x0, 0.05f, 0},
            {x1, 0.05f, 0},
            {x1, 0.95f, 0},
            {x0, 0.05f, 0},
            {x1, 0.95f, 0},
            {x0, 0.95f, 0}});
  }
  ANARIGeometry triangles = newGeometry("triangle");
  setArray(triangles, "vertex.position", ANARI_FLOAT32_VEC3, positions);
  ANARIGeometry spheres = newGeometry("sphere");
  setArray(spheres,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{0, 10, 0}, {0, -0.5f, 0}, {1, -0.5f, 0}});
  setFloat(spheres, "radius", 0.4f);
  ANARIMaterial material = newMatte({0.8f, 0.8f, 0.8f});
  renderAndCompare(newWorld({newSurface(triangles, material),
                       newSurface(spheres, material)}),
      flatCamera(2.f, 1.5f),
      debugRenderer("primitiveId"),
      96,
      64);
}

// Four squares whose surfaces have the ids 1, 2 and 7 and, at the right,
// none (dark grey); the two triangles of a square share its color.
using DebugObjectId = DebugScene;
TEST_F(DebugObjectId, Debug)
{
  ANARIMaterial material = newMatte({0.8f, 0.8f, 0.8f});
  const uint32_t ids[4] = {1, 2, 7, ~0u};
  std::vector<ANARISurface> surfaces;
  for (int i = 0; i < 4; i++)
    surfaces.push_back(
        newSurface(square(-1.5f + float(i), 0), material, ids[i]));
  renderAndCompare(newWorld(surfaces),
      flatCamera(1.f, 4.f),
      debugRenderer("objectId"),
      128,
      32);
}

// One square instanced eight times; top row left to right: an instance
// with id 3, then one instance with three transforms and the id array
// {10, 11, 12} (three colors); bottom row: an instance with two transforms
// and the single id 5 (two squares of one color), a plain instance without
// id (dark grey), and a square placed directly in the world (dark grey).
using DebugInstanceId = DebugScene;
TEST_F(DebugInstanceId, Debug)
{
  ANARIMaterial material = newMatte({0.8f, 0.8f, 0.8f});
  ANARIGroup group = newGroup({newSurface(square(0, 0), material)});
  ANARIInstance single = newInstance(group);
  setMat4(single, "transform", translation({-1.5f, 0.5f, 0}));
  setUint32(single, "id", 3);
  anariCommitParameters(device(), single);
  ANARIInstance many = newInstance(group);
  setArray(many,
      "transform",
      ANARI_FLOAT32_MAT4,
      std::vector<Mat4>{translation({-0.5f, 0.5f, 0}),
          translation({0.5f, 0.5f, 0}),
          translation({1.5f, 0.5f, 0})});
  setArray(many, "id", ANARI_UINT32, std::vector<uint32_t>{10, 11, 12});
  anariCommitParameters(device(), many);
  ANARIInstance pair = newInstance(group);
  setArray(pair,
      "transform",
      ANARI_FLOAT32_MAT4,
      std::vector<Mat4>{
          translation({-1.5f, -0.5f, 0}), translation({-0.5f, -0.5f, 0})});
  setUint32(pair, "id", 5);
  anariCommitParameters(device(), pair);
  ANARIInstance plain = newInstance(group);
  setMat4(plain, "transform", translation({0.5f, -0.5f, 0}));
  anariCommitParameters(device(), plain);
  renderAndCompare(newWorld({newSurface(square(1.5f, -0.5f), material)},
                       {single, many, pair, plain}),
      flatCamera(2.f, 2.f),
      debugRenderer("instanceId"),
      128,
      64);
}

// Id 0 in each id mode, over a grey background: a square whose surface id
// is 0 (objectId), one whose instance id is 0 (instanceId) and the first
// triangle of a geometry (primitiveId), each shown as
// primitiveId / objectId / instanceId in a row. Every id is a value like
// any other and needs a color unlike "nothing hit".
using DebugIdZero = DebugScene;
TEST_F(DebugIdZero, Debug)
{
  ANARIMaterial material = newMatte({0.8f, 0.8f, 0.8f});
  ANARIInstance instance =
      newInstance(newGroup({newSurface(square(0, 0), material, 0)}));
  setUint32(instance, "id", 0);
  anariCommitParameters(device(), instance);
  const char *modes[3] = {"primitiveId", "objectId", "instanceId"};
  for (const char *mode : modes) {
    ANARIRenderer renderer = debugRenderer(mode);
    setVec4(renderer, "background", {0.3f, 0.3f, 0.3f, 1});
    anariCommitParameters(device(), renderer);
    renderAndCompare(newWorld({}, {instance}),
        flatCamera(1.f, 1.f),
        renderer,
        32,
        32,
        std::string("DebugIdZero.Debug.") + mode);
  }
}

// Four shapes, left to right: a square with vertex.normal tilted left at
// its left edge and right at its right edge; a square with
// faceVarying.normal tilted down on its lower right triangle and up on its
// upper left one; a sphere; and a square turned 60 degrees about the
// vertical axis by its instance.
class NormalScene : public DebugScene
{
 protected:
  ANARIWorld normalWorld()
  {
    ANARIMaterial material = newMatte({0.8f, 0.8f, 0.8f});
    const float s = std::sqrt(0.5f);
    ANARIGeometry smooth = square(-1.5f, 0);
    setArray(smooth,
        "vertex.normal",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-s, 0, s}, {s, 0, s}, {s, 0, s}, {-s, 0, s}});
    ANARIGeometry faceted = square(-0.5f, 0);
    setArray(faceted,
        "faceVarying.normal",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0, -s, s},
            {0, -s, s},
            {0, -s, s},
            {0, s, s},
            {0, s, s},
            {0, s, s}});
    ANARIGeometry sphere = newGeometry("sphere");
    setArray(sphere,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0.5f, 0, 0}});
    setFloat(sphere, "radius", 0.45f);
    ANARIInstance turned =
        newInstance(newGroup({newSurface(square(0, 0), material)}));
    const float c = std::cos(kPi / 3.f), n = std::sin(kPi / 3.f);
    // A rotation about +y (column-major), then a move to x = 1.5.
    setMat4(turned,
        "transform",
        translation({1.5f, 0, 0})
            * Mat4{c, 0, -n, 0, 0, 1, 0, 0, n, 0, c, 0, 0, 0, 0, 1});
    anariCommitParameters(device(), turned);
    return newWorld({newSurface(smooth, material),
                        newSurface(faceted, material),
                        newSurface(sphere, material)},
        {turned});
  }
};

// Ng: the geometric normal facing the camera. Both flat squares are one
// lavender (0.5, 0.5, 1) whatever their shading normals; the sphere runs
// through every direction towards the camera; the turned square, whose
// normal the rotation leans to +x as (sin 60, 0, cos 60), is one flat
// (0.93, 0.5, 0.75).
using DebugNg = NormalScene;
TEST_F(DebugNg, Debug)
{
  renderAndCompare(
      normalWorld(), flatCamera(1.f, 4.f), debugRenderer("Ng"), 128, 32);
}

// Ns: the shading normal. The first square ramps from (0.15, 0.5, 0.85) at
// its left edge to (0.85, 0.5, 0.85) at its right (vertex normals,
// interpolated); the second is split along its diagonal, the lower right
// triangle (0.5, 0.15, 0.85), the upper left (0.5, 0.85, 0.85)
// (face-varying normals); the sphere and the turned square match Ng.
using DebugNs = NormalScene;
TEST_F(DebugNs, Debug)
{
  renderAndCompare(
      normalWorld(), flatCamera(1.f, 4.f), debugRenderer("Ns"), 128, 32);
}

// uv: the hit's surface parameters as (u, v, 0). Left, one triangle with
// vertex 0 at the lower left (black), 1 at the lower right (red), 2 at the
// top (green). Right, one quad with vertices 0 to 3 from the lower left
// counterclockwise: black, red, yellow (1, 1) at the upper right, green at
// the upper left.
using DebugUv = DebugScene;
TEST_F(DebugUv, Debug)
{
  ANARIGeometry triangle = newGeometry("triangle");
  setArray(triangle,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {-0.9f, -0.4f, 0}, {-0.1f, -0.4f, 0}, {-0.5f, 0.4f, 0}});
  ANARIGeometry quad = newGeometry("quad");
  setArray(quad,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{0.1f, -0.4f, 0},
          {0.9f, -0.4f, 0},
          {0.9f, 0.4f, 0},
          {0.1f, 0.4f, 0}});
  ANARIMaterial material = newMatte({0.8f, 0.8f, 0.8f});
  // Off centre by 0.01 so no pixel centre lies exactly on the quad's
  // inner diagonal (see QuadWatertight in GeometryTest.cpp).
  renderAndCompare(
      newWorld({newSurface(triangle, material), newSurface(quad, material)}),
      newOrthographicCamera({0.01f, 0.01f, 5}, {0, 0, -1}, {0, 1, 0}, 1.f, 2.f),
      debugRenderer("uv"),
      64,
      32);
}

// attribute0: a black-to-red ramp on the first square, black elsewhere.
using DebugAttribute0 = DebugScene;
TEST_F(DebugAttribute0, Debug)
{
  renderAttributeWorld("attribute0");
}

// attribute1: the second square's lower right triangle yellow, upper left
// cyan; black elsewhere.
using DebugAttribute1 = DebugScene;
TEST_F(DebugAttribute1, Debug)
{
  renderAttributeWorld("attribute1");
}

// attribute2: the third square's lower right triangle red fading to yellow
// at the upper right corner, its upper left triangle green fading to
// yellow there; black elsewhere.
using DebugAttribute2 = DebugScene;
TEST_F(DebugAttribute2, Debug)
{
  renderAttributeWorld("attribute2");
}

// attribute3: the fourth square magenta (from its instance); black
// elsewhere.
using DebugAttribute3 = DebugScene;
TEST_F(DebugAttribute3, Debug)
{
  renderAttributeWorld("attribute3");
}

// color: all four squares blue at the bottom to white at the top.
using DebugColor = DebugScene;
TEST_F(DebugColor, Debug)
{
  renderAttributeWorld("color");
}

// backface: green where the camera sees a surface's front, red where it
// sees the back. Left, a triangle counterclockwise as seen (front, green);
// next, the same triangle clockwise (back, red); a sphere (front); an
// uncapped cylinder seen from above the front along its axis: its outside
// green, the inside seen through the open end red.
using DebugBackface = DebugScene;
TEST_F(DebugBackface, Debug)
{
  ANARIGeometry front = newGeometry("triangle");
  setArray(front,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {-1.9f, -0.4f, 0}, {-1.1f, -0.4f, 0}, {-1.5f, 0.4f, 0}});
  ANARIGeometry back = newGeometry("triangle");
  setArray(back,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {-0.9f, -0.4f, 0}, {-0.5f, 0.4f, 0}, {-0.1f, -0.4f, 0}});
  ANARIGeometry sphere = newGeometry("sphere");
  setArray(sphere,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{0.5f, 0, 0}});
  setFloat(sphere, "radius", 0.4f);
  ANARIGeometry tube = newGeometry("cylinder");
  setArray(tube,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{1.5f, 0, -0.4f}, {1.5f, 0, 0.4f}});
  setFloat(tube, "radius", 0.3f);
  ANARIMaterial material = newMatte({0.8f, 0.8f, 0.8f});
  renderAndCompare(newWorld({newSurface(front, material),
                       newSurface(back, material),
                       newSurface(sphere, material),
                       newSurface(tube, material)}),
      newOrthographicCamera({0, 2.f, 5}, {0, -0.4f, -1}, {0, 1, 0}, 1.f, 4.f),
      debugRenderer("backface"),
      128,
      32);
}

// opacityHeatmap: how many see-through (blend, opacity 0.5) layers a ray
// passes before an opaque surface or the background, as heat(n / 8) =
// (t, 1 - |2t - 1|, 1 - t). Three overlapping see-through squares stepping
// down to the right over an opaque backdrop on the right half: from 0
// layers (pure blue over the backdrop, background black beside it) up to
// 3 where all squares overlap (t = 0.375).
using DebugOpacityHeatmap = DebugScene;
TEST_F(DebugOpacityHeatmap, Debug)
{
  ANARIMaterial seeThrough = keep(anariNewMaterial(device(), "matte"));
  setFloat(seeThrough, "opacity", 0.5f);
  setString(seeThrough, "alphaMode", "blend");
  anariCommitParameters(device(), seeThrough);
  std::vector<ANARISurface> surfaces;
  for (int i = 0; i < 3; i++) {
    ANARIGeometry g = newGeometry("triangle");
    const float x0 = -0.8f + 0.3f * float(i), y1 = 0.8f - 0.3f * float(i);
    setArray(g,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{x0, y1 - 1.f, 0.1f * float(i)},
            {x0 + 1.f, y1 - 1.f, 0.1f * float(i)},
            {x0 + 1.f, y1, 0.1f * float(i)},
            {x0, y1, 0.1f * float(i)}});
    setArray(g,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    surfaces.push_back(newSurface(g, seeThrough));
  }
  ANARIGeometry backdrop = newGeometry("triangle");
  setArray(backdrop,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{0, -1, -1}, {1, -1, -1}, {1, 1, -1}, {0, 1, -1}});
  setArray(backdrop,
      "primitive.index",
      ANARI_UINT32_VEC3,
      std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
  surfaces.push_back(newSurface(backdrop, newMatte({0.8f, 0.8f, 0.8f})));
  renderAndCompare(newWorld(surfaces),
      flatCamera(2.f, 1.f),
      debugRenderer("opacityHeatmap"),
      64,
      64);
}

} // namespace
