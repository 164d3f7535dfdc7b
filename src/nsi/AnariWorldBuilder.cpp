#include "AnariWorldBuilder.h"

#include "ImageIO.h"

#include <anari/frontend/type_utility.h>

#include <cstring>
#include <map>

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

ANARIGeometry newGeometry(ANARIDevice device, const GeometryData &data)
{
  ANARIGeometry geometry = anariNewGeometry(
      device, data.spheres ? "sphere" : (data.curves ? "curve" : "triangle"));
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
  } else {
    setArray(device,
        geometry,
        "primitive.index",
        newArray(device,
            ANARI_UINT32_VEC3,
            data.triangles.data(),
            data.triangles.size() / 3));
    if (!data.normals.empty())
      setArray(device,
          geometry,
          "vertex.normal",
          newArray(device, ANARI_FLOAT32_VEC3, data.normals.data(), vertices));
  }
  anariCommitParameters(device, geometry);
  return geometry;
}

ANARIMaterial newMaterial(ANARIDevice device, const ShaderDescription &shader)
{
  using Kind = ShaderDescription::Kind;
  const bool emits = shader.emissive[0] > 0 || shader.emissive[1] > 0
                     || shader.emissive[2] > 0;
  if (shader.kind == Kind::Matte && !emits) {
    ANARIMaterial matte = anariNewMaterial(device, "matte");
    setVec3(device, matte, "color", shader.color);
    anariCommitParameters(device, matte);
    return matte;
  }
  // physicallyBased's own defaults (metallic 1, roughness 1) are not the
  // shaders': every parameter is set.
  ANARIMaterial pbr = anariNewMaterial(device, "physicallyBased");
  setVec3(device, pbr, "baseColor", shader.color);
  setFloat(device, pbr, "metallic", shader.metallic);
  setFloat(device, pbr, "roughness", shader.roughness);
  setFloat(device, pbr, "specular", shader.specular);
  setFloat(device, pbr, "clearcoat", shader.clearcoat);
  setFloat(device, pbr, "transmission", shader.transmission);
  setFloat(device, pbr, "ior", shader.ior);
  setFloat(device, pbr, "opacity", shader.opacity);
  setVec3(device, pbr, "emissive", shader.emissive);
  anariCommitParameters(device, pbr);
  return pbr;
}

void setBrightness(
    ANARIDevice device, ANARILight light, const ShaderDescription &shader)
{
  if (shader.hasPower)
    setFloat(device, light, "power", shader.power);
  else
    setFloat(device,
        light,
        shader.normalizeArea ? "intensity" : "radiance",
        shader.intensity);
}

ANARILight newLight(
    ANARIDevice device, const LightItem &item, const ReportFunction &report)
{
  using Kind = LightItem::Kind;
  ANARILight light = nullptr;
  switch (item.kind) {
  case Kind::Quad:
    light = anariNewLight(device, "quad");
    setVec3(device, light, "position", item.position);
    setVec3(device, light, "edge1", item.edge1);
    setVec3(device, light, "edge2", item.edge2);
    setBrightness(device, light, item.shader);
    break;
  case Kind::Point:
    light = anariNewLight(device, "point");
    setVec3(device, light, "position", item.position);
    setFloat(device, light, "radius", item.radius);
    setBrightness(device, light, item.shader);
    break;
  case Kind::Spot:
    light = anariNewLight(device, "spot");
    setVec3(device, light, "position", item.position);
    setVec3(device, light, "direction", item.direction);
    setFloat(device, light, "openingAngle", item.openingAngle);
    setFloat(device, light, "falloffAngle", item.falloffAngle);
    // A spot has no area: power, else intensity.
    setFloat(device,
        light,
        item.shader.hasPower ? "power" : "intensity",
        item.shader.hasPower ? item.shader.power : item.shader.intensity);
    break;
  case Kind::Ring:
    light = anariNewLight(device, "ring");
    setVec3(device, light, "position", item.position);
    setVec3(device, light, "direction", item.direction);
    setFloat(device, light, "radius", item.radius);
    setBrightness(device, light, item.shader);
    break;
  case Kind::Directional:
    light = anariNewLight(device, "directional");
    setVec3(device, light, "direction", item.direction);
    setFloat(device, light, "angularDiameter", item.angularDiameter);
    setFloat(device, light, "irradiance", item.shader.intensity);
    break;
  case Kind::Hdri: {
    auto image = image::read(item.shader.image);
    if (!image.ok()) {
      report(NSIErrWarning,
          "environment image '" + item.shader.image + "': " + image.error
              + "; ignored");
      return nullptr;
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
    light = anariNewLight(device, "hdri");
    anariSetParameter(device, light, "radiance", ANARI_ARRAY2D, &array);
    anariRelease(device, array);
    setVec3(device, light, "direction", item.direction);
    setVec3(device, light, "up", item.edge1);
    setFloat(device, light, "scale", item.shader.intensity);
    break;
  }
  case Kind::Ambient:
    return nullptr;
  }
  setVec3(device, light, "color", item.shader.color);
  const bool visible = item.visibleToCamera;
  anariSetParameter(device, light, "visible", ANARI_BOOL, &visible);
  anariCommitParameters(device, light);
  return light;
}

} // namespace

AnariWorld buildAnariWorld(ANARIDevice device,
    const ResolvedScene &scene,
    const ReportFunction &report)
{
  AnariWorld out;
  // Only the geometry some surface uses (a mesh split by facesets is not).
  std::map<std::string, ANARIGeometry> geometries;
  for (auto &item : scene.surfaces) {
    if (!geometries.count(item.geometryHandle))
      geometries[item.geometryHandle] =
          newGeometry(device, scene.geometries.at(item.geometryHandle));
  }

  std::vector<ANARIInstance> instances;
  for (auto &item : scene.surfaces) {
    ANARISurface surface = anariNewSurface(device);
    ANARIGeometry geometry = geometries.at(item.geometryHandle);
    ANARIMaterial material = newMaterial(device, item.shader);
    anariSetParameter(device, surface, "geometry", ANARI_GEOMETRY, &geometry);
    anariSetParameter(device, surface, "material", ANARI_MATERIAL, &material);
    anariCommitParameters(device, surface);
    anariRelease(device, material);

    ANARIGroup group = anariNewGroup(device);
    setArray(
        device, group, "surface", newArray(device, ANARI_SURFACE, &surface, 1));
    anariCommitParameters(device, group);
    anariRelease(device, surface);
    for (const Placement &placement : item.worldFromObject) {
      std::vector<float> transforms;
      for (const Matrix &m : placement)
        transforms.insert(transforms.end(), m.begin(), m.end());
      const bool moves = placement.size() > 1;
      ANARIInstance instance =
          anariNewInstance(device, moves ? "motionTransform" : "transform");
      anariSetParameter(device, instance, "group", ANARI_GROUP, &group);
      if (moves) {
        // Uniform over the shutter, which the camera maps to [0, 1].
        setArray(device,
            instance,
            "motion.transform",
            newArray(device,
                ANARI_FLOAT32_MAT4,
                transforms.data(),
                placement.size()));
        const float time[2] = {0.f, 1.f};
        anariSetParameter(device, instance, "time", ANARI_FLOAT32_BOX1, time);
      } else {
        anariSetParameter(device,
            instance,
            "transform",
            ANARI_FLOAT32_MAT4,
            transforms.data());
      }
      anariCommitParameters(device, instance);
      instances.push_back(instance);
    }
    anariRelease(device, group);
  }
  for (auto &[handle, geometry] : geometries)
    anariRelease(device, geometry);

  std::vector<ANARILight> lights;
  for (auto &item : scene.lights) {
    if (item.kind == LightItem::Kind::Ambient) {
      out.ambientColor = item.shader.color;
      out.ambientRadiance += item.shader.intensity;
      if (item.visibleToCamera) {
        for (int c = 0; c < 3; ++c)
          out.background[c] += item.shader.color[c] * item.shader.intensity;
      }
      continue;
    }
    if (ANARILight light = newLight(device, item, report))
      lights.push_back(light);
  }

  out.world = anariNewWorld(device);
  if (!instances.empty())
    setArray(device,
        out.world,
        "instance",
        newArray(device, ANARI_INSTANCE, instances.data(), instances.size()));
  if (!lights.empty())
    setArray(device,
        out.world,
        "light",
        newArray(device, ANARI_LIGHT, lights.data(), lights.size()));
  anariCommitParameters(device, out.world);
  for (auto instance : instances)
    anariRelease(device, instance);
  for (auto light : lights)
    anariRelease(device, light);
  return out;
}

} // namespace prism::nsi
