// A ResolvedScene's surfaces and lights as an ANARI world on one device,
// kept between renders: each update compares the scene with the last one
// and creates, sets and commits only the ANARI objects whose data changed,
// so a live edit touches what it edits. One Group per (geometry, shader),
// one Instance per placement.
#pragma once

#include "GeometryBuilder.h"
#include "ResolvedScene.h"

#include <anari/anari.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace prism::nsi {

struct AnariWorld
{
  ANARIWorld world{nullptr}; // owned by the builder
  // Ambient light, which ANARI puts on the renderer rather than the world.
  std::array<float, 3> ambientColor{1, 1, 1};
  float ambientRadiance{0};
  // What camera rays that miss see: a uniform environment visible to the
  // camera shows as its colour; else black.
  std::array<float, 4> background{0, 0, 0, 1};
};

// What one update did to the ANARI objects, per category.
struct AnariUpdateCounts
{
  enum Category {
    Geometry,
    Material,
    Surface,
    Group,
    Instance,
    Light,
    Volume,
    World,
    CategoryCount
  };
  std::array<unsigned, CategoryCount> created{}, committed{}, released{};
  // "created geometry 0 material 0 … committed … released …".
  std::string summary() const;
};

class AnariWorldBuilder
{
 public:
  // `vertexMotion`: the device deforms triangles over the shutter
  // (KHR_GEOMETRY_TRIANGLE_MOTION_DEFORMATION); else moving meshes render
  // their first key, warned about.
  AnariWorldBuilder(
      ANARIDevice device, ReportFunction report, bool vertexMotion = true);
  ~AnariWorldBuilder();
  AnariWorldBuilder(const AnariWorldBuilder &) = delete;
  AnariWorldBuilder &operator=(const AnariWorldBuilder &) = delete;

  // Brings the world in line with `scene`; the world handle stays the same.
  AnariWorld update(const ResolvedScene &scene);
  const AnariUpdateCounts &lastUpdate() const
  {
    return m_counts;
  }

 private:
  using Category = AnariUpdateCounts::Category;
  void commit(Category category, ANARIObject object);
  void release(Category category, ANARIObject object);
  ANARIGeometry geometry(const std::string &handle, const GeometryData &data);
  // `key` is set to the material's key.
  ANARIMaterial material(const SurfaceItem &item, std::string &key);
  // The group and its one surface.
  ANARIGroup group(
      const std::string &key, ANARIGeometry geometry, ANARIMaterial material);
  ANARIInstance instance(
      const std::string &key, ANARIGroup group, const Placement &placement);
  ANARILight light(size_t index, const LightItem &item);
  // The group of a volume item's one volume; null when its file failed.
  ANARIGroup volumeGroup(const std::string &key, const VolumeItem &item);
  template <typename Record>
  void releaseUnused(std::map<std::string, Record> &records, Category category);

  template <typename Handle, typename Data>
  struct Entry
  {
    Handle handle{nullptr};
    Data data;
    bool used{false};
  };
  struct SurfaceData
  {
    ANARISurface surface{nullptr};
    ANARIGeometry geometry{nullptr};
    ANARIMaterial material{nullptr};
  };

  ANARIDevice m_device;
  ReportFunction m_report;
  bool m_vertexMotion{true};
  AnariUpdateCounts m_counts;
  std::map<std::string, Entry<ANARIGeometry, GeometryData>> m_geometries;
  std::map<std::string, Entry<ANARIMaterial, ShaderDescription>> m_materials;
  std::map<std::string, Entry<ANARIGroup, SurfaceData>> m_groups;
  std::map<std::string, Entry<ANARIInstance, Placement>> m_instances;
  std::map<std::string, Entry<ANARILight, LightItem>> m_lights;
  struct VolumeData
  {
    VolumeItem item; // without its placements
    ANARIVolume volume{nullptr};
  };
  std::map<std::string, Entry<ANARIGroup, VolumeData>> m_volumes;
  ANARIWorld m_world{nullptr};
  std::vector<ANARIInstance> m_worldInstances;
  std::vector<ANARILight> m_worldLights;
};

} // namespace prism::nsi
