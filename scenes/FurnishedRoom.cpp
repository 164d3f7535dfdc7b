// A furnished living room, the path tracer's benchmark scene: a closed room
// (plank floor, walls with baseboards, a door, pictures) with a sofa and
// coffee table on a rug, a dining table with chairs, a bookshelf full of
// books, a sideboard, a plant, a floor lamp, and metal and glass objects.
// A quad light in the ceiling and the lamp's bulb light it; the camera
// stands inside, so almost no path leaves the room.
#include "FurnishedRoom.h"

#include "DemoScenes.h"
#include "Objects.h"

#include <deque>
#include <numbers>

namespace prism::scenes {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// The room spans x in [-3, 3], z in [-2.5, 2.5] and y in [0, 2.7].
constexpr float kHalfWidth = 3.f;
constexpr float kHalfDepth = 2.5f;
constexpr float kHeight = 2.7f;

PartMaterial matte(const Vec3 &color)
{
  return {PartMaterial::Kind::Matte, color, 0.f};
}
PartMaterial metal(const Vec3 &color, float roughness)
{
  return {PartMaterial::Kind::Metal, color, roughness};
}
PartMaterial glass()
{
  return {PartMaterial::Kind::Glass, {1.f, 1.f, 1.f}, 0.f};
}

const PartMaterial kWall = matte({0.78f, 0.74f, 0.68f});
const PartMaterial kCeiling = matte({0.82f, 0.82f, 0.8f});
const PartMaterial kTrim = matte({0.86f, 0.85f, 0.82f});
const PartMaterial kDarkWood = matte({0.2f, 0.12f, 0.07f});
const PartMaterial kMediumWood = matte({0.42f, 0.27f, 0.15f});
const PartMaterial kSofaFabric = matte({0.16f, 0.26f, 0.38f});
const PartMaterial kCushionFabric = matte({0.22f, 0.33f, 0.46f});
const PartMaterial kBrass = metal({0.91f, 0.73f, 0.4f}, 0.25f);
const PartMaterial kSteel = metal({0.8f, 0.8f, 0.82f}, 0.08f);
const PartMaterial kCopper = metal({0.95f, 0.58f, 0.42f}, 0.3f);
const PartMaterial kBlackMetal = metal({0.05f, 0.05f, 0.05f}, 0.4f);
const PartMaterial kGlass = glass();

// A piece of furniture's frame: standing at `position` on the floor, its
// front (+z in its own coordinates) turned by `yaw` about +y.
Mat4 placed(const Vec3 &position, float yaw)
{
  return translationMatrix(position) * rotationYMatrix(yaw);
}

// The unit box to a box of `size` centred at `center` in `frame`.
Mat4 boxIn(const Mat4 &frame, const Vec3 &center, const Vec3 &size)
{
  return frame * translationMatrix(center) * scaleMatrix(size);
}

// Appends the unit sphere transformed by the affine `objectToWorld`
// (ellipsoids: cushions, bowls, a vase). Normals go through the cofactor
// matrix, which is the inverse transpose up to a positive factor.
void addSphere(TriangleMesh &mesh,
    const Mat4 &objectToWorld,
    uint32_t segments,
    uint32_t rings)
{
  const size_t first = mesh.positions.size();
  mesh.addUvSphere({0.f, 0.f, 0.f}, 1.f, segments, rings);
  const Mat4 &m = objectToWorld;
  const Vec3 a{m[0], m[1], m[2]}, b{m[4], m[5], m[6]}, c{m[8], m[9], m[10]};
  const Vec3 normalX = cross(b, c), normalY = cross(c, a),
             normalZ = cross(a, b);
  for (size_t i = first; i < mesh.positions.size(); i++) {
    mesh.positions[i] = transformPoint(m, mesh.positions[i]);
    const Vec3 n = mesh.normals[i];
    mesh.normals[i] =
        normalize(normalX * n[0] + normalY * n[1] + normalZ * n[2]);
    Vec4 &t = mesh.tangents[i];
    const Vec3 tangent = normalize(transformDirection(m, {t[0], t[1], t[2]}));
    t = {tangent[0], tangent[1], tangent[2], t[3]};
  }
}

// Collects meshes by part name; deque, so a returned mesh stays put while
// more parts are added.
class PartList
{
 public:
  // The mesh of part `name`, created with `material` on first use.
  TriangleMesh &mesh(const std::string &name, const PartMaterial &material)
  {
    for (RoomPart &part : m_parts)
      if (part.name == name)
        return part.mesh;
    m_parts.push_back({name, {}, material});
    return m_parts.back().mesh;
  }
  std::vector<RoomPart> take()
  {
    return {std::make_move_iterator(m_parts.begin()),
        std::make_move_iterator(m_parts.end())};
  }

 private:
  std::deque<RoomPart> m_parts;
};

// Boards of four tones in staggered rows along z.
void addFloor(PartList &parts, Random &random)
{
  const Vec3 tones[4] = {{0.46f, 0.3f, 0.17f},
      {0.52f, 0.35f, 0.2f},
      {0.4f, 0.25f, 0.14f},
      {0.49f, 0.33f, 0.2f}};
  constexpr int kColumns = 32;
  const float boardWidth = 2.f * kHalfWidth / kColumns;
  for (int column = 0; column < kColumns; column++) {
    const float x = -kHalfWidth + boardWidth * float(column);
    float z = kHalfDepth;
    // The first board of each row is cut short by a random amount.
    float length = random.uniform(0.3f, 1.8f);
    while (z > -kHalfDepth) {
      length = std::min(length, z + kHalfDepth);
      const int tone = int(random.next() % 4);
      parts.mesh("floor-" + std::to_string(tone), matte(tones[tone]))
          .addQuad({x, 0.f, z}, {boardWidth, 0.f, 0.f}, {0.f, 0.f, -length});
      z -= length;
      length = random.uniform(1.2f, 1.8f);
    }
  }
}

// Walls and ceiling facing inwards, baseboards, a door in the right wall.
void addShell(PartList &parts)
{
  const float w = kHalfWidth, d = kHalfDepth, h = kHeight;
  TriangleMesh &walls = parts.mesh("walls", kWall);
  walls.addQuad({-w, 0.f, -d}, {2 * w, 0.f, 0.f}, {0.f, h, 0.f}); // back
  walls.addQuad({w, 0.f, d}, {-2 * w, 0.f, 0.f}, {0.f, h, 0.f});  // front
  walls.addQuad({-w, 0.f, d}, {0.f, 0.f, -2 * d}, {0.f, h, 0.f}); // left
  walls.addQuad({w, 0.f, -d}, {0.f, 0.f, 2 * d}, {0.f, h, 0.f});  // right
  parts.mesh("ceiling", kCeiling)
      .addQuad({-w, h, -d}, {2 * w, 0.f, 0.f}, {0.f, 0.f, 2 * d});

  TriangleMesh &trim = parts.mesh("trim", kTrim);
  const Mat4 room = identityMatrix();
  constexpr float kBoardHeight = 0.09f, kBoardThickness = 0.015f;
  const float y = kBoardHeight / 2, inset = kBoardThickness / 2;
  trim.addBox(boxIn(
      room, {0.f, y, -d + inset}, {2 * w, kBoardHeight, kBoardThickness}));
  trim.addBox(
      boxIn(room, {0.f, y, d - inset}, {2 * w, kBoardHeight, kBoardThickness}));
  trim.addBox(boxIn(
      room, {-w + inset, y, 0.f}, {kBoardThickness, kBoardHeight, 2 * d}));
  trim.addBox(
      boxIn(room, {w - inset, y, 0.f}, {kBoardThickness, kBoardHeight, 2 * d}));

  // The door: a leaf in a three-piece frame, a brass knob.
  const float doorZ = 1.5f;
  trim.addBox(boxIn(room, {w - 0.02f, 2.1f, doorZ}, {0.04f, 0.08f, 1.06f}));
  trim.addBox(
      boxIn(room, {w - 0.02f, 1.04f, doorZ - 0.5f}, {0.04f, 2.08f, 0.06f}));
  trim.addBox(
      boxIn(room, {w - 0.02f, 1.04f, doorZ + 0.5f}, {0.04f, 2.08f, 0.06f}));
  parts.mesh("door", matte({0.62f, 0.6f, 0.56f}))
      .addBox(boxIn(room, {w - 0.015f, 1.03f, doorZ}, {0.03f, 2.06f, 0.94f}));
  addSphere(parts.mesh("brass", kBrass),
      translationMatrix({w - 0.07f, 1.f, doorZ - 0.38f})
          * scaleMatrix({0.03f, 0.03f, 0.03f}),
      16,
      8);
}

void addSofa(PartList &parts, const Mat4 &frame)
{
  TriangleMesh &fabric = parts.mesh("sofa", kSofaFabric);
  fabric.addBox(boxIn(frame, {0.f, 0.26f, 0.f}, {2.1f, 0.32f, 0.9f}));
  fabric.addBox(boxIn(frame, {0.f, 0.62f, -0.34f}, {2.1f, 0.5f, 0.22f}));
  for (float side : {-1.f, 1.f})
    fabric.addBox(
        boxIn(frame, {side * 0.97f, 0.54f, 0.f}, {0.16f, 0.28f, 0.9f}));
  TriangleMesh &legs = parts.mesh("dark wood", kDarkWood);
  for (float x : {-1.f, 1.f})
    for (float z : {-0.38f, 0.38f})
      legs.addBox(boxIn(frame, {x, 0.05f, z}, {0.05f, 0.1f, 0.05f}));
  TriangleMesh &cushions = parts.mesh("sofa cushions", kCushionFabric);
  for (float x : {-0.595f, 0.f, 0.595f}) {
    cushions.addBox(boxIn(frame, {x, 0.48f, 0.09f}, {0.58f, 0.12f, 0.66f}));
    cushions.addBox(boxIn(frame, {x, 0.72f, -0.17f}, {0.58f, 0.38f, 0.14f}));
  }
  // Throw pillows, leaning into the corners.
  addSphere(parts.mesh("pillow mustard", matte({0.78f, 0.56f, 0.12f})),
      frame * translationMatrix({-0.72f, 0.7f, 0.f}) * rotationYMatrix(0.35f)
          * scaleMatrix({0.2f, 0.18f, 0.07f}),
      32,
      16);
  addSphere(parts.mesh("pillow terracotta", matte({0.7f, 0.3f, 0.18f})),
      frame * translationMatrix({0.74f, 0.7f, 0.f}) * rotationYMatrix(-0.3f)
          * scaleMatrix({0.2f, 0.18f, 0.07f}),
      32,
      16);
}

// A patterned rug: a cream border around a deep red field.
void addRug(PartList &parts, const Vec3 &center)
{
  const Mat4 room = identityMatrix();
  parts.mesh("rug border", matte({0.82f, 0.75f, 0.6f}))
      .addBox(
          boxIn(room, center + Vec3{0.f, 0.006f, 0.f}, {2.2f, 0.012f, 2.6f}));
  parts.mesh("rug field", matte({0.5f, 0.1f, 0.09f}))
      .addBox(
          boxIn(room, center + Vec3{0.f, 0.007f, 0.f}, {1.95f, 0.014f, 2.35f}));
}

void addCoffeeTable(PartList &parts, const Mat4 &frame)
{
  TriangleMesh &wood = parts.mesh("dark wood", kDarkWood);
  wood.addBox(boxIn(frame, {0.f, 0.41f, 0.f}, {1.1f, 0.04f, 0.6f}));
  wood.addBox(boxIn(frame, {0.f, 0.12f, 0.f}, {1.f, 0.02f, 0.5f}));
  for (float x : {-0.5f, 0.5f})
    for (float z : {-0.25f, 0.25f})
      wood.addBox(boxIn(frame, {x, 0.215f, z}, {0.04f, 0.39f, 0.04f}));
  const float top = 0.43f;
  addSphere(parts.mesh("copper", kCopper),
      frame * translationMatrix({-0.25f, top + 0.05f, 0.f})
          * scaleMatrix({0.16f, 0.05f, 0.16f}),
      48,
      24);
  addSphere(parts.mesh("glass", kGlass),
      frame * translationMatrix({0.3f, top + 0.07f, 0.1f})
          * scaleMatrix({0.07f, 0.07f, 0.07f}),
      48,
      24);
  // Two books lying on top of each other.
  parts.mesh("books-0", matte({0.55f, 0.1f, 0.08f}))
      .addBox(boxIn(frame * rotationYMatrix(0.2f),
          {0.25f, top + 0.02f, -0.12f},
          {0.3f, 0.04f, 0.22f}));
  parts.mesh("books-3", matte({0.85f, 0.8f, 0.66f}))
      .addBox(boxIn(frame * rotationYMatrix(0.05f),
          {0.26f, top + 0.055f, -0.12f},
          {0.24f, 0.03f, 0.17f}));
}

void addChair(PartList &parts, const Mat4 &frame)
{
  TriangleMesh &wood = parts.mesh("medium wood", kMediumWood);
  wood.addBox(boxIn(frame, {0.f, 0.45f, 0.f}, {0.44f, 0.04f, 0.42f}));
  for (float x : {-0.195f, 0.195f}) {
    wood.addBox(boxIn(frame, {x, 0.215f, 0.185f}, {0.035f, 0.43f, 0.035f}));
    wood.addBox(boxIn(frame, {x, 0.47f, -0.185f}, {0.035f, 0.94f, 0.035f}));
  }
  wood.addBox(boxIn(frame, {0.f, 0.87f, -0.185f}, {0.42f, 0.1f, 0.025f}));
  wood.addBox(boxIn(frame, {0.f, 0.68f, -0.185f}, {0.42f, 0.05f, 0.025f}));
  parts.mesh("chair cushions", matte({0.33f, 0.42f, 0.27f}))
      .addBox(boxIn(frame, {0.f, 0.485f, 0.01f}, {0.4f, 0.03f, 0.38f}));
}

// A table for six with five chairs, a glass vase and a bowl of fruit.
void addDiningSet(PartList &parts, const Mat4 &frame, Random &random)
{
  TriangleMesh &wood = parts.mesh("medium wood", kMediumWood);
  wood.addBox(boxIn(frame, {0.f, 0.745f, 0.f}, {1.6f, 0.05f, 0.9f}));
  for (float x : {-0.72f, 0.72f})
    for (float z : {-0.38f, 0.38f})
      wood.addBox(boxIn(frame, {x, 0.36f, z}, {0.06f, 0.72f, 0.06f}));
  for (float z : {-0.38f, 0.38f})
    wood.addBox(boxIn(frame, {0.f, 0.68f, z}, {1.38f, 0.08f, 0.02f}));
  for (float x : {-0.72f, 0.72f})
    wood.addBox(boxIn(frame, {x, 0.68f, 0.f}, {0.02f, 0.08f, 0.7f}));

  struct Seat
  {
    Vec3 position;
    float yaw;
  };
  const Seat seats[] = {{{-0.4f, 0.f, -0.68f}, 0.f},
      {{0.4f, 0.f, -0.7f}, 0.f},
      {{-0.4f, 0.f, 0.72f}, kPi},
      {{0.42f, 0.f, 0.68f}, kPi},
      {{-1.06f, 0.f, 0.f}, 0.5f * kPi}};
  for (const Seat &seat : seats) {
    // Chairs left as people left them: a little askew.
    const float yaw = seat.yaw + random.uniform(-0.15f, 0.15f);
    addChair(parts, frame * placed(seat.position, yaw));
  }

  const float top = 0.77f;
  addSphere(parts.mesh("glass", kGlass),
      frame * translationMatrix({-0.15f, top + 0.15f, 0.05f})
          * scaleMatrix({0.085f, 0.15f, 0.085f}),
      64,
      32);
  const Vec3 bowl{0.35f, top + 0.055f, -0.05f};
  addSphere(parts.mesh("steel", kSteel),
      frame * translationMatrix(bowl) * scaleMatrix({0.17f, 0.055f, 0.17f}),
      48,
      24);
  const PartMaterial fruits[3] = {matte({0.85f, 0.4f, 0.04f}),
      matte({0.62f, 0.06f, 0.04f}),
      matte({0.42f, 0.6f, 0.12f})};
  const Vec3 offsets[5] = {{-0.06f, 0.f, -0.04f},
      {0.06f, 0.f, -0.03f},
      {0.f, 0.f, 0.07f},
      {0.01f, 0.07f, 0.f},
      {-0.08f, 0.f, 0.06f}};
  for (int i = 0; i < 5; i++) {
    const Vec3 center = bowl + Vec3{0.f, 0.09f, 0.f} + offsets[i];
    parts.mesh("fruit-" + std::to_string(i % 3), fruits[i % 3])
        .addUvSphere(transformPoint(frame, center), 0.045f, 24, 12);
  }
}

// A shelf unit whose five shelves hold books of random size and colour,
// a few lying in stacks, and some ornaments.
void addBookshelf(PartList &parts, const Mat4 &frame, Random &random)
{
  constexpr float kWidth = 1.6f, kTallness = 2.f, kDepth = 0.34f;
  constexpr float kBoard = 0.025f;
  TriangleMesh &wood = parts.mesh("dark wood", kDarkWood);
  for (float side : {-1.f, 1.f})
    wood.addBox(boxIn(frame,
        {side * (kWidth - 0.03f) / 2, kTallness / 2, 0.f},
        {0.03f, kTallness, kDepth}));
  wood.addBox(
      boxIn(frame, {0.f, kTallness - 0.015f, 0.f}, {kWidth, 0.03f, kDepth}));
  wood.addBox(boxIn(frame, {0.f, 0.05f, 0.f}, {kWidth - 0.06f, 0.1f, kDepth}));
  wood.addBox(boxIn(frame,
      {0.f, kTallness / 2, -kDepth / 2 + 0.01f},
      {kWidth - 0.06f, kTallness, 0.02f}));

  const Vec3 palette[8] = {{0.55f, 0.1f, 0.08f},
      {0.1f, 0.2f, 0.42f},
      {0.12f, 0.35f, 0.2f},
      {0.85f, 0.8f, 0.66f},
      {0.75f, 0.55f, 0.12f},
      {0.3f, 0.15f, 0.3f},
      {0.08f, 0.08f, 0.09f},
      {0.6f, 0.35f, 0.25f}};
  auto books = [&](int colour) -> TriangleMesh & {
    return parts.mesh(
        "books-" + std::to_string(colour), matte(palette[colour]));
  };
  const float inner = kWidth / 2 - 0.03f;
  const float back = -kDepth / 2 + 0.02f;
  constexpr int kShelves = 5;
  const float spacing = (kTallness - 0.1f - 0.03f) / kShelves;
  for (int shelf = 0; shelf < kShelves; shelf++) {
    const float shelfTop =
        0.1f + spacing * float(shelf) + (shelf ? kBoard / 2 : 0.f);
    if (shelf > 0)
      wood.addBox(boxIn(frame,
          {0.f, 0.1f + spacing * float(shelf), 0.f},
          {kWidth - 0.06f, kBoard, kDepth - 0.02f}));
    const float clearance = spacing - kBoard;
    float x = -inner;
    while (true) {
      const float choice = random.uniform();
      if (choice < 0.06f) { // a gap
        x += random.uniform(0.05f, 0.2f);
        continue;
      }
      if (choice < 0.1f && x + 0.3f < inner) { // a stack lying flat
        float y = shelfTop;
        const int count = 2 + int(random.next() % 4);
        for (int i = 0; i < count; i++) {
          const Vec3 size{random.uniform(0.2f, 0.26f),
              random.uniform(0.025f, 0.05f),
              random.uniform(0.15f, 0.22f)};
          books(int(random.next() % 8))
              .addBox(
                  boxIn(frame * rotationYMatrix(random.uniform(-0.08f, 0.08f)),
                      {x + 0.15f, y + size[1] / 2, back + 0.13f},
                      size));
          y += size[1];
        }
        x += 0.3f;
        continue;
      }
      if (choice < 0.13f && x + 0.16f < inner) { // an ornament
        const float radius = random.uniform(0.04f, 0.07f);
        const Vec3 center{x + 0.08f, shelfTop + radius, 0.f};
        const bool metallic = random.uniform() < 0.5f;
        parts.mesh(metallic ? "brass" : "glass", metallic ? kBrass : kGlass)
            .addUvSphere(transformPoint(frame, center), radius, 32, 16);
        x += 0.16f;
        continue;
      }
      const float width = random.uniform(0.022f, 0.055f);
      if (x + width > inner)
        break;
      const Vec3 size{width,
          clearance * random.uniform(0.55f, 0.88f),
          random.uniform(0.17f, 0.27f)};
      books(int(random.next() % 8))
          .addBox(boxIn(frame,
              {x + width / 2, shelfTop + size[1] / 2, back + size[2] / 2},
              size));
      x += width + 0.002f;
    }
  }
}

// A low cabinet with brass handles; a steel and a glass sphere on top.
void addSideboard(PartList &parts, const Mat4 &frame)
{
  TriangleMesh &wood = parts.mesh("dark wood", kDarkWood);
  wood.addBox(boxIn(frame, {0.f, 0.42f, 0.f}, {1.5f, 0.7f, 0.45f}));
  for (float x : {-0.7f, 0.7f})
    for (float z : {-0.18f, 0.18f})
      wood.addBox(boxIn(frame, {x, 0.035f, z}, {0.04f, 0.07f, 0.04f}));
  TriangleMesh &brass = parts.mesh("brass", kBrass);
  for (float x : {-0.45f, -0.05f, 0.05f, 0.45f})
    brass.addBox(boxIn(frame, {x, 0.6f, 0.23f}, {0.015f, 0.12f, 0.015f}));
  parts.mesh("steel", kSteel)
      .addUvSphere(transformPoint(frame, {-0.4f, 0.89f, 0.f}), 0.12f, 64, 32);
  parts.mesh("glass", kGlass)
      .addUvSphere(transformPoint(frame, {0.15f, 0.86f, 0.05f}), 0.09f, 48, 24);
  addSphere(parts.mesh("brass", kBrass),
      frame * translationMatrix({0.5f, 0.81f, 0.f})
          * scaleMatrix({0.13f, 0.04f, 0.13f}),
      48,
      24);
}

// A potted plant: a terracotta pot and a crown of leafy spheres.
void addPlant(PartList &parts, const Mat4 &frame, Random &random)
{
  parts.mesh("terracotta", matte({0.6f, 0.28f, 0.16f}))
      .addBox(boxIn(frame, {0.f, 0.2f, 0.f}, {0.34f, 0.4f, 0.34f}));
  parts.mesh("soil", matte({0.12f, 0.08f, 0.05f}))
      .addBox(boxIn(frame, {0.f, 0.395f, 0.f}, {0.3f, 0.02f, 0.3f}));
  parts.mesh("medium wood", kMediumWood)
      .addBox(boxIn(frame, {0.f, 0.65f, 0.f}, {0.03f, 0.5f, 0.03f}));
  const PartMaterial leaves[2] = {
      matte({0.14f, 0.34f, 0.1f}), matte({0.22f, 0.42f, 0.12f})};
  for (int i = 0; i < 14; i++) {
    const Vec3 center{random.uniform(-0.22f, 0.22f),
        random.uniform(0.75f, 1.35f),
        random.uniform(-0.22f, 0.22f)};
    parts.mesh("leaves-" + std::to_string(i % 2), leaves[i % 2])
        .addUvSphere(
            transformPoint(frame, center), random.uniform(0.1f, 0.19f), 32, 16);
  }
}

// A floor lamp: a round foot, a pole and a square shade, open at both
// ends, around the bulb. Returns the bulb's centre.
Vec3 addFloorLamp(PartList &parts, const Mat4 &frame)
{
  TriangleMesh &metalParts = parts.mesh("black metal", kBlackMetal);
  addSphere(metalParts,
      frame * translationMatrix({0.f, 0.02f, 0.f})
          * scaleMatrix({0.16f, 0.025f, 0.16f}),
      32,
      16);
  metalParts.addBox(boxIn(frame, {0.f, 0.735f, 0.f}, {0.025f, 1.43f, 0.025f}));
  TriangleMesh &shade = parts.mesh("lamp shade", matte({0.9f, 0.84f, 0.7f}));
  const float y = 1.58f;
  for (float side : {-1.f, 1.f}) {
    shade.addBox(boxIn(frame, {0.f, y, side * 0.205f}, {0.42f, 0.32f, 0.01f}));
    shade.addBox(boxIn(frame, {side * 0.205f, y, 0.f}, {0.01f, 0.32f, 0.4f}));
  }
  return transformPoint(frame, {0.f, 1.56f, 0.f});
}

// A framed canvas on a wall: `frame` has the wall's inward normal as +z.
void addPicture(PartList &parts,
    const Mat4 &frame,
    float width,
    float height,
    const Vec3 &background,
    const Vec3 &accent)
{
  parts.mesh("dark wood", kDarkWood)
      .addBox(boxIn(frame, {0.f, 0.f, 0.015f}, {width, height, 0.03f}));
  const float border = 0.05f;
  const Vec3 corner = transformPoint(
      frame, {-width / 2 + border, -height / 2 + border, 0.031f});
  const Vec3 across = transformDirection(frame, {width - 2 * border, 0.f, 0.f});
  const Vec3 up = transformDirection(frame, {0.f, height - 2 * border, 0.f});
  parts.mesh("canvas", matte(background)).addQuad(corner, across, up);
  // An abstract block of colour, a hair in front of the canvas.
  const Vec3 out = transformDirection(frame, {0.f, 0.f, 0.001f});
  parts.mesh("paint", matte(accent))
      .addQuad(
          corner + across * 0.2f + up * 0.25f + out, across * 0.45f, up * 0.5f);
}

} // namespace

size_t FurnishedRoom::triangleCount() const
{
  size_t count = 0;
  for (const RoomPart &part : parts)
    count += part.mesh.triangles.size();
  return count;
}

FurnishedRoom furnishedRoomLayout()
{
  Random random(2024);
  PartList parts;
  addFloor(parts, random);
  addShell(parts);
  addRug(parts, {-1.5f, 0.f, -0.2f});
  // Along the left wall, facing into the room (+x).
  addSofa(parts, placed({-2.5f, 0.f, -0.2f}, 0.5f * kPi));
  addCoffeeTable(parts, placed({-1.45f, 0.f, -0.2f}, 0.5f * kPi));
  addDiningSet(parts, placed({1.1f, 0.f, -0.6f}, 0.f), random);
  addBookshelf(parts, placed({-0.7f, 0.f, -kHalfDepth + 0.18f}, 0.f), random);
  addSideboard(parts, placed({kHalfWidth - 0.24f, 0.f, -1.6f}, -0.5f * kPi));
  addPlant(parts, placed({0.55f, 0.f, -2.2f}, 0.f), random);
  const Vec3 bulb = addFloorLamp(parts, placed({-2.55f, 0.f, -1.85f}, 0.f));
  addPicture(parts,
      placed({-kHalfWidth, 1.55f, -0.2f}, 0.5f * kPi),
      1.1f,
      0.65f,
      {0.55f, 0.68f, 0.75f},
      {0.8f, 0.55f, 0.15f});
  addPicture(parts,
      placed({1.3f, 1.65f, -kHalfDepth}, 0.f),
      0.8f,
      0.6f,
      {0.85f, 0.82f, 0.72f},
      {0.15f, 0.3f, 0.5f});

  FurnishedRoom room;
  // The ceiling light's fitting, a hair below the ceiling; the light itself
  // a hair below that. Large and dim rather than small and bright, so the
  // caustics of the glass and metal (which only paths that hit the light
  // find) stay faint speckles.
  const Vec3 panelCorner{-1.f, kHeight - 0.005f, -1.f};
  const Vec3 panelEdge1{2.f, 0.f, 0.f}, panelEdge2{0.f, 0.f, 1.4f};
  parts
      .mesh(
          "light panel", {PartMaterial::Kind::LightPanel, {1.f, 1.f, 1.f}, 0.f})
      .addQuad(panelCorner, panelEdge1, panelEdge2);
  // The front side, edge2 x edge1 (spec 5.7.4), faces down.
  room.ceilingLight = {panelCorner + Vec3{0.f, -0.001f, 0.f},
      panelEdge2,
      panelEdge1,
      {1.f, 0.93f, 0.82f},
      5.5f};
  room.bulb = {bulb, 0.09f, {1.f, 0.72f, 0.42f}, 0.0001f};

  room.parts = parts.take();
  for (const RoomPart &part : room.parts)
    room.bounds.extend(part.mesh.bounds());
  room.camera.valid = true;
  room.camera.eye = {1.9f, 1.55f, 2.25f};
  room.camera.at = {-0.9f, 0.85f, -1.f};
  room.camera.fovyDegrees = 55.f;
  return room;
}

Scene buildFurnishedRoom(ANARIDevice device)
{
  const FurnishedRoom room = furnishedRoomLayout();
  Scene scene;
  scene.name = "furnished-room";
  scene.description = "a furnished living room";
  scene.camera = room.camera;
  scene.bounds = room.bounds;

  std::vector<ANARIObject> lights;
  ANARILight ceiling = newLightIfSupported(device, "quad", scene, lights);
  if (ceiling) {
    setVec3(device, ceiling, "position", room.ceilingLight.position);
    setVec3(device, ceiling, "edge1", room.ceilingLight.edge1);
    setVec3(device, ceiling, "edge2", room.ceilingLight.edge2);
    setVec3(device, ceiling, "color", room.ceilingLight.color);
    setFloat(device, ceiling, "intensity", room.ceilingLight.intensity);
    anariCommitParameters(device, ceiling);
  }
  if (ANARILight bulb = newLightIfSupported(device, "point", scene, lights)) {
    setVec3(device, bulb, "position", room.bulb.position);
    setFloat(device, bulb, "radius", room.bulb.radius);
    setVec3(device, bulb, "color", room.bulb.color);
    setFloat(device, bulb, "intensity", room.bulb.intensity);
    anariCommitParameters(device, bulb);
  }

  std::vector<ANARIObject> surfaces;
  uint32_t id = 0;
  for (const RoomPart &part : room.parts) {
    const PartMaterial &look = part.material;
    ANARIMaterial material = nullptr;
    const char *materialSubtype =
        look.kind == PartMaterial::Kind::Matte ? "matte" : "physicallyBased";
    if (look.kind == PartMaterial::Kind::Matte) {
      material = newMatte(device, look.color);
    } else {
      material = anariNewMaterial(device, "physicallyBased");
      setVec3(device, material, "baseColor", look.color);
      const bool isMetal = look.kind == PartMaterial::Kind::Metal;
      setFloat(device, material, "metallic", isMetal ? 1.f : 0.f);
      setFloat(device, material, "roughness", look.roughness);
      if (look.kind == PartMaterial::Kind::Glass) {
        setFloat(device, material, "transmission", 1.f);
        setFloat(device, material, "ior", 1.5f);
      }
      // Without a quad light the fitting glows by itself, as bright.
      if (look.kind == PartMaterial::Kind::LightPanel && !ceiling)
        setVec3(device,
            material,
            "emissive",
            room.ceilingLight.color * room.ceilingLight.intensity);
      anariCommitParameters(device, material);
    }
    ANARIGeometry geometry = newTriangleGeometry(device, part.mesh);
    ANARISurface surface = newListedSurface(device,
        scene.surfaces,
        geometry,
        "triangle",
        material,
        materialSubtype,
        id);
    anariRelease(device, geometry);
    anariRelease(device, material);
    surfaces.push_back(surface);
    id++;
  }
  finishWorld(device, scene, surfaces, {}, lights);
  return scene;
}

} // namespace prism::scenes
