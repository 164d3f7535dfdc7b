// The furnished room as plain data: its triangle meshes with a description
// of their materials, its lights and its camera. buildFurnishedRoom turns it
// into ANARI objects; the path-tracer benchmark traces the same triangles
// with raw Embree, so both sides see exactly one scene.
#pragma once

#include "Meshes.h"

#include <string>
#include <vector>

namespace prism::scenes {

// What a part is made of, in terms every device understands: matte is a
// `matte` material, the others `physicallyBased` ones. The light panel is
// the ceiling light's fitting: white, and glowing by itself on devices
// without quad lights so the room is still lit.
struct PartMaterial
{
  enum class Kind { Matte, Metal, Glass, LightPanel };
  Kind kind{Kind::Matte};
  Vec3 color{0.7f, 0.7f, 0.7f};
  float roughness{0.f}; // metal only
};

// One surface of the room: every triangle of one material.
struct RoomPart
{
  std::string name;
  TriangleMesh mesh;
  PartMaterial material;
};

// The `quad` light in the ceiling: corner + edges as ANARI's quad light
// takes them (front side edge2 x edge1, facing down).
struct CeilingLight
{
  Vec3 position, edge1, edge2;
  Vec3 color;
  float intensity; // W / (sr m^2)
};

// The floor lamp's bulb: a `point` light with a radius.
struct BulbLight
{
  Vec3 position;
  float radius;
  Vec3 color;
  float intensity; // W / sr
};

struct FurnishedRoom
{
  std::vector<RoomPart> parts;
  CeilingLight ceilingLight;
  BulbLight bulb;
  SuggestedCamera camera;
  Bounds bounds;

  size_t triangleCount() const;
};

// The room, the same on every call and every platform: 6 x 5 m, 2.7 m high,
// closed on all sides, the camera inside.
FurnishedRoom furnishedRoomLayout();

} // namespace prism::scenes
