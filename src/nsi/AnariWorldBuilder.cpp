#include "AnariWorldBuilder.h"

#include "ImageIO.h"
#include "VolumeBuilder.h"

#include <anari/frontend/type_utility.h>

#include <cstring>
#include <type_traits>

namespace prism::nsi {

namespace {

template <typename T>
ANARIArray1D newArray(
    ANARIDevice device, ANARIDataType type, const T *data, size_t count)
{
  ANARIArray1D array =
      anariNewArray1D(device, nullptr, nullptr, nullptr, type, count);
  void *mapped = anariMapArray(device, array);
  if (mapped)
    std::memcpy(mapped, data, count * anari::sizeOf(type));
  anariUnmapArray(device, array);
  return array;
}

void setArray(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIArray1D array)
{
  anariSetParameter(device, object, name, ANARI_ARRAY1D, &array);
  anariRelease(device, array);
}

void setFloat(
    ANARIDevice device, ANARIObject object, const char *name, float value)
{
  anariSetParameter(device, object, name, ANARI_FLOAT32, &value);
}

void setVec3(ANARIDevice device,
    ANARIObject object,
    const char *name,
    const std::array<float, 3> &v)
{
  anariSetParameter(device, object, name, ANARI_FLOAT32_VEC3, v.data());
}

void setString(
    ANARIDevice device, ANARIObject object, const char *name, const char *value)
{
  anariSetParameter(device, object, name, ANARI_STRING, value);
}

const char *geometrySubtype(const GeometryData &data)
{
  return data.spheres ? "sphere" : (data.curves ? "curve" : "triangle");
}

// Keys as an array of arrays, one FLOAT32_VEC3 array each.
ANARIArray1D newKeyArray(
    ANARIDevice device, const std::vector<std::vector<float>> &keys)
{
  std::vector<ANARIArray1D> arrays;
  for (const auto &key : keys)
    arrays.push_back(
        newArray(device, ANARI_FLOAT32_VEC3, key.data(), key.size() / 3));
  ANARIArray1D out =
      newArray(device, ANARI_ARRAY1D, arrays.data(), arrays.size());
  for (ANARIArray1D array : arrays)
    anariRelease(device, array); // the outer array holds them
  return out;
}

// Deforming triangles: motion.vertex.* keys over the shutter, which the
// camera maps to [0, 1]; unset when they stopped moving.
void setVertexMotion(
    ANARIDevice device, ANARIGeometry geometry, const GeometryData &data)
{
  if (data.positionKeys.size() < 2) {
    for (const char *name :
        {"motion.vertex.position", "motion.vertex.normal", "time"})
      anariUnsetParameter(device, geometry, name);
    return;
  }
  setArray(device,
      geometry,
      "motion.vertex.position",
      newKeyArray(device, data.positionKeys));
  if (data.normalKeys.size() > 1)
    setArray(device,
        geometry,
        "motion.vertex.normal",
        newKeyArray(device, data.normalKeys));
  else
    anariUnsetParameter(device, geometry, "motion.vertex.normal");
  const float time[2] = {0.f, 1.f};
  anariSetParameter(device, geometry, "time", ANARI_FLOAT32_BOX1, time);
}

// `vertexMotion`: the device deforms triangles (else the first key stays).
void setGeometryParameters(ANARIDevice device,
    ANARIGeometry geometry,
    const GeometryData &data,
    bool vertexMotion)
{
  const size_t vertices = data.positions.size() / 3;
  setArray(device,
      geometry,
      "vertex.position",
      newArray(device, ANARI_FLOAT32_VEC3, data.positions.data(), vertices));
  if (data.spheres || data.curves) {
    if (data.curves)
      setArray(device,
          geometry,
          "primitive.index",
          newArray(device,
              ANARI_UINT32,
              data.segmentStarts.data(),
              data.segmentStarts.size()));
    setArray(device,
        geometry,
        "vertex.radius",
        newArray(device, ANARI_FLOAT32, data.radii.data(), data.radii.size()));
    return;
  }
  setArray(device,
      geometry,
      "primitive.index",
      newArray(device,
          ANARI_UINT32_VEC3,
          data.triangles.data(),
          data.triangles.size() / 3));
  // Face-varying data is per vertex here: each face vertex is a vertex.
  // An edit may have removed an array, so absent ones are unset.
  const struct
  {
    const char *name;
    ANARIDataType type;
    const std::vector<float> &values;
  } attributes[] = {{"vertex.normal", ANARI_FLOAT32_VEC3, data.normals},
      {"vertex.attribute0", ANARI_FLOAT32_VEC2, data.texcoords},
      {"vertex.color", ANARI_FLOAT32_VEC3, data.colors}};
  for (const auto &a : attributes) {
    if (a.values.empty())
      anariUnsetParameter(device, geometry, a.name);
    else
      setArray(device,
          geometry,
          a.name,
          newArray(device, a.type, a.values.data(), vertices));
  }
  if (vertexMotion)
    setVertexMotion(device, geometry, data);
}

const char *materialSubtype(const ShaderDescription &shader)
{
  const bool emits = shader.emissive[0] > 0 || shader.emissive[1] > 0
                     || shader.emissive[2] > 0;
  return shader.kind == ShaderDescription::Kind::Matte && !emits
             ? "matte"
             : "physicallyBased";
}

void setMaterialParameters(
    ANARIDevice device, ANARIMaterial material, const ShaderDescription &shader)
{
  // Cs on the geometry replaces the shader's colour (the `color` attribute).
  if (std::strcmp(materialSubtype(shader), "matte") == 0) {
    if (shader.colorFromGeometry)
      setString(device, material, "color", "color");
    else
      setVec3(device, material, "color", shader.color);
    return;
  }
  // physicallyBased's own defaults (metallic 1, roughness 1) are not the
  // shaders': every parameter is set.
  if (shader.colorFromGeometry)
    setString(device, material, "baseColor", "color");
  else
    setVec3(device, material, "baseColor", shader.color);
  setFloat(device, material, "metallic", shader.metallic);
  setFloat(device, material, "roughness", shader.roughness);
  setFloat(device, material, "specular", shader.specular);
  setFloat(device, material, "clearcoat", shader.clearcoat);
  setFloat(device, material, "transmission", shader.transmission);
  setFloat(device, material, "ior", shader.ior);
  setFloat(device, material, "opacity", shader.opacity);
  setVec3(device, material, "emissive", shader.emissive);
}

const char *lightSubtype(LightItem::Kind kind)
{
  using Kind = LightItem::Kind;
  switch (kind) {
  case Kind::Quad:
    return "quad";
  case Kind::Point:
    return "point";
  case Kind::Spot:
    return "spot";
  case Kind::Ring:
    return "ring";
  case Kind::Directional:
    return "directional";
  case Kind::Hdri:
    return "hdri";
  case Kind::Ambient:
    break;
  }
  return nullptr;
}

// Every parameter but an hdri's radiance image.
void setLightParameters(
    ANARIDevice device, ANARILight light, const LightItem &item)
{
  using Kind = LightItem::Kind;
  const Kind kind = item.kind;
  const ShaderDescription &shader = item.shader;
  if (kind != Kind::Directional && kind != Kind::Hdri)
    setVec3(device, light, "position", item.position);
  if (kind != Kind::Quad && kind != Kind::Point)
    setVec3(device, light, "direction", item.direction);
  if (kind == Kind::Quad) {
    setVec3(device, light, "edge1", item.edge1);
    setVec3(device, light, "edge2", item.edge2);
  }
  if (kind == Kind::Point || kind == Kind::Ring)
    setFloat(device, light, "radius", item.radius);
  if (kind == Kind::Spot) {
    setFloat(device, light, "openingAngle", item.openingAngle);
    setFloat(device, light, "falloffAngle", item.falloffAngle);
    // A spot has no area: power, else intensity.
    setFloat(device,
        light,
        shader.hasPower ? "power" : "intensity",
        shader.hasPower ? shader.power : shader.intensity);
  } else if (kind == Kind::Directional) {
    setFloat(device, light, "angularDiameter", item.angularDiameter);
    setFloat(device, light, "irradiance", shader.intensity);
  } else if (kind == Kind::Hdri) {
    setVec3(device, light, "up", item.edge1);
    setFloat(device, light, "scale", shader.intensity);
  } else if (shader.hasPower) {
    setFloat(device, light, "power", shader.power);
  } else {
    setFloat(device,
        light,
        shader.normalizeArea ? "intensity" : "radiance",
        shader.intensity);
  }
  // PRISM_LIGHT_DECAY: set only when it is not the inverse square, so
  // devices without it see nothing new for physical lights.
  if ((kind == Kind::Point || kind == Kind::Spot) && shader.decay != 2.f)
    setFloat(device, light, "decay", shader.decay);
  setVec3(device, light, "color", shader.color);
  const bool visible = item.visibleToCamera;
  anariSetParameter(device, light, "visible", ANARI_BOOL, &visible);
}

// The environment image as an hdri's radiance; false (warned) when it
// cannot be read.
bool setHdriImage(ANARIDevice device,
    ANARILight light,
    const std::string &file,
    const ReportFunction &report)
{
  auto image = image::read(file);
  if (!image.ok()) {
    report(NSIErrWarning,
        "environment image '" + file + "': " + image.error + "; ignored");
    return false;
  }
  std::vector<float> radiance;
  radiance.reserve(image.image.pixels.size() * 3);
  for (auto &p : image.image.pixels)
    radiance.insert(radiance.end(), {p.r, p.g, p.b});
  ANARIArray2D array = anariNewArray2D(device,
      nullptr,
      nullptr,
      nullptr,
      ANARI_FLOAT32_VEC3,
      image.image.width,
      image.image.height);
  if (void *mapped = anariMapArray(device, array))
    std::memcpy(mapped, radiance.data(), radiance.size() * sizeof(float));
  anariUnmapArray(device, array);
  anariSetParameter(device, light, "radiance", ANARI_ARRAY2D, &array);
  anariRelease(device, array);
  return true;
}

void setTransform(
    ANARIDevice device, ANARIInstance instance, const Placement &placement)
{
  std::vector<float> transforms;
  for (const Matrix &m : placement)
    transforms.insert(transforms.end(), m.begin(), m.end());
  if (placement.size() > 1) {
    // Uniform over the shutter, which the camera maps to [0, 1].
    setArray(device,
        instance,
        "motion.transform",
        newArray(
            device, ANARI_FLOAT32_MAT4, transforms.data(), placement.size()));
    const float time[2] = {0.f, 1.f};
    anariSetParameter(device, instance, "time", ANARI_FLOAT32_BOX1, time);
  } else {
    anariSetParameter(
        device, instance, "transform", ANARI_FLOAT32_MAT4, transforms.data());
  }
}

// Sets the world's object array `name` to `handles` unless `current`
// already holds them (or `force`); true when set.
template <typename Handle>
bool setObjectList(ANARIDevice device,
    ANARIWorld world,
    const char *name,
    ANARIDataType type,
    const std::vector<Handle> &handles,
    std::vector<Handle> &current,
    bool force)
{
  if (!force && handles == current)
    return false;
  if (handles.empty())
    anariUnsetParameter(device, world, name);
  else
    setArray(device,
        world,
        name,
        newArray(device, type, handles.data(), handles.size()));
  current = handles;
  return true;
}

} // namespace

std::string AnariUpdateCounts::summary() const
{
  static const char *const kNames[CategoryCount] = {"geometry",
      "material",
      "surface",
      "group",
      "instance",
      "light",
      "volume",
      "world"};
  std::string text;
  auto list = [&](const char *what, const auto &counts) {
    text += text.empty() ? what : std::string("; ") + what;
    for (int c = 0; c < CategoryCount; ++c)
      text += std::string(" ") + kNames[c] + " " + std::to_string(counts[c]);
  };
  list("created", created);
  list("committed", committed);
  list("released", released);
  return text;
}

AnariWorldBuilder::AnariWorldBuilder(
    ANARIDevice device, ReportFunction report, bool vertexMotion)
    : m_device(device),
      m_report(std::move(report)),
      m_vertexMotion(vertexMotion)
{}

AnariWorldBuilder::~AnariWorldBuilder()
{
  for (auto &[key, entry] : m_instances)
    anariRelease(m_device, entry.handle);
  for (auto &[key, entry] : m_groups) {
    anariRelease(m_device, entry.data.surface);
    anariRelease(m_device, entry.handle);
  }
  for (auto &[key, entry] : m_materials)
    anariRelease(m_device, entry.handle);
  for (auto &[key, entry] : m_geometries)
    anariRelease(m_device, entry.handle);
  for (auto &[key, entry] : m_lights)
    anariRelease(m_device, entry.handle);
  for (auto &[key, entry] : m_volumes) {
    if (entry.handle) {
      anariRelease(m_device, entry.data.volume);
      anariRelease(m_device, entry.handle);
    }
  }
  if (m_world)
    anariRelease(m_device, m_world);
}

void AnariWorldBuilder::commit(Category category, ANARIObject object)
{
  anariCommitParameters(m_device, object);
  ++m_counts.committed[category];
}

void AnariWorldBuilder::release(Category category, ANARIObject object)
{
  anariRelease(m_device, object);
  ++m_counts.released[category];
}

ANARIGeometry AnariWorldBuilder::geometry(
    const std::string &handle, const GeometryData &data)
{
  auto &entry = m_geometries[handle];
  entry.used = true;
  if (entry.handle && entry.data == data)
    return entry.handle;
  if (entry.handle
      && std::strcmp(geometrySubtype(entry.data), geometrySubtype(data)) != 0) {
    release(Category::Geometry, entry.handle);
    entry.handle = nullptr;
  }
  if (!entry.handle) {
    entry.handle = anariNewGeometry(m_device, geometrySubtype(data));
    ++m_counts.created[Category::Geometry];
  }
  entry.data = data;
  if (!m_vertexMotion && !data.positionKeys.empty())
    m_report(NSIErrWarning,
        "mesh '" + handle.substr(0, handle.find('\x1f'))
            + "' moves, but the ANARI device has no vertex motion; its "
              "vertices at shutter open are used");
  setGeometryParameters(m_device, entry.handle, data, m_vertexMotion);
  commit(Category::Geometry, entry.handle);
  return entry.handle;
}

ANARIMaterial AnariWorldBuilder::material(
    const SurfaceItem &item, std::string &key)
{
  const char *subtype = materialSubtype(item.shader);
  key = item.shaderHandle + '\n' + subtype;
  // A key already used by this update for other values gets a suffix.
  for (int n = 1;; ++n) {
    auto found = m_materials.find(key);
    if (found == m_materials.end() || !found->second.used
        || found->second.data == item.shader)
      break;
    key = item.shaderHandle + '\n' + subtype + '\n' + std::to_string(n);
  }
  auto &entry = m_materials[key];
  entry.used = true;
  if (entry.handle && entry.data == item.shader)
    return entry.handle;
  if (!entry.handle) {
    entry.handle = anariNewMaterial(m_device, subtype);
    ++m_counts.created[Category::Material];
  }
  entry.data = item.shader;
  setMaterialParameters(m_device, entry.handle, item.shader);
  commit(Category::Material, entry.handle);
  return entry.handle;
}

ANARIGroup AnariWorldBuilder::group(
    const std::string &key, ANARIGeometry geometry, ANARIMaterial material)
{
  auto &entry = m_groups[key];
  entry.used = true;
  SurfaceData &data = entry.data;
  if (!entry.handle) {
    data.surface = anariNewSurface(m_device);
    ++m_counts.created[Category::Surface];
  }
  if (data.geometry != geometry || data.material != material) {
    data.geometry = geometry;
    data.material = material;
    anariSetParameter(
        m_device, data.surface, "geometry", ANARI_GEOMETRY, &geometry);
    anariSetParameter(
        m_device, data.surface, "material", ANARI_MATERIAL, &material);
    commit(Category::Surface, data.surface);
  }
  if (!entry.handle) {
    entry.handle = anariNewGroup(m_device);
    ++m_counts.created[Category::Group];
    setArray(m_device,
        entry.handle,
        "surface",
        newArray(m_device, ANARI_SURFACE, &data.surface, 1));
    commit(Category::Group, entry.handle);
  }
  return entry.handle;
}

ANARIInstance AnariWorldBuilder::instance(
    const std::string &key, ANARIGroup group, const Placement &placement)
{
  auto &entry = m_instances[key];
  entry.used = true;
  if (entry.handle && entry.data == placement)
    return entry.handle;
  const bool moves = placement.size() > 1;
  if (entry.handle && moves != (entry.data.size() > 1)) {
    release(Category::Instance, entry.handle);
    entry.handle = nullptr;
  }
  if (!entry.handle) {
    entry.handle =
        anariNewInstance(m_device, moves ? "motionTransform" : "transform");
    ++m_counts.created[Category::Instance];
    anariSetParameter(m_device, entry.handle, "group", ANARI_GROUP, &group);
  }
  entry.data = placement;
  setTransform(m_device, entry.handle, placement);
  commit(Category::Instance, entry.handle);
  return entry.handle;
}

ANARILight AnariWorldBuilder::light(size_t index, const LightItem &item)
{
  // Keyed by position and kind: a scene that keeps its lights keeps them.
  const char *subtype = lightSubtype(item.kind);
  auto &entry = m_lights[std::to_string(index) + '\n' + subtype];
  entry.used = true;
  if (entry.handle && entry.data == item)
    return entry.handle;
  // An hdri whose image changed is made anew (its image is read once).
  if (entry.handle
      && (item.kind == LightItem::Kind::Hdri
          || entry.data.shader.image != item.shader.image)) {
    release(Category::Light, entry.handle);
    entry.handle = nullptr;
  }
  if (!entry.handle) {
    ANARILight light = anariNewLight(m_device, subtype);
    if (item.kind == LightItem::Kind::Hdri
        && !setHdriImage(m_device, light, item.shader.image, m_report)) {
      anariRelease(m_device, light);
      entry.used = false;
      return nullptr;
    }
    entry.handle = light;
    ++m_counts.created[Category::Light];
  }
  entry.data = item;
  setLightParameters(m_device, entry.handle, item);
  commit(Category::Light, entry.handle);
  return entry.handle;
}

template <typename Record>
void AnariWorldBuilder::releaseUnused(
    std::map<std::string, Record> &records, Category category)
{
  for (auto it = records.begin(); it != records.end();) {
    if (it->second.used) {
      it->second.used = false; // for the next update
      ++it;
      continue;
    }
    if constexpr (std::is_same_v<Record, decltype(m_groups)::mapped_type>) {
      if (it->second.data.surface)
        release(Category::Surface, it->second.data.surface);
    }
    if constexpr (std::is_same_v<Record, decltype(m_volumes)::mapped_type>) {
      if (it->second.data.volume)
        release(Category::Volume, it->second.data.volume);
    }
    if (it->second.handle)
      release(category, it->second.handle);
    it = records.erase(it);
  }
}

ANARIGroup AnariWorldBuilder::volumeGroup(
    const std::string &key, const VolumeItem &item)
{
  auto &entry = m_volumes[key];
  VolumeItem unplaced = item;
  unplaced.worldFromObject.clear();
  entry.used = true;
  // A file that failed is reported once, until the node changes.
  if (entry.data.item == unplaced)
    return entry.handle;
  if (entry.data.volume)
    release(Category::Volume, entry.data.volume);
  if (entry.handle)
    release(Category::Group, entry.handle);
  entry.handle = nullptr;
  entry.data = {unplaced, newNanoVdbVolume(m_device, item, m_report)};
  if (!entry.data.volume)
    return nullptr;
  ++m_counts.created[Category::Volume];
  entry.handle = anariNewGroup(m_device);
  ++m_counts.created[Category::Group];
  setArray(m_device,
      entry.handle,
      "volume",
      newArray(m_device, ANARI_VOLUME, &entry.data.volume, 1));
  commit(Category::Group, entry.handle);
  return entry.handle;
}

AnariWorld AnariWorldBuilder::update(const ResolvedScene &scene)
{
  m_counts = {};
  AnariWorld out;
  std::vector<ANARIInstance> instances;
  for (auto &item : scene.surfaces) {
    ANARIGeometry geometry = this->geometry(
        item.geometryHandle, scene.geometries.at(item.geometryHandle));
    std::string materialKey;
    ANARIMaterial material = this->material(item, materialKey);
    const std::string groupKey = item.geometryHandle + '\n' + materialKey
                                 + (item.visibleToCamera ? "\n1" : "\n0");
    ANARIGroup group = this->group(groupKey, geometry, material);
    for (size_t p = 0; p < item.worldFromObject.size(); ++p)
      instances.push_back(this->instance(
          groupKey + '\n' + std::to_string(p), group, item.worldFromObject[p]));
  }

  for (const VolumeItem &item : scene.volumes) {
    const std::string key = "volume\n" + item.handle + '\n' + item.shaderHandle;
    ANARIGroup group = volumeGroup(key, item);
    for (size_t p = 0; group && p < item.worldFromObject.size(); ++p)
      instances.push_back(this->instance(
          key + '\n' + std::to_string(p), group, item.worldFromObject[p]));
  }

  std::vector<ANARILight> lights;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const LightItem &item = scene.lights[i];
    if (item.kind == LightItem::Kind::Ambient) {
      out.ambientColor = item.shader.color;
      out.ambientRadiance += item.shader.intensity;
      if (item.visibleToCamera) {
        for (int c = 0; c < 3; ++c)
          out.background[c] += item.shader.color[c] * item.shader.intensity;
      }
      continue;
    }
    if (ANARILight light = this->light(i, item))
      lights.push_back(light);
  }

  // The world is told only when the set of its instances or lights changed;
  // edits inside them reach it through their own commits.
  bool worldChanged = false;
  if (!m_world) {
    m_world = anariNewWorld(m_device);
    ++m_counts.created[Category::World];
    worldChanged = true;
  }
  worldChanged |= setObjectList(m_device,
      m_world,
      "instance",
      ANARI_INSTANCE,
      instances,
      m_worldInstances,
      worldChanged);
  worldChanged |= setObjectList(m_device,
      m_world,
      "light",
      ANARI_LIGHT,
      lights,
      m_worldLights,
      worldChanged);
  if (worldChanged)
    commit(Category::World, m_world);

  releaseUnused(m_instances, Category::Instance);
  releaseUnused(m_groups, Category::Group);
  releaseUnused(m_materials, Category::Material);
  releaseUnused(m_geometries, Category::Geometry);
  releaseUnused(m_lights, Category::Light);
  releaseUnused(m_volumes, Category::Group);
  out.world = m_world;
  return out;
}

} // namespace prism::nsi
