// Geometry subtypes (spec 5.9) as soups and indexed, their radii and caps,
// and instance transforms including transform arrays (spec 5.5.1). Surfaces
// use a matte material whose color is the "color" attribute, so per-vertex
// and per-primitive colors tell primitives and their ends apart.
#include "RenderTest.h"

#include <cmath>

namespace {

constexpr float kPi = 3.14159265f;

const Vec3 kRed{0.9f, 0.1f, 0.1f};
const Vec3 kGreen{0.1f, 0.8f, 0.1f};
const Vec3 kBlue{0.1f, 0.2f, 0.9f};
const Vec3 kYellow{0.9f, 0.8f, 0.1f};
const Vec3 kWhite{0.9f, 0.9f, 0.9f};

class GeometryScene : public RenderTest
{
 protected:
  // One surface of `geometry` colored by its "color" attribute.
  ANARIWorld worldOf(ANARIGeometry geometry)
  {
    return newWorld({newSurface(geometry, newMatte("color"))});
  }
  // Looks straight down -z at the plane z = 0, `height` world units high.
  ANARICamera flatCamera(float height, float aspect)
  {
    return newOrthographicCamera(
        {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, height, aspect);
  }
  // A perspective view of the origin from `eye`.
  ANARICamera viewOfOrigin(const Vec3 &eye, float aspect)
  {
    return newPerspectiveCamera(eye,
        {-eye[0], -eye[1], -eye[2]},
        {0, 1, 0},
        aspect,
        40.f * kPi / 180.f);
  }

  // Eight cones or cylinders in a 4 x 2 grid, columns from left to right
  // capped none, first, second, both. Every axis points along z; in the
  // top row vertex 0 (red) is nearer the camera, in the bottom row vertex 1
  // (blue). With `perVertexCaps` one geometry gets the same caps from
  // vertex.cap (overriding caps "both"); otherwise each column is its own
  // geometry with `caps` set.
  ANARIWorld capsWorld(const char *subtype, bool perVertexCaps)
  {
    const char *modes[4] = {"none", "first", "second", "both"};
    const uint8_t capOf[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    std::vector<ANARISurface> surfaces;
    std::vector<float> allRadii;
    std::vector<Vec3> allPositions, allColors;
    std::vector<uint8_t> allCaps;
    const bool cone = std::string(subtype) == "cone";
    for (int column = 0; column < 4; column++) {
      const float x = -2.25f + 1.5f * float(column);
      const std::vector<Vec3> positions = {{x, 0.75f, 0.4f}, // top row
          {x, 0.75f, -0.4f},
          {x, -0.75f, -0.4f}, // bottom row
          {x, -0.75f, 0.4f}};
      const std::vector<Vec3> colors = {kRed, kBlue, kRed, kBlue};
      const std::vector<float> radii = {0.45f, 0.25f, 0.45f, 0.25f};
      if (perVertexCaps) {
        allPositions.insert(
            allPositions.end(), positions.begin(), positions.end());
        allColors.insert(allColors.end(), colors.begin(), colors.end());
        allRadii.insert(allRadii.end(), radii.begin(), radii.end());
        for (int i = 0; i < 4; i++)
          allCaps.push_back(capOf[column][i % 2]);
        continue;
      }
      ANARIGeometry geometry = newGeometry(subtype);
      setArray(geometry, "vertex.position", ANARI_FLOAT32_VEC3, positions);
      setArray(geometry, "vertex.color", ANARI_FLOAT32_VEC3, colors);
      if (cone)
        setArray(geometry, "vertex.radius", ANARI_FLOAT32, radii);
      else
        setFloat(geometry, "radius", 0.4f);
      setString(geometry, "caps", modes[column]);
      surfaces.push_back(newSurface(geometry, newMatte("color")));
    }
    if (perVertexCaps) {
      ANARIGeometry geometry = newGeometry(subtype);
      setArray(geometry, "vertex.position", ANARI_FLOAT32_VEC3, allPositions);
      setArray(geometry, "vertex.color", ANARI_FLOAT32_VEC3, allColors);
      setArray(geometry, "vertex.cap", ANARI_UINT8, allCaps);
      if (cone)
        setArray(geometry, "vertex.radius", ANARI_FLOAT32, allRadii);
      else
        setFloat(geometry, "radius", 0.4f);
      setString(geometry, "caps", "both");
      surfaces.push_back(newSurface(geometry, newMatte("color")));
    }
    return newWorld(surfaces);
  }
  // Looks down at the caps grid from the front, a little from above.
  ANARICamera capsCamera()
  {
    return newOrthographicCamera(
        {0, 1.75f, 5}, {0, -0.35f, -1}, {0, 1, 0}, 3.4f, 2.f);
  }

  // An "L" in the plane z = 0 of two quads: a red upright bar (x in
  // [0, 0.2], y in [0, 1]) and a blue foot to its right (x up to 0.6).
  ANARIGroup letterL()
  {
    ANARIGeometry geometry = newGeometry("quad");
    setArray(geometry,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0, 0, 0},
            {0.2f, 0, 0},
            {0.2f, 1, 0},
            {0, 1, 0},
            {0.2f, 0, 0},
            {0.6f, 0, 0},
            {0.6f, 0.2f, 0},
            {0.2f, 0.2f, 0}});
    setArray(geometry,
        "primitive.color",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{kRed, kBlue});
    return newGroup({newSurface(geometry, newMatte("color"))});
  }
  // Where the transform tests place the "L": as is, turned a quarter
  // counterclockwise, stretched twice as wide, and turned half round.
  std::vector<Mat4> letterPlacements()
  {
    return {translation({-2.1f, -0.5f, 0}),
        translation({-0.3f, -0.5f, 0}) * rotationZ(kPi / 2.f),
        translation({0.1f, -0.5f, 0}) * scaling({2, 1, 1}),
        translation({2.2f, 0.6f, 0}) * rotationZ(kPi)};
  }
};

// Three triangles from nine vertices (a tenth, left over, is ignored):
// red pointing up, green pointing down, blue with its right angle at the
// lower right.
using TriangleSoup = GeometryScene;
TEST_F(TriangleSoup, Raycast)
{
  ANARIGeometry triangles = newGeometry("triangle");
  setArray(triangles,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-1.4f, -0.9f, 0},
          {-0.5f, -0.9f, 0},
          {-0.95f, 0.9f, 0},
          {-0.45f, 0.9f, 0},
          {0, -0.9f, 0},
          {0.45f, 0.9f, 0},
          {0.5f, -0.9f, 0},
          {1.4f, -0.9f, 0},
          {1.4f, 0.9f, 0},
          {-1.4f, 0.9f, 0}});
  setArray(triangles,
      "primitive.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kGreen, kBlue});
  renderAndCompare(
      worldOf(triangles), flatCamera(2.f, 1.5f), newRenderer(), 96, 64);
}

// A house of three indexed triangles over five shared vertices: the wall
// (two triangles) shades continuously from red and green at the bottom to
// blue and yellow at the eaves, the roof to white at its peak. UINT64_VEC3
// indices draw the same picture.
using TriangleIndexed = GeometryScene;
TEST_F(TriangleIndexed, Raycast)
{
  auto house = [&](bool wide) {
    ANARIGeometry triangles = newGeometry("triangle");
    setArray(triangles,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-0.8f, -0.9f, 0},
            {0.8f, -0.9f, 0},
            {0.8f, 0.3f, 0},
            {-0.8f, 0.3f, 0},
            {0, 0.9f, 0}});
    setArray(triangles,
        "vertex.color",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{kRed, kGreen, kBlue, kYellow, kWhite});
    if (wide) {
      setArray(triangles,
          "primitive.index",
          ANARI_UINT64_VEC3,
          std::vector<uint64_t>{0, 1, 2, 0, 2, 3, 3, 2, 4});
    } else {
      setArray(triangles,
          "primitive.index",
          ANARI_UINT32_VEC3,
          std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 3, 2, 4});
    }
    return worldOf(triangles);
  };
  ANARICamera camera = flatCamera(2.f, 1.f);
  ANARIRenderer renderer = newRenderer();
  renderAndCompare(house(false), camera, renderer, 64, 64);
  expectSameImage(render(house(true), camera, renderer, 64, 64),
      render(house(false), camera, renderer, 64, 64),
      "UINT64_VEC3 against UINT32_VEC3 indices");
}

// Three quads from twelve vertices (three more, left over, are ignored): a
// red square, a green trapezoid and a blue parallelogram leaning right.
using QuadSoup = GeometryScene;
TEST_F(QuadSoup, Raycast)
{
  ANARIGeometry quads = newGeometry("quad");
  setArray(quads,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-1.4f, -0.4f, 0},
          {-0.6f, -0.4f, 0},
          {-0.6f, 0.4f, 0},
          {-1.4f, 0.4f, 0},
          {-0.5f, -0.8f, 0},
          {0.5f, -0.8f, 0},
          {0.2f, 0.8f, 0},
          {-0.2f, 0.8f, 0},
          {0.6f, -0.8f, 0},
          {1.0f, -0.8f, 0},
          {1.4f, 0.8f, 0},
          {1.0f, 0.8f, 0},
          {-1.4f, 0.9f, 0},
          {1.4f, 0.9f, 0},
          {1.4f, -0.9f, 0}});
  setArray(quads,
      "primitive.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kGreen, kBlue});
  renderAndCompare(
      worldOf(quads), flatCamera(2.f, 1.5f), newRenderer(), 96, 64);
}

// A 2 x 2 grid of quads over nine shared vertices, colored per vertex: red
// at the lower left, green at the lower right, blue at the upper left,
// yellow at the upper right, white in the middle; colors run continuously
// across the shared edges. UINT64_VEC4 indices draw the same picture. The
// camera is moved off centre by 0.01 so no pixel centre lies exactly on a
// quad's inner diagonal (QuadWatertight covers that).
using QuadIndexed = GeometryScene;
TEST_F(QuadIndexed, Raycast)
{
  auto grid = [&](bool wide) {
    std::vector<Vec3> positions;
    for (int y = 0; y < 3; y++) {
      for (int x = 0; x < 3; x++)
        positions.push_back(
            {-0.9f + 0.9f * float(x), -0.9f + 0.9f * float(y), 0.f});
    }
    const Vec3 grey{0.4f, 0.4f, 0.4f};
    ANARIGeometry quads = newGeometry("quad");
    setArray(quads, "vertex.position", ANARI_FLOAT32_VEC3, positions);
    setArray(quads,
        "vertex.color",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{
            kRed, grey, kGreen, grey, kWhite, grey, kBlue, grey, kYellow});
    const std::vector<uint32_t> index = {
        0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
    if (wide) {
      setArray(quads,
          "primitive.index",
          ANARI_UINT64_VEC4,
          std::vector<uint64_t>(index.begin(), index.end()));
    } else {
      setArray(quads, "primitive.index", ANARI_UINT32_VEC4, index);
    }
    return worldOf(quads);
  };
  ANARICamera camera =
      newOrthographicCamera({0.01f, 0.01f, 5}, {0, 0, -1}, {0, 1, 0}, 2.f, 1.f);
  ANARIRenderer renderer = newRenderer();
  renderAndCompare(grid(false), camera, renderer, 64, 64);
  expectSameImage(render(grid(true), camera, renderer, 64, 64),
      render(grid(false), camera, renderer, 64, 64),
      "UINT64_VEC4 against UINT32_VEC4 indices");
}

// One white square quad filling the middle of the frame, seen so that the
// centres of the 64 pixels on the diagonal x + y = 63 lie exactly on the
// edge (v1, v3) that splits it into two triangles: it must be solid white.
using QuadWatertight = GeometryScene;
TEST_F(QuadWatertight, Raycast)
{
  ANARIGeometry quad = newGeometry("quad");
  setArray(quad,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-0.9f, -0.9f, 0},
          {0.9f, -0.9f, 0},
          {0.9f, 0.9f, 0},
          {-0.9f, 0.9f, 0}});
  renderAndCompare(newWorld({newSurface(quad, newMatte(kWhite))}),
      flatCamera(2.f, 1.f),
      newRenderer(),
      64,
      64);
}

// Three spheres of the uniform radius 0.5, red, green and blue from left
// to right, lit from the eye.
using SphereSoup = GeometryScene;
TEST_F(SphereSoup, Raycast)
{
  ANARIGeometry spheres = newGeometry("sphere");
  setArray(spheres,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-1.2f, 0, 0}, {0, 0, 0}, {1.2f, 0, 0}});
  setArray(spheres,
      "primitive.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kGreen, kBlue});
  setFloat(spheres, "radius", 0.5f);
  renderAndCompare(
      worldOf(spheres), viewOfOrigin({0, 0, 4}, 1.5f), newRenderer(), 96, 64);
}

// Four candidate spheres along x with per-vertex radii 0.2, 0.3, 0.4, 0.5
// and colors red, green, blue, yellow; primitive.index {3, 0, 2} draws the
// big yellow one at the right, the small red one at the left and the blue
// one, but not the green one (second from the left).
using SphereIndexed = GeometryScene;
TEST_F(SphereIndexed, Raycast)
{
  ANARIGeometry spheres = newGeometry("sphere");
  setArray(spheres,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {-1.5f, 0, 0}, {-0.5f, 0, 0}, {0.5f, 0, 0}, {1.5f, 0, 0}});
  setArray(spheres,
      "vertex.radius",
      ANARI_FLOAT32,
      std::vector<float>{0.2f, 0.3f, 0.4f, 0.5f});
  setArray(spheres,
      "vertex.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kGreen, kBlue, kYellow});
  setArray(
      spheres, "primitive.index", ANARI_UINT32, std::vector<uint32_t>{3, 0, 2});
  renderAndCompare(
      worldOf(spheres), viewOfOrigin({0, 0, 4}, 1.5f), newRenderer(), 96, 64);
}

// Without primitive.index one curve joins all five vertices: an unbroken
// zigzag tube of uniform radius 0.12, red at the left end through green
// (middle) to blue at the right end.
using CurveSoup = GeometryScene;
TEST_F(CurveSoup, Raycast)
{
  ANARIGeometry curve = newGeometry("curve");
  setArray(curve,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-1.5f, -0.5f, 0},
          {-0.75f, 0.5f, 0},
          {0, -0.5f, 0},
          {0.75f, 0.5f, 0},
          {1.5f, -0.5f, 0}});
  setArray(curve,
      "vertex.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kYellow, kGreen, kWhite, kBlue});
  setFloat(curve, "radius", 0.12f);
  renderAndCompare(
      worldOf(curve), viewOfOrigin({0, 0, 4}, 1.5f), newRenderer(), 96, 64);
}

// Six zigzag vertices with radii alternating 0.05 (bottom) and 0.2 (top);
// primitive.index {0, 1, 3} makes the segments 0-1 and 1-2 (a tapered "V"
// at the left) and 3-4 (a tapered "\" right of it); the segments 2-3 and
// 4-5 are absent.
using CurveIndexed = GeometryScene;
TEST_F(CurveIndexed, Raycast)
{
  ANARIGeometry curve = newGeometry("curve");
  setArray(curve,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-1.5f, 0.6f, 0},
          {-0.9f, -0.6f, 0},
          {-0.3f, 0.6f, 0},
          {0.3f, 0.6f, 0},
          {0.9f, -0.6f, 0},
          {1.5f, 0.6f, 0}});
  setArray(curve,
      "vertex.radius",
      ANARI_FLOAT32,
      std::vector<float>{0.2f, 0.05f, 0.2f, 0.2f, 0.05f, 0.2f});
  setArray(curve,
      "vertex.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kGreen, kBlue, kYellow, kWhite, kRed});
  setArray(
      curve, "primitive.index", ANARI_UINT32, std::vector<uint32_t>{0, 1, 3});
  renderAndCompare(
      worldOf(curve), viewOfOrigin({0, 0, 4}, 1.5f), newRenderer(), 96, 64);
}

// Two cones from four vertices (a fifth, left over, is ignored), seen from
// above the front: at the left an upright cone from radius 0.5 (red base)
// to a point (blue tip); at the right a tilted cone widening from 0.1
// (green) to 0.4 (yellow), its open wide end turned away from the camera.
using ConeSoup = GeometryScene;
TEST_F(ConeSoup, Raycast)
{
  ANARIGeometry cones = newGeometry("cone");
  setArray(cones,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-1.2f, -0.8f, 0},
          {-1.2f, 0.8f, 0},
          {0.4f, -0.5f, 0},
          {1.4f, 0.5f, 0},
          {0, 0, 0}});
  setArray(cones,
      "vertex.radius",
      ANARI_FLOAT32,
      std::vector<float>{0.5f, 0.f, 0.1f, 0.4f, 1.f});
  setArray(cones,
      "vertex.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kBlue, kGreen, kYellow, kWhite});
  renderAndCompare(
      worldOf(cones), viewOfOrigin({0, 1.5f, 4}, 1.5f), newRenderer(), 96, 64);
}

// Four vertices at the corners of a square with radii 0.1 (bottom) and 0.3
// (top); primitive.index {(0, 2), (1, 3)} joins the diagonals into an "X"
// of two capped cones (a soup would have joined the bottom and top edges).
using ConeIndexed = GeometryScene;
TEST_F(ConeIndexed, Raycast)
{
  ANARIGeometry cones = newGeometry("cone");
  setArray(cones,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {-1.f, -0.8f, 0}, {1.f, -0.8f, 0}, {1.f, 0.8f, 0}, {-1.f, 0.8f, 0}});
  setArray(cones,
      "vertex.radius",
      ANARI_FLOAT32,
      std::vector<float>{0.1f, 0.1f, 0.3f, 0.3f});
  setArray(cones,
      "vertex.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kGreen, kBlue, kYellow});
  setArray(cones,
      "primitive.index",
      ANARI_UINT32_VEC2,
      std::vector<uint32_t>{0, 2, 1, 3});
  setString(cones, "caps", "both");
  renderAndCompare(
      worldOf(cones), viewOfOrigin({0, 0, 4}, 1.5f), newRenderer(), 96, 64);
}

// Two cylinders of the uniform radius 0.25 from four vertices, capped at
// both ends, seen from above the front: an upright one at the left (red
// bottom, blue top cap facing up), a horizontal one at the right (green
// left end, yellow right end).
using CylinderSoup = GeometryScene;
TEST_F(CylinderSoup, Raycast)
{
  ANARIGeometry cylinders = newGeometry("cylinder");
  setArray(cylinders,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {-1.2f, -0.8f, 0}, {-1.2f, 0.8f, 0}, {-0.2f, 0, 0}, {1.5f, 0, 0}});
  setArray(cylinders,
      "vertex.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kBlue, kGreen, kYellow});
  setFloat(cylinders, "radius", 0.25f);
  setString(cylinders, "caps", "both");
  renderAndCompare(worldOf(cylinders),
      viewOfOrigin({0, 3.f, 3.f}, 1.5f),
      newRenderer(),
      96,
      64);
}

// A square frame of four indexed cylinders around four shared corners,
// each with its own radius (primitive.radius) and color (primitive.color):
// bottom red 0.05, right green 0.1, top blue 0.15, left yellow 0.2.
using CylinderIndexed = GeometryScene;
TEST_F(CylinderIndexed, Raycast)
{
  ANARIGeometry cylinders = newGeometry("cylinder");
  setArray(cylinders,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {-1.f, -0.8f, 0}, {1.f, -0.8f, 0}, {1.f, 0.8f, 0}, {-1.f, 0.8f, 0}});
  setArray(cylinders,
      "primitive.index",
      ANARI_UINT32_VEC2,
      std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 0});
  setArray(cylinders,
      "primitive.radius",
      ANARI_FLOAT32,
      std::vector<float>{0.05f, 0.1f, 0.15f, 0.2f});
  setArray(cylinders,
      "primitive.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kGreen, kBlue, kYellow});
  renderAndCompare(
      worldOf(cylinders), viewOfOrigin({0, 0, 4}, 1.5f), newRenderer(), 96, 64);
}

// caps none / first / second / both (columns). Top row: vertex 0 faces the
// camera, so "first" and "both" show a solid red disc; "none" and "second"
// show the open tube and, through it, the blue second cap ("second") or
// the background. Bottom row: vertex 1 faces the camera, so "second" and
// "both" show a solid blue disc and "first" a red cap inside the tube.
using ConeCaps = GeometryScene;
TEST_F(ConeCaps, Raycast)
{
  renderAndCompare(
      capsWorld("cone", false), capsCamera(), newRenderer(), 128, 64);
}

using CylinderCaps = GeometryScene;
TEST_F(CylinderCaps, Raycast)
{
  renderAndCompare(
      capsWorld("cylinder", false), capsCamera(), newRenderer(), 128, 64);
}

// The caps grid from vertex.cap flags, which override caps "both": the
// same picture as ConeCaps / CylinderCaps.
using ConeVertexCap = GeometryScene;
TEST_F(ConeVertexCap, Raycast)
{
  ANARICamera camera = capsCamera();
  ANARIRenderer renderer = newRenderer();
  renderAndCompare(capsWorld("cone", true), camera, renderer, 128, 64);
  expectSameImage(render(capsWorld("cone", true), camera, renderer, 128, 64),
      render(capsWorld("cone", false), camera, renderer, 128, 64),
      "vertex.cap against caps");
}

using CylinderVertexCap = GeometryScene;
TEST_F(CylinderVertexCap, Raycast)
{
  ANARICamera camera = capsCamera();
  ANARIRenderer renderer = newRenderer();
  renderAndCompare(capsWorld("cylinder", true), camera, renderer, 128, 64);
  expectSameImage(
      render(capsWorld("cylinder", true), camera, renderer, 128, 64),
      render(capsWorld("cylinder", false), camera, renderer, 128, 64),
      "vertex.cap against caps");
}

// Four instances of one "L" (red bar, blue foot) from left to right: as
// modelled; turned a quarter counterclockwise (bar lying along -x, foot
// pointing up); stretched twice as wide; turned half round (upside down,
// foot pointing left), high in the frame.
using InstanceTransform = GeometryScene;
TEST_F(InstanceTransform, Raycast)
{
  ANARIGroup letter = letterL();
  std::vector<ANARIInstance> instances;
  for (const Mat4 &placement : letterPlacements()) {
    ANARIInstance instance = newInstance(letter);
    setMat4(instance, "transform", placement);
    anariCommitParameters(device(), instance);
    instances.push_back(instance);
  }
  renderAndCompare(
      newWorld({}, instances), flatCamera(2.4f, 2.f), newRenderer(), 128, 64);
}

// The same four placements as one instance with an ARRAY1D of transforms
// (KHR_INSTANCE_TRANSFORM_ARRAY): the picture of InstanceTransform.
using InstanceTransformArray = GeometryScene;
TEST_F(InstanceTransformArray, Raycast)
{
  ANARIInstance instance = newInstance(letterL());
  setArray(instance, "transform", ANARI_FLOAT32_MAT4, letterPlacements());
  anariCommitParameters(device(), instance);
  ANARICamera camera = flatCamera(2.4f, 2.f);
  ANARIRenderer renderer = newRenderer();
  ANARIWorld world = newWorld({}, {instance});
  renderAndCompare(world, camera, renderer, 128, 64);

  std::vector<ANARIInstance> separate;
  ANARIGroup letter = letterL();
  for (const Mat4 &placement : letterPlacements()) {
    ANARIInstance single = newInstance(letter);
    setMat4(single, "transform", placement);
    anariCommitParameters(device(), single);
    separate.push_back(single);
  }
  expectSameImage(render(world, camera, renderer, 128, 64),
      render(newWorld({}, separate), camera, renderer, 128, 64),
      "a transform array against one instance per transform");
}

} // namespace
