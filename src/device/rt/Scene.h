// One Embree scene: the geometry of a group (ids = surface indices), or the
// instances of a world (ids = instance indices). The only code, with
// Context, that sees Embree types.
#pragma once

#include "../math/KeyTimeline.h"
#include "Context.h"
#include "Hit.h"
#include "RayHitPacket.h"
#include "RayValidity.h"
#include "ShadowStops.h"
#include "UserGeometry.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

struct RTCSceneTy;
struct RTCGeometryTy;
struct RTCRayNp;

namespace prism {
class MotionTransform;
}

namespace prism::rt {
class RayQueue;
}

namespace prism::rt {

// Rays traced together in one coherent packet (see RayHitPacket).
constexpr int kPacketSize = 8;

// Vertex positions of a deforming mesh at keys uniformly distributed over
// `timeline`: one array per key, each as addTriangles' `vertices`.
struct VertexKeys
{
  std::vector<const float3 *> positions;
  KeyTimeline timeline;
};

class Scene
{
 public:
  explicit Scene(const Context &context);
  ~Scene();
  Scene(const Scene &) = delete;
  Scene &operator=(const Scene &) = delete;

  // Starts over with no geometry (keeps the context).
  void clear();

  // Shared, not copied: the arrays must outlive the scene's next clear().
  // Vertex arrays need 4 readable bytes after their last element (Embree
  // reads 16 bytes per vertex).
  void addTriangles(uint32_t id,
      const float3 *vertices,
      size_t vertexCount,
      const uint32_t *indices,
      size_t triangleCount);
  void addQuads(uint32_t id,
      const float3 *vertices,
      size_t vertexCount,
      const uint32_t *indices,
      size_t quadCount);
  // Deforming meshes (motion blur over Embree time steps).
  void addTriangles(uint32_t id,
      const VertexKeys &vertices,
      size_t vertexCount,
      const uint32_t *indices,
      size_t triangleCount);
  void addQuads(uint32_t id,
      const VertexKeys &vertices,
      size_t vertexCount,
      const uint32_t *indices,
      size_t quadCount);
  void addSpheres(uint32_t id, const float4 *centerAndRadius, size_t count);
  // Round linear segments from vertex i to i + 1 for every listed i.
  void addRoundCurves(uint32_t id,
      const float4 *positionAndRadius,
      size_t vertexCount,
      const uint32_t *segmentStarts,
      size_t segmentCount);
  void addUser(uint32_t id, const UserGeometry *geometry, size_t count);
  // Makes geometry `id` (already added) single-sided: every ray passes
  // through the side its geometric normal points away from (for triangles
  // and quads, where the corners run clockwise). Embree-native geometry
  // only; user geometry stays two-sided.
  void cullBackFaces(uint32_t id);
  // Makes geometry `id` (already added) see-through for occlusion rays:
  // where one meets it, the ShadowStops the trace was given decides
  // whether it stops (without one, it does).
  void letShadowsThrough(uint32_t id);
  // `child` placed by `worldFromObject`; `child` must be committed first.
  // The caller keeps rayRange() within the placement's worldRayRange()
  // (setRayRange), which it knows from the inverse it has checked.
  void addInstance(
      uint32_t id, const Scene &child, const mat3x4 &worldFromObject);
  // `child` moving over the shutter (motion blur over Embree time steps).
  void addInstance(
      uint32_t id, const Scene &child, const MotionTransform &worldFromObject);

  // Moves instance `id` (added by addInstance with a fixed transform) to
  // `worldFromObject`, keeping its Embree geometry: an edit commit()
  // then rebuilds only this scene's BVH (true and nothing done when it is
  // there already). False, changing nothing, when
  // `id` is not such an instance of `child` as built now (the child was
  // rebuilt since). As for addInstance, the caller sets rayRange() for the
  // placements as they are after the move.
  bool moveInstance(
      uint32_t id, const Scene &child, const mat3x4 &worldFromObject);
  // Whether geometry `id` is a fixed-transform instance of `child` as
  // built now.
  bool placesInstance(uint32_t id, const Scene &child) const;

  // Builds the BVH; call after adding everything.
  void commit();
  box3 bounds() const;
  // The largest coordinate of a ray traced here: below Embree's own limit
  // when an instance's transform would move rays out of its range there
  // (see worldRayRange()); rays beyond it find nothing.
  float rayRange() const
  {
    return m_rayRange;
  }
  // A ray range for the placements: the smallest of their
  // worldRayRange()s. Rays only: the BVH does not depend on it. (Moving
  // instances added since lower it further.)
  void setRayRange(float range)
  {
    m_rayRange = std::min(range, kLargestCoordinate);
  }

  // The closest hit along the ray in (tMin, tMax) at `time` (in the
  // shutter's [0, 1]); false if none.
  bool intersect(const float3 &origin,
      const float3 &direction,
      float tMin,
      float tMax,
      Hit &hit,
      float time) const;
  // Every ray of `queue` (incoherent rays, Embree's stream API): the
  // closest hits, or only whether anything blocks each ray (`stops`
  // deciding at see-through surfaces).
  void intersect(RayQueue &queue) const;
  void occluded(RayQueue &queue, const ShadowStops *stops = nullptr) const;
  // Traces the lanes of `packet` whose `active` entry is -1, in place, with
  // no copies: a lane's geometryId is kInvalidId unless it found a hit, and
  // its other hit fields mean something only then.
  void intersect(RayHitPacket &packet, const int active[kPacketSize]) const;

 private:
  // Commits `geometry` and attaches it as `id`, handing over our reference.
  void attach(RTCGeometryTy *geometry, uint32_t id);
  // Whether geometry `id` added an Embree geometry.
  bool isAttached(uint32_t id) const;
  // Sets geometry `id`'s filters for what m_oneSided and m_seeThrough say.
  void setFilters(uint32_t id);
  // Marks the queue's rays beyond rayRange() untraceable.
  void confine(RayQueue &queue) const;
  // The queue's ray arrays from ray `i` on, as Embree's stream API takes
  // them.
  static RTCRayNp streamAt(RayQueue &queue, size_t i);
  // Triangles (3 indices per primitive) or quads (4), sharing the arrays.
  void addMesh(uint32_t id,
      bool quads,
      const VertexKeys &vertices,
      size_t vertexCount,
      const uint32_t *indices,
      size_t primitiveCount);

  const Context &m_context;
  RTCSceneTy *m_scene{nullptr};
  float m_rayRange;
  // Vertices interpolated between keys where Embree's time steps fall
  // between them; kept until clear().
  std::vector<std::vector<float3>> m_interpolatedVertices;
  // By geometry id: added, single-sided, see-through, user geometry.
  std::vector<bool> m_attached, m_oneSided, m_seeThrough, m_user;
};

} // namespace prism::rt
