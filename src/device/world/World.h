// ANARIWorld: everything a frame renders (spec 5.4). Its Embree scene holds
// one Embree instance per placement of every instance, plus one identity
// placement of an implicit group for surfaces placed in the world directly.
#pragma once

#include "../light/EmissiveSurface.h"
#include "../light/Light.h"
#include "../light/LightSelector.h"
#include "../light/PlacedLight.h"
#include "../rt/RayQueue.h"
#include "../rt/Scene.h"
#include "Group.h"
#include "Instance.h"
#include "PlacedVolume.h"

#include <memory>
#include <vector>

namespace prism {

class World : public Object
{
 public:
  explicit World(DeviceState &device);
  ~World() override;

  // One placed group: what an Embree instance id stands for. There may be
  // ten million, so a placement keeps 16 bytes: its group, transform and
  // id are read from the instance that holds them, and the transform is
  // inverted where a hit needs it.
  class Placement
  {
   public:
    // The world's own surfaces, placed where they are.
    explicit Placement(const Group *worldGroup)
        : m_worldGroup(worldGroup),
          m_index(0),
          m_identity(true),
          m_byInstance(false)
    {}
    Placement(const Instance *instance, uint32_t index, bool identity)
        : m_instance(instance),
          m_index(index),
          m_identity(identity),
          m_byInstance(true)
    {}

    const Group *group() const
    {
      return m_byInstance ? m_instance->group() : m_worldGroup;
    }
    // NULL for surfaces placed in the world.
    const Instance *instance() const
    {
      return m_byInstance ? m_instance : nullptr;
    }
    // The user's id (~0u when unset).
    uint32_t instanceId() const
    {
      return m_byInstance ? m_instance->id(m_index) : ~0u;
    }
    // At the shutter midpoint for a moving instance.
    mat3x4 worldFromObject() const
    {
      return m_byInstance ? m_instance->worldFromObject(m_index)
                          : kIdentityMat3x4;
    }
    // Keys of a moving instance, or NULL.
    const MotionTransform *motion() const
    {
      return m_byInstance ? m_instance->motion() : nullptr;
    }
    // objectFromWorld at `time`, in the shutter's [0, 1].
    mat3x4 objectFromWorldAt(float time) const
    {
      const MotionTransform *keys = motion();
      return inverse(keys ? keys->at(time) : worldFromObject());
    }
    // worldFromObject is the identity (skip transforms).
    bool identity() const
    {
      return m_identity;
    }
    // Whether both place by the same instance's same transform.
    bool samePlacer(const Placement &other) const
    {
      return m_byInstance == other.m_byInstance && m_index == other.m_index
             && (m_byInstance ? m_instance == other.m_instance
                              : m_worldGroup == other.m_worldGroup);
    }

   private:
    union
    {
      const Instance *m_instance;
      const Group *m_worldGroup;
    };
    uint32_t m_index; // among the instance's transforms
    bool m_identity;
    bool m_byInstance;
  };
  static_assert(sizeof(Placement) <= 16, "a placement per instance");

  const Placement &placement(uint32_t instanceId) const
  {
    return m_placements[instanceId];
  }
  uint32_t placementCount() const
  {
    return uint32_t(m_placements.size());
  }
  // The closest hit at `time` (in the shutter's [0, 1]); instanceId names
  // the placement (see placement()).
  bool intersect(const float3 &origin,
      const float3 &direction,
      float tMin,
      float tMax,
      rt::Hit &hit,
      float time) const;
  // Every ray of the queue: closest hits (instanceId as above), or only
  // whether something blocks each (`stops` deciding at see-through
  // surfaces; without it they block).
  void intersect(rt::RayQueue &queue) const;
  void occluded(
      rt::RayQueue &queue, const rt::ShadowStops *stops = nullptr) const;
  // The packet's active lanes traced in place (see rt::Scene); instance
  // ids name placements, as above.
  void intersect(
      rt::RayHitPacket &packet, const int active[rt::kPacketSize]) const;
  box3 bounds() const
  {
    return m_bounds;
  }
  // Every valid light, placed in world space (world lights and the lights
  // of every instanced group).
  const std::vector<std::unique_ptr<PlacedLight>> &lights() const
  {
    return m_placedLights;
  }
  // The index in lights() of the light that samples surface `geometryId`
  // of placement `instanceId` (an emissive surface), or -1 if none does.
  int32_t emitterLight(uint32_t instanceId, uint32_t geometryId) const
  {
    if (instanceId >= m_emitterLights.size())
      return -1;
    const std::vector<int32_t> &ofPlacement = m_emitterLights[instanceId];
    return geometryId < ofPlacement.size() ? ofPlacement[geometryId] : -1;
  }
  // The lights a ray can reach (PlacedLight::reachableByRays()), so rays
  // need not ask every emissive surface, each with where it can be found.
  struct ReachableLight
  {
    uint32_t index; // in lights()
    bool bounded;   // false: at infinity, asked by every ray
    LightBounds bounds;
  };
  const std::vector<ReachableLight> &lightsReachableByRays() const
  {
    return m_reachableLights;
  }
  // Every placement of every valid, visible volume.
  const std::vector<PlacedVolume> &volumes() const
  {
    return m_placedVolumes;
  }
  // A hash of the lights the world declares (its own, and its instances'
  // groups' at each placement; emissive surfaces aside): each light's
  // contentHash() and where it is placed. Kept until the world changes;
  // call it like Object::contentHash().
  uint64_t declaredLightsHash() const;
  // Chooses among lights() for next-event estimation.
  const LightSelector &lightSelector() const
  {
    return m_lightSelector;
  }
  // How many lights() the world declares (its own and its instances'
  // groups', at each placement; while sharing lights, every process's):
  // the first ones of lights().
  size_t declaredLightCount() const
  {
    return m_declaredLightCount;
  }
  // A light this world declares itself, as placed: the light and where.
  struct DeclaredLight
  {
    const Light *light;
    mat3x4 worldFromObject;
  };
  // This world's own declared lights, in their order in lights() when not
  // sharing (every valid light placed, at each placement).
  const std::vector<DeclaredLight> &ownDeclaredLights() const
  {
    return m_ownDeclaredSources;
  }
  // The emissive surfaces this world placed itself (after the declared
  // ones in lights(), unless shared, below), in placement order.
  size_t ownEmitterCount() const
  {
    return m_sharesEmitters ? m_ownEmitters.size()
                            : m_placedLights.size() - m_declaredLightCount;
  }
  const EmissiveSurface &ownEmitter(size_t index) const
  {
    const PlacedLight &light =
        m_sharesEmitters ? *m_ownEmitters[index]
                         : *m_placedLights[m_declaredLightCount + index];
    return static_cast<const EmissiveSurface &>(light);
  }
  // For a data-parallel device whose processes each hold part of a scene:
  // `emitters` (every process's, in one order the same on every process)
  // follow the declared lights in lights() instead of this world's own,
  // which are emitters[firstOwn ...] (emitterLight() then names those);
  // the light selector weighs lights at infinity by `sceneRadius`, the
  // radius of every process's world together. Until keepOwnEmitters() or
  // the next finalize().
  void shareEmitters(std::vector<std::unique_ptr<PlacedLight>> emitters,
      size_t firstOwn,
      float sceneRadius);
  // As shareEmitters(), and `declared` (every process's declared lights,
  // the same on every process) stand in lights() for this world's own
  // declared lights too.
  void shareLights(std::vector<std::unique_ptr<PlacedLight>> declared,
      std::vector<std::unique_ptr<PlacedLight>> emitters,
      size_t firstOwn,
      float sceneRadius);
  // Only `declared` in place of the world's own declared lights; its own
  // emitters stay (their indices follow the declared lights).
  void shareDeclaredLights(
      std::vector<std::unique_ptr<PlacedLight>> declared, float sceneRadius);
  // Back to the world's own declared lights and emitters.
  void keepOwnEmitters();
  bool sharesEmitters() const
  {
    return m_sharesEmitters;
  }
  // Whether shareLights() or shareDeclaredLights() put other declared
  // lights in place of its own.
  bool sharesDeclaredLights() const
  {
    return m_sharesDeclared;
  }
  // What the light selector takes for the radius of a scene of `bounds`.
  static float sceneRadius(const box3 &bounds);
  void finalize() override;
  void dropReferences() override;
  bool getProperty(const std::string &name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;

 protected:
  void commitParameters() override;

 private:
  std::vector<Object *> readObjects(const char *name);
  // Adds a light for every surface with constant emission.
  void placeEmitters();
  // Places the volumes of every placed group.
  void placeVolumes();
  // Moves the Embree instances whose transform changed since `previous`
  // (the placements the scene was built for) and keeps the rest; false
  // (the scene then needs rebuildScene()) when more than transforms
  // changed.
  bool moveInstancesInPlace(const std::vector<Placement> &previous);
  // The top-level scene from m_placements, every instance anew.
  void rebuildScene();
  // The lights rays can reach and light selection, from m_placedLights.
  void indexLights(float sceneRadius);
  // Moves every emitterLight() index by `shift`.
  void shiftEmitterIndices(int32_t shift);
  // shareEmitters(), and shareLights() when `declared` is not NULL.
  void share(std::vector<std::unique_ptr<PlacedLight>> *declared,
      std::vector<std::unique_ptr<PlacedLight>> emitters,
      size_t firstOwn,
      float sceneRadius);

  std::vector<const Instance *> m_instances;
  Group *m_implicitGroup; // an internal object, never seen by the API
  std::vector<Object *> m_lights;
  std::vector<Placement> m_placements;
  // The smallest rt::worldRayRange() over the placements.
  float m_placementRayRange{rt::kLargestCoordinate};
  std::vector<std::unique_ptr<PlacedLight>> m_placedLights;
  LightSelector m_lightSelector;
  // Per placement, per geometry id: see emitterLight(). Empty in a world
  // without emitters (a vector per placement of ten million would not be).
  std::vector<std::vector<int32_t>> m_emitterLights;
  size_t m_declaredLightCount{0};
  // While sharing emitters: this world's own, out of lights(), and where
  // they are among the shared ones.
  bool m_sharesEmitters{false};
  std::vector<std::unique_ptr<PlacedLight>> m_ownEmitters;
  // How far emitterLight()'s indices moved while sharing.
  int32_t m_emitterShift{0};
  // While sharing declared lights: this world's own, out of lights().
  bool m_sharesDeclared{false};
  std::vector<std::unique_ptr<PlacedLight>> m_ownDeclared;
  std::vector<DeclaredLight> m_ownDeclaredSources;
  std::vector<ReachableLight> m_reachableLights;
  std::vector<PlacedVolume> m_placedVolumes;
  std::unique_ptr<rt::Scene> m_scene;
  // A world of one untransformed placement traces its group's scene
  // directly: no instance level, the most common case for simple scenes.
  const rt::Scene *m_traced{nullptr};
  box3 m_bounds;
  mutable uint64_t m_lightsHashEpoch{~0ull};
  mutable uint64_t m_lightsHash{0};
};

} // namespace prism
