#include "Scene.h"

#include "../math/MotionTransform.h"
#include "RayQueue.h"
#include "RayValidity.h"

#include "../parallel/Blocks.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

namespace prism::rt {
namespace {

// Rays per Embree stream call: a tile's wavefront (32 x 32).
constexpr size_t kStreamSize = 1024;

// Embree's context for a trace, and where the filters of single-sided
// surfaces record the nearest face each ray passed (indexed by the ray's
// id; none for rays traced outside a queue). Every trace passes one, so
// a filter may read it from any context Embree hands it.
struct TraceContext
{
  RTCIntersectContext embree;
  float *passedOneSided{nullptr};
  const ShadowStops *stops{nullptr}; // occlusion rays at see-through surfaces
};
static_assert(std::is_standard_layout_v<
                  TraceContext> && offsetof(TraceContext, embree) == 0);

TraceContext plainContext(RTCIntersectContextFlags flags)
{
  TraceContext context;
  rtcInitIntersectContext(&context.embree);
  context.embree.flags = flags;
  return context;
}

// How Embree should trace a queue's rays (coherent: a tile's camera rays).
TraceContext contextFor(RayQueue &queue, float *passedOneSided)
{
  TraceContext context =
      plainContext(queue.coherent() ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                    : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
  context.passedOneSided = passedOneSided;
  return context;
}

// Notes that ray i of a filter's rays passed a face at its candidate
// distance (Embree puts it in the ray's tfar while the filter decides).
void notePassed(const RTCFilterFunctionNArguments *args, unsigned i)
{
  const auto *context = reinterpret_cast<const TraceContext *>(args->context);
  if (!context->passedOneSided)
    return;
  float &nearest = context->passedOneSided[RTCRayN_id(args->ray, args->N, i)];
  nearest = std::min(nearest, RTCRayN_tfar(args->ray, args->N, i));
}

void userBounds(const RTCBoundsFunctionArguments *args)
{
  auto *geometry = (const UserGeometry *)args->geometryUserPtr;
  const box3 b = geometry->primitiveBounds(args->primID);
  *args->bounds_o = {b.lower.x,
      b.lower.y,
      b.lower.z,
      0.f,
      b.upper.x,
      b.upper.y,
      b.upper.z,
      0.f};
}

float3 originOf(RTCRayN *ray, unsigned n, unsigned i)
{
  return {RTCRayN_org_x(ray, n, i),
      RTCRayN_org_y(ray, n, i),
      RTCRayN_org_z(ray, n, i)};
}

float3 directionOf(RTCRayN *ray, unsigned n, unsigned i)
{
  return {RTCRayN_dir_x(ray, n, i),
      RTCRayN_dir_y(ray, n, i),
      RTCRayN_dir_z(ray, n, i)};
}

// Ray i of a stream Embree hands a user geometry, tested against
// `primitive`: the nearest hit in the ray's (tnear, tfar), if any, and the
// primitive id it reports.
bool intersectLane(const UserGeometry &geometry,
    unsigned primitive,
    RTCRayN *ray,
    unsigned n,
    unsigned i,
    float &t,
    float &u,
    float &v,
    float3 &normal,
    uint32_t &reportedPrimitive)
{
  reportedPrimitive = primitive;
  return geometry.intersectPrimitive(primitive,
      originOf(ray, n, i),
      directionOf(ray, n, i),
      RTCRayN_tnear(ray, n, i),
      RTCRayN_tfar(ray, n, i),
      t,
      u,
      v,
      normal,
      reportedPrimitive);
}

void userIntersect(const RTCIntersectFunctionNArguments *args)
{
  auto *geometry = (const UserGeometry *)args->geometryUserPtr;
  RTCRayHitN *rayHit = (RTCRayHitN *)args->rayhit;
  RTCRayN *ray = RTCRayHitN_RayN(rayHit, args->N);
  RTCHitN *hit = RTCRayHitN_HitN(rayHit, args->N);
  for (unsigned i = 0; i < args->N; i++) {
    if (!args->valid[i])
      continue;
    float t, u, v;
    float3 normal;
    uint32_t primitive;
    if (!intersectLane(*geometry,
            args->primID,
            ray,
            args->N,
            i,
            t,
            u,
            v,
            normal,
            primitive))
      continue;
    RTCRayN_tfar(ray, args->N, i) = t;
    RTCHitN_Ng_x(hit, args->N, i) = normal.x;
    RTCHitN_Ng_y(hit, args->N, i) = normal.y;
    RTCHitN_Ng_z(hit, args->N, i) = normal.z;
    RTCHitN_u(hit, args->N, i) = u;
    RTCHitN_v(hit, args->N, i) = v;
    RTCHitN_primID(hit, args->N, i) = primitive;
    RTCHitN_geomID(hit, args->N, i) = args->geomID;
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; l++)
      RTCHitN_instID(hit, args->N, i, l) = args->context->instID[l];
  }
}

// Crossings of a see-through user geometry a shadow ray may pass before
// it counts as blocked.
constexpr int kMaxSeeThroughCrossings = 64;

// Embree's occlusion test of a user geometry's primitive: the first
// crossing blocks the ray, or, `kSeeThrough`, each crossing in turn as the
// trace's ShadowStops decides (as the filters do for native geometry).
template <bool kSeeThrough>
void userOccluded(const RTCOccludedFunctionNArguments *args)
{
  auto *geometry = (const UserGeometry *)args->geometryUserPtr;
  const auto *context = reinterpret_cast<const TraceContext *>(args->context);
  RTCRayN *ray = args->ray;
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; i++) {
    if (!args->valid[i])
      continue;
    const float3 origin = originOf(ray, n, i),
                 direction = directionOf(ray, n, i);
    float tMin = RTCRayN_tnear(ray, n, i);
    const float tMax = RTCRayN_tfar(ray, n, i);
    for (int crossing = 0; crossing < kMaxSeeThroughCrossings; crossing++) {
      Hit hit;
      hit.primitiveId = args->primID;
      if (!geometry->intersectPrimitive(args->primID,
              origin,
              direction,
              tMin,
              tMax,
              hit.t,
              hit.u,
              hit.v,
              hit.geometricNormal,
              hit.primitiveId))
        break;
      hit.geometryId = args->geomID;
      hit.instanceId = args->context->instID[0];
      const bool passes = kSeeThrough && context->stops
                          && crossing + 1 < kMaxSeeThroughCrossings
                          && !context->stops->at(
                              origin, direction, RTCRayN_time(ray, n, i), hit);
      if (!passes) {
        RTCRayN_tfar(ray, n, i) = -std::numeric_limits<float>::infinity();
        break;
      }
      // On past it, as the path tracer carries a ray on past a layer.
      tMin = hit.t + std::max(1e-4f, hit.t * 1e-5f);
    }
  }
}

// Ray times Embree accepts; anything else traces at the shutter midpoint.
float validTime(float time)
{
  return time >= 0.f && time <= 1.f ? time : 0.5f;
}

// The uniform time steps Embree traces keys over `timeline` with. Embree
// drops geometry at times outside its steps' range, ANARI holds the first
// and last key: extra steps repeating them extend the range over the
// whole shutter [0, 1]. Keys too dense for Embree's step limit are
// resampled over the range covering keys and shutter.
struct TimeSteps
{
  uint32_t count{1};
  float begin{0.f}, end{1.f};

  float time(uint32_t step) const
  {
    return count < 2 ? begin
                     : begin + (end - begin) * float(step) / float(count - 1);
  }
};

TimeSteps timeStepsFor(const KeyTimeline &keys)
{
  if (keys.keyCount < 2 || !(keys.end > keys.begin))
    return {};
  const float spacing = (keys.end - keys.begin) / float(keys.keyCount - 1);
  // A step ends up within 1e-4 spacings of the shutter's ends at most.
  const float before = std::max(0.f, std::ceil(keys.begin / spacing - 1e-4f));
  const float after =
      std::max(0.f, std::ceil((1.f - keys.end) / spacing - 1e-4f));
  const float count = float(keys.keyCount) + before + after;
  if (count <= float(RTC_MAX_TIME_STEP_COUNT)) {
    return {uint32_t(count),
        keys.begin - before * spacing,
        keys.end + after * spacing};
  }
  return {RTC_MAX_TIME_STEP_COUNT,
      std::min(0.f, keys.begin),
      std::max(1.f, keys.end)};
}

void setTimeSteps(RTCGeometry geometry, const TimeSteps &steps)
{
  rtcSetGeometryTimeStepCount(geometry, steps.count);
  if (steps.count > 1)
    rtcSetGeometryTimeRange(geometry, steps.begin, steps.end);
}

// validRay() without branches, so a packet's lanes are checked together:
// a magnitude test is false for NaN and infinities too.
int validLane(const RayHitPacket &p, int i, float range)
{
  auto usable = [range](float v) {
    return int(std::abs(v) <= range);
  };
  const int origin =
      usable(p.originX[i]) & usable(p.originY[i]) & usable(p.originZ[i]);
  const int direction = usable(p.directionX[i]) & usable(p.directionY[i])
                        & usable(p.directionZ[i]);
  const int interval = int(p.tMin[i] >= 0.f)
                       & int(p.tMin[i] <= std::numeric_limits<float>::max())
                       & int(p.tMax[i] >= p.tMin[i]);
  return -(origin & direction & interval);
}

// RayHitPacket is handed to Embree as an RTCRayHit8, so it must be one.
#define PRISM_SAME_OFFSET(ours, embree) \
  static_assert(offsetof(RayHitPacket, ours) == offsetof(RTCRayHit8, embree))
static_assert(sizeof(RayHitPacket) == sizeof(RTCRayHit8));
static_assert(alignof(RayHitPacket) >= alignof(RTCRayHit8));
static_assert(RTC_MAX_INSTANCE_LEVEL_COUNT == 1);
PRISM_SAME_OFFSET(originX, ray.org_x);
PRISM_SAME_OFFSET(tMin, ray.tnear);
PRISM_SAME_OFFSET(directionX, ray.dir_x);
PRISM_SAME_OFFSET(time, ray.time);
PRISM_SAME_OFFSET(tMax, ray.tfar);
PRISM_SAME_OFFSET(mask, ray.mask);
PRISM_SAME_OFFSET(id, ray.id);
PRISM_SAME_OFFSET(flags, ray.flags);
PRISM_SAME_OFFSET(normalX, hit.Ng_x);
PRISM_SAME_OFFSET(u, hit.u);
PRISM_SAME_OFFSET(v, hit.v);
PRISM_SAME_OFFSET(primitiveId, hit.primID);
PRISM_SAME_OFFSET(geometryId, hit.geomID);
PRISM_SAME_OFFSET(instanceId, hit.instID);
#undef PRISM_SAME_OFFSET

// The sign of (ray direction . geometric normal) of hit i: > 0 on the
// geometry's back side. Ray and normal are in the same space (the
// instance's, under instancing), and the sign of their dot product is the
// same in every space, so mirroring transforms need no care.
float facing(const RTCFilterFunctionNArguments *args, unsigned i)
{
  return RTCRayN_dir_x(args->ray, args->N, i)
             * RTCHitN_Ng_x(args->hit, args->N, i)
         + RTCRayN_dir_y(args->ray, args->N, i)
               * RTCHitN_Ng_y(args->hit, args->N, i)
         + RTCRayN_dir_z(args->ray, args->N, i)
               * RTCHitN_Ng_z(args->hit, args->N, i);
}

// Embree filter of camera and bounce rays: rejects hits on a geometry's
// back side (the ray along its geometric normal).
void rejectBackFaces(const RTCFilterFunctionNArguments *args)
{
  for (unsigned i = 0; i < args->N; i++) {
    if (args->valid[i] == -1 && facing(args, i) > 0.f) {
      args->valid[i] = 0;
      notePassed(args, i);
    }
  }
}

// Whether shadow ray i passes a single-sided face. Light runs against
// shadow rays, from the light to the shaded point: it passes a face whose
// back it meets, which is the face the shadow ray meets from the front. So
// a single-sided surface shadows only what lies behind it seen from the
// light, and light reaches exactly where the camera sees through back
// faces.
bool passesFaceLitFromBehind(
    const RTCFilterFunctionNArguments *args, unsigned i)
{
  if (!(facing(args, i) < 0.f))
    return false;
  notePassed(args, i);
  return true;
}

// Whether shadow ray i passes a see-through surface: as the trace's
// ShadowStops decides (none: it stops).
bool passesSeeThrough(const RTCFilterFunctionNArguments *args, unsigned i)
{
  const auto *context = reinterpret_cast<const TraceContext *>(args->context);
  if (!context->stops)
    return false;
  RTCRayN *ray = args->ray; // Embree's accessors take them non-const
  RTCHitN *hit = args->hit;
  const unsigned n = args->N;
  Hit h;
  h.t = RTCRayN_tfar(ray, n, i);
  h.u = RTCHitN_u(hit, n, i);
  h.v = RTCHitN_v(hit, n, i);
  h.geometricNormal = {RTCHitN_Ng_x(hit, n, i),
      RTCHitN_Ng_y(hit, n, i),
      RTCHitN_Ng_z(hit, n, i)};
  h.primitiveId = RTCHitN_primID(hit, n, i);
  h.geometryId = RTCHitN_geomID(hit, n, i);
  h.instanceId = RTCHitN_instID(hit, n, i, 0);
  return !context->stops->at(
      originOf(ray, n, i), directionOf(ray, n, i), RTCRayN_time(ray, n, i), h);
}

// Embree filters of shadow rays, by what the geometry is.
template <bool kOneSided, bool kSeeThrough>
void filterShadowRays(const RTCFilterFunctionNArguments *args)
{
  for (unsigned i = 0; i < args->N; i++) {
    if (args->valid[i] != -1)
      continue;
    if ((kOneSided && passesFaceLitFromBehind(args, i))
        || (kSeeThrough && passesSeeThrough(args, i)))
      args->valid[i] = 0;
  }
}

Hit toHit(const RTCRayHit &rh)
{
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
    return hit;
  hit.t = rh.ray.tfar;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  hit.geometricNormal = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
  hit.primitiveId = rh.hit.primID;
  hit.geometryId = rh.hit.geomID;
  hit.instanceId = rh.hit.instID[0];
  return hit;
}

RTCBuildQuality embreeQuality(Context::BuildQuality quality)
{
  switch (quality) {
  case Context::BuildQuality::Low:
    return RTC_BUILD_QUALITY_LOW;
  case Context::BuildQuality::High:
    return RTC_BUILD_QUALITY_HIGH;
  case Context::BuildQuality::Medium:
    break;
  }
  return RTC_BUILD_QUALITY_MEDIUM;
}

} // namespace

Scene::Scene(const Context &context) : m_context(context)
{
  clear();
}

Scene::~Scene()
{
  if (m_scene)
    rtcReleaseScene(m_scene);
}

void Scene::clear()
{
  if (m_scene)
    rtcReleaseScene(m_scene);
  m_rayRange = kLargestCoordinate;
  m_interpolatedVertices.clear();
  m_attached.clear();
  m_oneSided.clear();
  m_seeThrough.clear();
  m_user.clear();
  m_scene = m_context.isValid() ? rtcNewScene(m_context.handle()) : nullptr;
  if (m_scene) {
    rtcSetSceneBuildQuality(m_scene, embreeQuality(m_context.buildQuality()));
    // Watertight: without it rays through a quad's split diagonal can miss.
    rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_ROBUST);
  }
}

void Scene::addMesh(uint32_t id,
    bool quads,
    const VertexKeys &vertices,
    size_t vertexCount,
    const uint32_t *indices,
    size_t primitiveCount)
{
  if (!m_scene || vertices.positions.empty())
    return;
  RTCGeometry g = rtcNewGeometry(m_context.handle(),
      quads ? RTC_GEOMETRY_TYPE_QUAD : RTC_GEOMETRY_TYPE_TRIANGLE);
  const TimeSteps steps = timeStepsFor(vertices.timeline);
  setTimeSteps(g, steps);
  for (uint32_t step = 0; step < steps.count; step++) {
    const KeyTimeline::Position at = vertices.timeline.locate(steps.time(step));
    // Steps normally fall on keys (up to rounding); only resampled ones
    // need vertices of their own.
    const float3 *positions = vertices.positions[at.index];
    if (at.fraction > 1.f - 1e-4f) {
      positions = vertices.positions[at.index + 1];
    } else if (at.fraction >= 1e-4f) {
      const float3 *a = vertices.positions[at.index];
      const float3 *b = vertices.positions[at.index + 1];
      std::vector<float3> between(vertexCount + 1); // Embree's read padding
      for (size_t v = 0; v < vertexCount; v++)
        between[v] = a[v] * (1.f - at.fraction) + b[v] * at.fraction;
      m_interpolatedVertices.push_back(std::move(between));
      positions = m_interpolatedVertices.back().data();
    }
    rtcSetSharedGeometryBuffer(g,
        RTC_BUFFER_TYPE_VERTEX,
        step,
        RTC_FORMAT_FLOAT3,
        positions,
        0,
        sizeof(float3),
        vertexCount);
  }
  const unsigned corners = quads ? 4 : 3;
  rtcSetSharedGeometryBuffer(g,
      RTC_BUFFER_TYPE_INDEX,
      0,
      quads ? RTC_FORMAT_UINT4 : RTC_FORMAT_UINT3,
      indices,
      0,
      corners * sizeof(uint32_t),
      primitiveCount);
  attach(g, id);
}

void Scene::addTriangles(uint32_t id,
    const float3 *vertices,
    size_t vertexCount,
    const uint32_t *indices,
    size_t triangleCount)
{
  addMesh(id, false, {{vertices}, {}}, vertexCount, indices, triangleCount);
}

void Scene::addQuads(uint32_t id,
    const float3 *vertices,
    size_t vertexCount,
    const uint32_t *indices,
    size_t quadCount)
{
  addMesh(id, true, {{vertices}, {}}, vertexCount, indices, quadCount);
}

void Scene::addTriangles(uint32_t id,
    const VertexKeys &vertices,
    size_t vertexCount,
    const uint32_t *indices,
    size_t triangleCount)
{
  addMesh(id, false, vertices, vertexCount, indices, triangleCount);
}

void Scene::addQuads(uint32_t id,
    const VertexKeys &vertices,
    size_t vertexCount,
    const uint32_t *indices,
    size_t quadCount)
{
  addMesh(id, true, vertices, vertexCount, indices, quadCount);
}

void Scene::addSpheres(uint32_t id, const float4 *centerAndRadius, size_t count)
{
  if (!m_scene)
    return;
  RTCGeometry g =
      rtcNewGeometry(m_context.handle(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
  rtcSetSharedGeometryBuffer(g,
      RTC_BUFFER_TYPE_VERTEX,
      0,
      RTC_FORMAT_FLOAT4,
      centerAndRadius,
      0,
      sizeof(float4),
      count);
  attach(g, id);
}

void Scene::addRoundCurves(uint32_t id,
    const float4 *positionAndRadius,
    size_t vertexCount,
    const uint32_t *segmentStarts,
    size_t segmentCount)
{
  if (!m_scene)
    return;
  RTCGeometry g =
      rtcNewGeometry(m_context.handle(), RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  rtcSetSharedGeometryBuffer(g,
      RTC_BUFFER_TYPE_VERTEX,
      0,
      RTC_FORMAT_FLOAT4,
      positionAndRadius,
      0,
      sizeof(float4),
      vertexCount);
  rtcSetSharedGeometryBuffer(g,
      RTC_BUFFER_TYPE_INDEX,
      0,
      RTC_FORMAT_UINT,
      segmentStarts,
      0,
      sizeof(uint32_t),
      segmentCount);
  attach(g, id);
}

void Scene::addUser(uint32_t id, const UserGeometry *geometry, size_t count)
{
  if (!m_scene)
    return;
  RTCGeometry g = rtcNewGeometry(m_context.handle(), RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(g, unsigned(count));
  rtcSetGeometryUserData(g, const_cast<UserGeometry *>(geometry));
  rtcSetGeometryBoundsFunction(g, userBounds, nullptr);
  rtcSetGeometryIntersectFunction(g, userIntersect);
  rtcSetGeometryOccludedFunction(g, userOccluded<false>);
  attach(g, id);
  m_user[id] = true;
}

void Scene::addInstance(
    uint32_t id, const Scene &child, const mat3x4 &worldFromObject)
{
  if (!m_scene || !child.m_scene)
    return;
  RTCGeometry g =
      rtcNewGeometry(m_context.handle(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(g, child.m_scene);
  rtcSetGeometryTransform(
      g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, &worldFromObject);
  // The child this instance places, for moveInstance(), kept where Embree
  // keeps the instance (ten million ids need no table of their own); the
  // instance holds a reference to it, so no other scene can take its
  // address while it is placed. Moving instances leave it NULL.
  rtcSetGeometryUserData(g, child.m_scene);
  attach(g, id);
}

bool Scene::placesInstance(uint32_t id, const Scene &child) const
{
  if (!child.m_scene || !isAttached(id))
    return false;
  return rtcGetGeometryUserData(rtcGetGeometry(m_scene, id)) == child.m_scene;
}

bool Scene::moveInstance(
    uint32_t id, const Scene &child, const mat3x4 &worldFromObject)
{
  if (!placesInstance(id, child))
    return false;
  RTCGeometry g = rtcGetGeometry(m_scene, id);
  mat3x4 current;
  rtcGetGeometryTransform(g, 0.f, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, &current);
  if (std::memcmp(&current, &worldFromObject, sizeof(mat3x4)) == 0)
    return true; // not moved
  rtcSetGeometryTransform(
      g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, &worldFromObject);
  rtcCommitGeometry(g);
  // From the first move on, the scene is one that changes: Embree builds
  // it faster (RTC_SCENE_FLAG_DYNAMIC) at some cost in trace speed.
  if (!(rtcGetSceneFlags(m_scene) & RTC_SCENE_FLAG_DYNAMIC)) {
    rtcSetSceneFlags(
        m_scene, rtcGetSceneFlags(m_scene) | RTC_SCENE_FLAG_DYNAMIC);
    rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_LOW);
  }
  return true;
}

void Scene::addInstance(
    uint32_t id, const Scene &child, const MotionTransform &worldFromObject)
{
  if (!m_scene || !child.m_scene)
    return;
  RTCGeometry g =
      rtcNewGeometry(m_context.handle(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(g, child.m_scene);
  const TimeSteps steps = timeStepsFor(worldFromObject.timeline());
  setTimeSteps(g, steps);
  for (uint32_t step = 0; step < steps.count; step++) {
    const float time = steps.time(step);
    if (worldFromObject.isDecomposed()) {
      // Embree slerps the rotation between steps, as MotionTransform does.
      const MotionTransform::Decomposed d = worldFromObject.decomposedAt(time);
      RTCQuaternionDecomposition q;
      rtcInitQuaternionDecomposition(&q);
      rtcQuaternionDecompositionSetScale(&q, d.scale.x, d.scale.y, d.scale.z);
      rtcQuaternionDecompositionSetQuaternion(
          &q, d.rotation.w, d.rotation.x, d.rotation.y, d.rotation.z);
      rtcQuaternionDecompositionSetTranslation(
          &q, d.translation.x, d.translation.y, d.translation.z);
      rtcSetGeometryTransformQuaternion(g, step, &q);
    } else {
      const mat3x4 m = worldFromObject.at(time);
      rtcSetGeometryTransform(g, step, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, &m);
    }
    m_rayRange =
        std::min(m_rayRange, worldRayRange(inverse(worldFromObject.at(time))));
  }
  attach(g, id);
}

void Scene::attach(RTCGeometry geometry, uint32_t id)
{
  rtcSetGeometryBuildQuality(geometry, embreeQuality(m_context.buildQuality()));
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(m_scene, geometry, id);
  rtcReleaseGeometry(geometry);
  if (id >= m_attached.size()) {
    m_attached.resize(size_t(id) + 1, false);
    m_oneSided.resize(size_t(id) + 1, false);
    m_seeThrough.resize(size_t(id) + 1, false);
    m_user.resize(size_t(id) + 1, false);
  }
  m_attached[id] = true;
}

bool Scene::isAttached(uint32_t id) const
{
  return m_scene && id < m_attached.size() && m_attached[id];
}

void Scene::cullBackFaces(uint32_t id)
{
  // Geometry that added nothing (empty, invalid) has no Embree geometry.
  if (!isAttached(id))
    return;
  m_oneSided[id] = true;
  setFilters(id);
}

void Scene::letShadowsThrough(uint32_t id)
{
  if (!isAttached(id))
    return;
  m_seeThrough[id] = true;
  setFilters(id);
}

void Scene::setFilters(uint32_t id)
{
  RTCGeometry geometry = rtcGetGeometry(m_scene, id);
  const bool oneSided = m_oneSided[id], seeThrough = m_seeThrough[id];
  rtcSetGeometryIntersectFilterFunction(
      geometry, oneSided ? rejectBackFaces : nullptr);
  rtcSetGeometryOccludedFilterFunction(geometry,
      oneSided && seeThrough ? filterShadowRays<true, true>
      : oneSided             ? filterShadowRays<true, false>
                             : filterShadowRays<false, true>);
  // User geometry runs no filters: its occlusion test asks itself.
  if (m_user[id])
    rtcSetGeometryOccludedFunction(
        geometry, seeThrough ? userOccluded<true> : userOccluded<false>);
  rtcCommitGeometry(geometry);
}

void Scene::commit()
{
  if (m_scene)
    rtcCommitScene(m_scene);
}

box3 Scene::bounds() const
{
  if (!m_scene)
    return emptyBox3();
  RTCBounds b;
  rtcGetSceneBounds(m_scene, &b);
  if (!(b.lower_x <= b.upper_x))
    return emptyBox3();
  return {{b.lower_x, b.lower_y, b.lower_z}, {b.upper_x, b.upper_y, b.upper_z}};
}

bool Scene::intersect(const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    Hit &hit,
    float time) const
{
  hit = Hit{};
  if (!m_scene || !isTraceable(origin, direction, tMin, tMax, m_rayRange))
    return false;
  TraceContext context = plainContext(RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
  RTCRayHit rh;
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = direction.x;
  rh.ray.dir_y = direction.y;
  rh.ray.dir_z = direction.z;
  rh.ray.tnear = tMin;
  rh.ray.tfar = tMax;
  rh.ray.time = validTime(time);
  rh.ray.mask = ~0u;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(m_scene, &context.embree, &rh);
  hit = toHit(rh);
  return hit.found();
}

void Scene::confine(RayQueue &queue) const
{
  if (m_rayRange >= kLargestCoordinate)
    return; // push() already checked against Embree's own range
  for (size_t i = 0; i < queue.size(); i++) {
    const float3 origin{
        queue.m_originX[i], queue.m_originY[i], queue.m_originZ[i]};
    const float3 direction{
        queue.m_directionX[i], queue.m_directionY[i], queue.m_directionZ[i]};
    if (!isTraceable(
            origin, direction, queue.m_tMin[i], queue.m_tMax[i], m_rayRange)) {
      // As push() marks untraceable rays: an empty interval.
      queue.m_tMin[i] = 1.f;
      queue.m_tMax[i] = 0.f;
    }
  }
}

RTCRayNp Scene::streamAt(RayQueue &queue, size_t i)
{
  RTCRayNp rays;
  rays.org_x = queue.m_originX.data() + i;
  rays.org_y = queue.m_originY.data() + i;
  rays.org_z = queue.m_originZ.data() + i;
  rays.tnear = queue.m_tMin.data() + i;
  rays.dir_x = queue.m_directionX.data() + i;
  rays.dir_y = queue.m_directionY.data() + i;
  rays.dir_z = queue.m_directionZ.data() + i;
  rays.time = queue.m_time.data() + i;
  rays.tfar = queue.m_tMax.data() + i;
  rays.mask = queue.m_mask.data() + i;
  rays.id = queue.m_index.data() + i; // the filters' index, not the tag
  rays.flags = queue.m_flags.data() + i;
  return rays;
}

void Scene::intersect(RayQueue &queue) const
{
  if (!m_scene || queue.empty())
    return;
  confine(queue);
  // A tile's wavefront is one stream; a larger one (a lockstep render's
  // row of tiles) streams of a tile's size on several threads.
  forEachBlock(queue.size(), kStreamSize, [&](size_t i, size_t count) {
    TraceContext context = contextFor(queue, queue.m_passedOneSided.data());
    RTCRayHitNp rays;
    rays.ray = streamAt(queue, i);
    rays.hit.Ng_x = queue.m_normalX.data() + i;
    rays.hit.Ng_y = queue.m_normalY.data() + i;
    rays.hit.Ng_z = queue.m_normalZ.data() + i;
    rays.hit.u = queue.m_u.data() + i;
    rays.hit.v = queue.m_v.data() + i;
    rays.hit.primID = queue.m_primitiveId.data() + i;
    rays.hit.geomID = queue.m_geometryId.data() + i;
    static_assert(RTC_MAX_INSTANCE_LEVEL_COUNT == 1);
    rays.hit.instID[0] = queue.m_instanceId.data() + i;
    rtcIntersectNp(m_scene, &context.embree, &rays, unsigned(count));
  });
}

void Scene::occluded(RayQueue &queue, const ShadowStops *stops) const
{
  if (!m_scene || queue.empty())
    return;
  confine(queue);
  forEachBlock(queue.size(), kStreamSize, [&](size_t i, size_t count) {
    TraceContext context = contextFor(queue, queue.m_passedOneSided.data());
    context.stops = stops;
    RTCRayNp rays = streamAt(queue, i);
    rtcOccludedNp(m_scene, &context.embree, &rays, unsigned(count));
  });
  for (size_t i = 0; i < queue.size(); i++) {
    const float through = queue.occluded(i) ? 0.f : 1.f;
    queue.m_transmittance[i] = float3{through, through, through};
  }
}

void Scene::intersect(RayHitPacket &packet, const int active[kPacketSize]) const
{
  static_assert(kPacketSize == RayHitPacket::kLanes);
  alignas(32) int valid[kPacketSize];
  for (int i = 0; i < kPacketSize; i++) {
    packet.mask[i] = ~0u;
    packet.id[i] = unsigned(i);
    packet.flags[i] = 0;
    packet.geometryId[i] = RTC_INVALID_GEOMETRY_ID;
    packet.instanceId[i] = RTC_INVALID_GEOMETRY_ID;
    packet.time[i] = validTime(packet.time[i]);
    valid[i] = active[i] & validLane(packet, i, m_rayRange);
  }
  if (!m_scene)
    return;
  TraceContext context = plainContext(RTC_INTERSECT_CONTEXT_FLAG_COHERENT);
  rtcIntersect8(
      valid, m_scene, &context.embree, reinterpret_cast<RTCRayHit8 *>(&packet));
}

} // namespace prism::rt
