#include "World.h"

#include "../array/Array.h"
#include "../light/EmissiveSurface.h"
#include "../light/Light.h"
#include "../material/Material.h"
#include "../object/DeviceState.h"
#include "../rt/Context.h"
#include "../rt/RayValidity.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace prism {
namespace {

// `shape` moved into world space. Spheres keep their shape only under
// similarity transforms; under others they are left out (rays still find
// them).
EmitterShape placedEmitterShape(
    const EmitterShape &shape, const mat3x4 &worldFromObject)
{
  EmitterShape out;
  out.triangles.reserve(shape.triangles.size());
  for (const float3 &p : shape.triangles)
    out.triangles.push_back(transformPoint(worldFromObject, p));
  const float3 *axes = worldFromObject.col;
  const float scale = length(axes[0]);
  const float tolerance = 1e-4f * scale;
  const bool similarity =
      std::abs(length(axes[1]) - scale) <= tolerance
      && std::abs(length(axes[2]) - scale) <= tolerance
      && std::abs(dot(axes[0], axes[1])) <= tolerance * scale
      && std::abs(dot(axes[1], axes[2])) <= tolerance * scale
      && std::abs(dot(axes[0], axes[2])) <= tolerance * scale;
  if (similarity) {
    for (const float4 &s : shape.spheres) {
      const float3 c = transformPoint(worldFromObject, float3{s.x, s.y, s.z});
      out.spheres.push_back(float4{c.x, c.y, c.z, s.w * scale});
    }
  }
  return out;
}

// Whether rays can find a group placed by `worldFromObject`: its `bounds`
// must lie within `range`, the placement's rt::worldRayRange() (the range
// that Embree, moving rays into the group's space, can trace there).
// Transforms with huge or tiny (but finite) entries fail this; rays would
// overflow inside Embree.
bool isTraceablePlacement(
    const box3 &bounds, const mat3x4 &worldFromObject, float range)
{
  if (!(range > 0.f))
    return false;
  for (int corner = 0; corner < 8; corner++) {
    const float3 p{corner & 1 ? bounds.upper.x : bounds.lower.x,
        corner & 2 ? bounds.upper.y : bounds.lower.y,
        corner & 4 ? bounds.upper.z : bounds.lower.z};
    const float3 placed = transformPoint(worldFromObject, p);
    if (!(std::abs(placed.x) <= range && std::abs(placed.y) <= range
            && std::abs(placed.z) <= range))
      return false;
  }
  return true;
}

} // namespace

World::World(DeviceState &device)
    : Object(device, ANARI_WORLD, ""),
      m_implicitGroup(new Group(device)),
      m_scene(std::make_unique<rt::Scene>(device.rtContext())),
      m_bounds(emptyBox3())
{}

World::~World()
{
  if (m_implicitGroup)
    m_implicitGroup->releaseInternal();
}

void World::dropReferences()
{
  Object::dropReferences();
  m_traced = nullptr;
  m_instances.clear();
  m_placements.clear();
  m_placedLights.clear();
  m_emitterLights.clear();
  m_reachableLights.clear();
  m_ownEmitters.clear();
  m_sharesEmitters = false;
  m_declaredLightCount = 0;
  if (m_implicitGroup)
    m_implicitGroup->setSurfaces({});
}

std::vector<Object *> World::readObjects(const char *name)
{
  auto *array = (const Array *)readObject(name, {ANARI_ARRAY1D});
  if (!array)
    return {};
  auto objects = array->objects();
  for (Object *object : objects)
    dependOn(object);
  return objects;
}

void World::commitParameters()
{
  m_instances.clear();
  for (Object *object : readObjects("instance")) {
    auto *instance = dynamic_cast<const Instance *>(object);
    if (object && !instance)
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'instance' array holds a %s; it is skipped",
          object->describe().c_str());
    if (instance)
      m_instances.push_back(instance);
  }
  m_implicitGroup->setSurfaces(readObjects("surface"));
  m_implicitGroup->setVolumes(readObjects("volume"));
  m_lights = readObjects("light");
}

void World::finalize()
{
  m_implicitGroup->finalize();
  m_placedLights.clear();
  m_ownEmitters.clear();
  m_sharesEmitters = false;
  m_emitterShift = 0;
  m_ownDeclared.clear();
  m_sharesDeclared = false;
  m_ownDeclaredSources.clear();
  auto placeLights = [&](const std::vector<Object *> &lights,
                         const mat3x4 &transform) {
    for (Object *object : lights) {
      auto *light = dynamic_cast<const Light *>(object);
      if (light && light->isValid()) {
        if (auto placed = light->place(transform)) {
          m_placedLights.push_back(std::move(placed));
          m_ownDeclaredSources.push_back({light, transform});
        }
      }
    }
  };
  placeLights(m_lights, kIdentityMat3x4);
  for (const Instance *instance : m_instances) {
    if (!instance->isValid() || instance->group()->lights().empty())
      continue;
    for (size_t i = 0; i < instance->placementCount(); i++)
      placeLights(instance->group()->lights(), instance->worldFromObject(i));
  }
  m_declaredLightCount = m_placedLights.size();
  std::vector<Placement> previous;
  previous.swap(m_placements);
  m_placementRayRange = rt::kLargestCoordinate;
  auto place = [&](const Group *group,
                   const Instance *instance,
                   uint32_t index) {
    const mat3x4 transform =
        instance ? instance->worldFromObject(index) : kIdentityMat3x4;
    const mat3x4 objectFromWorld = inverse(transform);
    bool invertible = true;
    for (const float3 &c : objectFromWorld.col)
      invertible &=
          std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
    for (const float3 &c : transform.col)
      invertible &=
          std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
    // Surfaces placed in the world directly have no instance to name.
    const Object &placer = instance ? *(const Object *)instance : *this;
    if (!invertible) {
      placer.report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "a transform is not invertible (or not finite); that placement is "
          "skipped");
      return;
    }
    const float range = rt::worldRayRange(objectFromWorld);
    if (!isTraceablePlacement(group->bounds(), transform, range)) {
      placer.report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "a transform moves its group (or rays into it) beyond the range "
          "rays can be traced in (coordinates up to %g); that placement is "
          "skipped",
          double(rt::kLargestCoordinate));
      return;
    }
    m_placementRayRange = std::min(m_placementRayRange, range);
    if (!instance) {
      m_placements.emplace_back(group);
      return;
    }
    const bool identity =
        !instance->motion()
        && std::memcmp(&transform, &kIdentityMat3x4, sizeof(mat3x4)) == 0;
    m_placements.emplace_back(instance, index, identity);
  };
  size_t placements = 1;
  for (const Instance *instance : m_instances)
    placements += instance->placementCount();
  m_placements.reserve(placements);
  if (!isEmpty(m_implicitGroup->bounds()))
    place(m_implicitGroup, nullptr, 0);
  for (const Instance *instance : m_instances) {
    if (!instance->isValid() || isEmpty(instance->group()->bounds()))
      continue;
    for (size_t i = 0; i < instance->placementCount(); i++)
      place(instance->group(), instance, uint32_t(i));
  }
  if (!moveInstancesInPlace(previous))
    rebuildScene();
  m_scene->commit();
  m_bounds = m_scene->bounds();
  placeVolumes();
  const bool single = m_placements.size() == 1 && m_placements[0].identity();
  m_traced = single ? &m_placements[0].group()->scene() : m_scene.get();
  placeEmitters();
  indexLights(sceneRadius(m_bounds));
}

bool World::moveInstancesInPlace(const std::vector<Placement> &previous)
{
  // The same instances' placements in the same order, none moving over the
  // shutter: only transforms changed. (Ids are read at hits.)
  if (previous.size() != m_placements.size() || m_placements.empty())
    return false;
  // The rays' range follows the placements as they are now, lower or
  // higher (it bounds rays, not the BVH).
  m_scene->setRayRange(m_placementRayRange);
  for (size_t i = 0; i < m_placements.size(); i++) {
    if (!m_placements[i].samePlacer(previous[i]) || m_placements[i].motion())
      return false;
  }
  // Each placement to its transform (unchanged ones are left alone); an
  // instance given another group, a group rebuilt since, or one that
  // moved over the shutter before is caught here: a full rebuild follows.
  for (size_t i = 0; i < m_placements.size(); i++) {
    const Placement &now = m_placements[i];
    if (!m_scene->moveInstance(
            uint32_t(i), now.group()->scene(), now.worldFromObject()))
      return false;
  }
  return true;
}

void World::rebuildScene()
{
  m_scene->clear();
  m_scene->setRayRange(m_placementRayRange);
  for (size_t i = 0; i < m_placements.size(); i++) {
    const Placement &p = m_placements[i];
    if (const MotionTransform *keys = p.motion())
      m_scene->addInstance(uint32_t(i), p.group()->scene(), *keys);
    else
      m_scene->addInstance(
          uint32_t(i), p.group()->scene(), p.worldFromObject());
  }
}

void World::indexLights(float radius)
{
  m_reachableLights.clear();
  for (size_t i = 0; i < m_placedLights.size(); i++) {
    const PlacedLight &light = *m_placedLights[i];
    if (light.reachableByRays()) {
      ReachableLight reachable{uint32_t(i), false, {}};
      reachable.bounded = light.bounds(reachable.bounds);
      m_reachableLights.push_back(reachable);
    }
  }
  m_lightSelector.build(m_placedLights, radius);
}

float World::sceneRadius(const box3 &bounds)
{
  return isEmpty(bounds) ? 1.f : 0.5f * length(bounds.upper - bounds.lower);
}

void World::shareEmitters(std::vector<std::unique_ptr<PlacedLight>> emitters,
    size_t firstOwn,
    float radius)
{
  share(nullptr, std::move(emitters), firstOwn, radius);
}

void World::shareLights(std::vector<std::unique_ptr<PlacedLight>> declared,
    std::vector<std::unique_ptr<PlacedLight>> emitters,
    size_t firstOwn,
    float radius)
{
  share(&declared, std::move(emitters), firstOwn, radius);
}

void World::share(std::vector<std::unique_ptr<PlacedLight>> *declared,
    std::vector<std::unique_ptr<PlacedLight>> emitters,
    size_t firstOwn,
    float radius)
{
  keepOwnEmitters();
  const size_t own = m_placedLights.size() - m_declaredLightCount;
  if (firstOwn + own > emitters.size())
    return; // not this world's emitters among them: keep its own
  for (size_t i = m_declaredLightCount; i < m_placedLights.size(); i++)
    m_ownEmitters.push_back(std::move(m_placedLights[i]));
  m_placedLights.resize(m_declaredLightCount);
  if (declared) {
    m_ownDeclared = std::move(m_placedLights);
    m_placedLights = std::move(*declared);
    m_sharesDeclared = true;
  }
  // The own emitters' indices follow the declared lights, then the
  // emitters of the processes before this one.
  m_emitterShift = int32_t(m_placedLights.size())
                   - int32_t(m_declaredLightCount) + int32_t(firstOwn);
  m_declaredLightCount = m_placedLights.size();
  for (auto &emitter : emitters)
    m_placedLights.push_back(std::move(emitter));
  shiftEmitterIndices(m_emitterShift);
  m_sharesEmitters = true;
  indexLights(radius);
}

void World::shiftEmitterIndices(int32_t shift)
{
  for (auto &ofPlacement : m_emitterLights) {
    for (int32_t &index : ofPlacement)
      index = index >= 0 ? index + shift : index;
  }
}

void World::shareDeclaredLights(
    std::vector<std::unique_ptr<PlacedLight>> declared, float radius)
{
  keepOwnEmitters();
  std::vector<std::unique_ptr<PlacedLight>> emitters;
  for (size_t i = m_declaredLightCount; i < m_placedLights.size(); i++)
    emitters.push_back(std::move(m_placedLights[i]));
  m_placedLights.resize(m_declaredLightCount);
  m_ownDeclared = std::move(m_placedLights);
  m_placedLights = std::move(declared);
  m_emitterShift =
      int32_t(m_placedLights.size()) - int32_t(m_declaredLightCount);
  m_declaredLightCount = m_placedLights.size();
  for (auto &emitter : emitters)
    m_placedLights.push_back(std::move(emitter));
  shiftEmitterIndices(m_emitterShift);
  m_sharesDeclared = true;
  indexLights(radius);
}

void World::keepOwnEmitters()
{
  if (!m_sharesEmitters && !m_sharesDeclared)
    return;
  std::vector<std::unique_ptr<PlacedLight>> emitters;
  if (m_sharesEmitters) {
    emitters = std::move(m_ownEmitters);
    m_ownEmitters.clear();
  } else {
    for (size_t i = m_declaredLightCount; i < m_placedLights.size(); i++)
      emitters.push_back(std::move(m_placedLights[i]));
  }
  m_placedLights.resize(m_declaredLightCount);
  if (m_sharesDeclared) {
    m_placedLights = std::move(m_ownDeclared);
    m_ownDeclared.clear();
  }
  m_declaredLightCount = m_placedLights.size();
  for (auto &emitter : emitters)
    m_placedLights.push_back(std::move(emitter));
  shiftEmitterIndices(-m_emitterShift);
  m_emitterShift = 0;
  m_sharesEmitters = false;
  m_sharesDeclared = false;
  indexLights(sceneRadius(m_bounds));
}

uint64_t World::declaredLightsHash() const
{
  if (m_lightsHashEpoch == epoch())
    return m_lightsHash;
  ContentHash hash;
  auto addLights = [&](const std::vector<Object *> &lights) {
    for (const Object *light : lights)
      hash.add(light ? light->contentHash() : 0);
  };
  addLights(m_lights);
  for (const Instance *instance : m_instances) {
    if (!instance->isValid() || instance->group()->lights().empty())
      continue;
    for (size_t i = 0; i < instance->placementCount(); i++) {
      const mat3x4 worldFromObject = instance->worldFromObject(i);
      hash.add(&worldFromObject, sizeof(mat3x4));
      addLights(instance->group()->lights());
    }
  }
  m_lightsHash = hash.value();
  m_lightsHashEpoch = epoch();
  return m_lightsHash;
}

void World::placeVolumes()
{
  m_placedVolumes.clear();
  auto place = [&](const Group &group,
                   const mat3x4 &worldFromObject,
                   uint32_t instanceId) {
    const mat3x4 objectFromWorld = inverse(worldFromObject);
    for (const float3 &c : objectFromWorld.col) {
      if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
        return; // reported with the group's surfaces, or harmless
    }
    for (const Volume *volume : group.volumes()) {
      const box3 b = volume->bounds();
      box3 world = emptyBox3();
      for (int corner = 0; corner < 8; corner++) {
        world = extend(world,
            transformPoint(worldFromObject,
                {corner & 1 ? b.upper.x : b.lower.x,
                    corner & 2 ? b.upper.y : b.lower.y,
                    corner & 4 ? b.upper.z : b.lower.z}));
      }
      m_placedVolumes.push_back({volume, objectFromWorld, world, instanceId});
      m_bounds = extend(m_bounds, world);
    }
  };
  place(*m_implicitGroup, kIdentityMat3x4, ~0u);
  for (const Instance *instance : m_instances) {
    if (!instance->isValid() || instance->group()->volumes().empty())
      continue;
    // A moving instance's volumes stay where the shutter's middle puts
    // them.
    for (size_t i = 0; i < instance->placementCount(); i++) {
      place(*instance->group(), instance->worldFromObject(i), instance->id(i));
    }
  }
}

void World::placeEmitters()
{
  // Beyond these, further emissive surfaces are found by rays alone: each
  // placement of a surface copies its primitives, and light selection
  // grows with the number of lights.
  constexpr size_t kMaxEmitters = 1u << 16;
  constexpr size_t kMaxEmitterPrimitives = 1u << 22;
  size_t emitters = 0, primitives = 0;
  std::vector<std::vector<int32_t>>().swap(m_emitterLights);
  for (size_t p = 0; p < m_placements.size(); p++) {
    const Placement &placement = m_placements[p];
    // Moving instances' emitters are found by rays alone.
    if (placement.motion())
      continue;
    const Group &group = *placement.group();
    for (uint32_t g = 0; g < group.surfaceCount(); g++) {
      // A surface recommitted since its group was (the group refreshes
      // before the frame renders) may have lost its geometry or material.
      const Surface *surface = group.surface(g);
      float3 radiance;
      if (!surface || !surface->isValid()
          || !surface->material()->constantEmission(radiance))
        continue;
      if (emitters >= kMaxEmitters
          || primitives + surface->geometry()->primitiveCount()
                 > kMaxEmitterPrimitives)
        continue;
      EmitterShape shape;
      surface->geometry()->appendEmitterShape(shape);
      if (!placement.identity())
        shape = placedEmitterShape(shape, placement.worldFromObject());
      auto light =
          std::make_unique<EmissiveSurface>(std::move(shape), radiance);
      if (light->isEmpty())
        continue;
      emitters++;
      primitives += light->primitiveCount();
      if (m_emitterLights.empty())
        m_emitterLights.resize(m_placements.size());
      m_emitterLights[p].resize(group.surfaceCount(), -1);
      m_emitterLights[p][g] = int32_t(m_placedLights.size());
      m_placedLights.push_back(std::move(light));
    }
  }
}

bool World::intersect(const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    rt::Hit &hit,
    float time) const
{
  if (!m_traced
      || !m_traced->intersect(origin, direction, tMin, tMax, hit, time))
    return false;
  if (m_traced != m_scene.get())
    hit.instanceId = 0;
  return true;
}

void World::intersect(rt::RayQueue &queue) const
{
  if (!m_traced)
    return;
  m_traced->intersect(queue);
  // Hits in a group's scene traced directly: the one placement.
  if (m_traced != m_scene.get())
    queue.assignInstance(0);
}

void World::occluded(rt::RayQueue &queue, const rt::ShadowStops *stops) const
{
  if (m_traced)
    m_traced->occluded(queue, stops);
}

void World::intersect(
    rt::RayHitPacket &packet, const int active[rt::kPacketSize]) const
{
  if (!m_traced) {
    for (int i = 0; i < rt::kPacketSize; i++)
      packet.geometryId[i] = rt::kInvalidId;
    return;
  }
  m_traced->intersect(packet, active);
  if (m_traced != m_scene.get()) {
    // The group's scene traced directly: every hit is placement 0.
    for (int i = 0; i < rt::kPacketSize; i++)
      packet.instanceId[i] = 0;
  }
}

bool World::getProperty(const std::string &name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (name == "bounds" && type == ANARI_FLOAT32_BOX3 && mem
      && size >= sizeof(box3) && !isEmpty(m_bounds)) {
    std::memcpy(mem, &m_bounds, sizeof(box3));
    return true;
  }
  // Embree's memory for the whole device (every world's BVHs), now and at
  // its peak: what the big-scene benchmark sets against raw Embree's.
  if ((name == "prism.embreeBytes" || name == "prism.embreePeakBytes")
      && type == ANARI_UINT64 && mem && size >= sizeof(uint64_t)) {
    const rt::Context &context = device().rtContext();
    const int64_t bytes = name == "prism.embreeBytes"
                              ? context.embreeBytes()
                              : context.embreePeakBytes();
    const uint64_t value = uint64_t(std::max<int64_t>(bytes, 0));
    std::memcpy(mem, &value, sizeof(value));
    return true;
  }
  return Object::getProperty(name, type, mem, size, mask);
}

} // namespace prism
