#include "Resolver.h"

#include "CurveTessellation.h"
#include "MotionSamples.h"

#include <algorithm>
#include <cmath>

namespace prism::nsi {

void Resolver::geometry(const std::string &handle,
    const Node &node,
    const Placement &world,
    const std::vector<AttributesOnPath> &attributes)
{
  auto built = m_scene.geometries.find(handle);
  if (built == m_scene.geometries.end()) {
    if (m_failed.count(handle))
      return;
    std::optional<GeometryData> data;
    auto points = node.attributes.find("P");
    if (node.type != "mesh" && m_times.size() > 1
        && points != node.attributes.end() && isMoving(points->second))
      warnOnce(node.type + " '" + handle
               + "': 'P' moves, but only meshes have vertex motion; the "
                 "first sample is rendered");
    if (node.type == "mesh")
      data = buildMesh(handle, node, m_report, m_times, m_subdivisionLevel);
    else if (node.type == "particles")
      data = buildParticles(handle, node, m_report);
    else if (node.type == "plane")
      data = GeometryData{}; // sized once the whole scene is known
    else
      data = buildCurves(handle, node, m_report);
    if (!data) {
      m_failed.insert(handle);
      return;
    }
    if (!data->positionKeys.empty())
      m_scene.hasMotion = true;
    built = m_scene.geometries.emplace(handle, std::move(*data)).first;
  }
  const auto facesets = node.inputsOf("facesets");
  if (node.type != "mesh" || facesets.empty()) {
    placeSurface(handle, world, attributes);
    return;
  }
  // Each faceset's faces are a surface of their own, its attributes the
  // nearest; the faces in no set keep the mesh's.
  std::set<uint32_t> inSomeSet;
  for (const Input *input : facesets) {
    const Node *faceset = m_graph.find(input->from);
    if (!faceset || faceset->type != "faceset")
      continue;
    std::set<uint32_t> faces;
    for (double f : numbers(*faceset, "faces")) {
      if (f >= 0 && f < 4e9)
        faces.insert(uint32_t(f));
    }
    inSomeSet.insert(faces.begin(), faces.end());
    const std::string part = handle + '\x1f' + input->from;
    if (!addPart(handle, part, [&](uint32_t f) { return faces.count(f) > 0; }))
      continue;
    std::vector<AttributesOnPath> nearer = attributes;
    for (auto &a : nearer)
      ++a.level;
    for (const Input *a : faceset->inputsOf("geometryattributes")) {
      if (const Node *setAttributes = m_graph.find(a->from))
        nearer.push_back({setAttributes, 0});
    }
    placeSurface(part, world, nearer);
  }
  const std::string rest = handle + '\x1f';
  if (addPart(handle, rest, [&](uint32_t f) { return !inSomeSet.count(f); }))
    placeSurface(rest, world, attributes);
}

// The triangles of `whole` whose faces `keep` accepts, as geometry `part`
// (made once); false when there are none.
template <typename Keep>
bool Resolver::addPart(
    const std::string &whole, const std::string &part, Keep keep)
{
  auto found = m_scene.geometries.find(part);
  if (found == m_scene.geometries.end()) {
    const GeometryData &source = m_scene.geometries.at(whole);
    GeometryData subset = source;
    subset.triangles.clear();
    subset.triangleFaces.clear();
    for (size_t t = 0; t < source.triangleFaces.size(); ++t) {
      if (!keep(source.triangleFaces[t]))
        continue;
      subset.triangles.insert(subset.triangles.end(),
          source.triangles.begin() + 3 * t,
          source.triangles.begin() + 3 * t + 3);
      subset.triangleFaces.push_back(source.triangleFaces[t]);
    }
    found = m_scene.geometries.emplace(part, std::move(subset)).first;
  }
  return !found->second.triangles.empty();
}

// One placement of built geometry `key` with the attributes on its path.
void Resolver::placeSurface(const std::string &key,
    const Placement &world,
    const std::vector<AttributesOnPath> &attributes)
{
  if (resolveFlag(attributes, "visibility").value_or(1) == 0)
    return;
  const bool cameraSees =
      resolveFlag(attributes, "visibility.camera").value_or(1) != 0;
  const GeometryData &data = m_scene.geometries.at(key);

  std::string shaderHandle;
  const Node *shaderNode = resolveShader(attributes, shaderHandle);
  ShaderDescription shader;
  if (shaderNode) {
    shader = describeShader(*shaderNode);
    if (!shader.recognised)
      warnOnce("shader '" + shaderHandle + "' ('" + shader.shaderName
               + "') is not recognised; a grey matte is used");
  }
  if (shader.kind == ShaderDescription::Kind::Emitter
      && light(data, world.front(), shader, cameraSees))
    return;
  if (shader.kind == ShaderDescription::Kind::Emitter) {
    // Other emitting geometry glows: an emissive surface.
    shader.emissive = {shader.color[0] * shader.intensity,
        shader.color[1] * shader.intensity,
        shader.color[2] * shader.intensity};
    shader.color = {0, 0, 0};
  } else {
    shader.colorFromGeometry = !data.colors.empty();
  }
  const std::string surfaceKey =
      key + '\n' + shaderHandle + '\n' + (cameraSees ? "1" : "0");
  auto [it, added] =
      m_surfaceIndex.emplace(surfaceKey, m_scene.surfaces.size());
  if (added) {
    SurfaceItem item;
    item.geometryHandle = key;
    item.shaderHandle = shaderHandle;
    item.shader = shader;
    item.visibleToCamera = cameraSees;
    m_scene.surfaces.push_back(std::move(item));
  }
  m_scene.surfaces[it->second].worldFromObject.push_back(world);
}

// Where the geometry's vertices are over the shutter: its positions, or
// each of its keys.
std::vector<const std::vector<float> *> Resolver::movingPositions(
    const GeometryData &data)
{
  std::vector<const std::vector<float> *> out{&data.positions};
  for (const auto &key : data.positionKeys)
    out.push_back(&key);
  return out;
}

// NSI planes are infinite (z = 0 in their space, facing +Z); ANARI gets
// a square 100 times wider than everything else in the scene, cameras
// included, as seen from each plane's origin.
void Resolver::sizePlanes()
{
  std::array<double, 3> low{INFINITY, INFINITY, INFINITY};
  std::array<double, 3> high{-INFINITY, -INFINITY, -INFINITY};
  auto grow = [&](const std::array<double, 3> &p) {
    for (int c = 0; c < 3; ++c) {
      low[c] = std::min(low[c], p[c]);
      high[c] = std::max(high[c], p[c]);
    }
  };
  for (auto &camera : m_scene.cameras)
    grow(transformPoint(camera.worldFromCamera, {0, 0, 0}));
  for (auto &item : m_scene.surfaces) {
    const GeometryData &data = m_scene.geometries.at(item.geometryHandle);
    if (data.positions.empty())
      continue; // a plane
    std::array<double, 3> a{INFINITY, INFINITY, INFINITY};
    std::array<double, 3> b{-INFINITY, -INFINITY, -INFINITY};
    float margin = 0;
    for (float r : data.radii)
      margin = std::max(margin, r);
    for (const auto *positions : movingPositions(data)) {
      for (size_t i = 0; i + 2 < positions->size(); i += 3) {
        for (int c = 0; c < 3; ++c) {
          a[c] = std::min(a[c], double((*positions)[i + c]) - margin);
          b[c] = std::max(b[c], double((*positions)[i + c]) + margin);
        }
      }
    }
    for (const Placement &placement : item.worldFromObject) {
      for (int corner = 0; corner < 8; ++corner) {
        grow(transformPoint(placement.front(),
            {corner & 1 ? b[0] : a[0],
                corner & 2 ? b[1] : a[1],
                corner & 4 ? b[2] : a[2]}));
      }
    }
  }
  if (!(low[0] <= high[0]))
    low = high = {0, 0, 0};
  const std::array<double, 3> centre{
      (low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2};
  const double diagonal =
      std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
  for (auto &item : m_scene.surfaces) {
    GeometryData &data = m_scene.geometries.at(item.geometryHandle);
    if (!data.positions.empty() && !data.isPlane)
      continue;
    double half = data.planeHalfSize;
    for (const Placement &placement : item.worldFromObject) {
      const Matrix &m = placement.front();
      const double scale = std::max(std::hypot(m[0], m[1], m[2]), 1e-12);
      const std::array<double, 3> origin{m[12], m[13], m[14]};
      const double reach = std::hypot(centre[0] - origin[0],
                               centre[1] - origin[1],
                               centre[2] - origin[2])
                           + diagonal + 1;
      half = std::max(half, 100 * reach / scale);
    }
    const float s = float(half);
    data.isPlane = true;
    data.planeHalfSize = half;
    data.positions = {-s, -s, 0, s, -s, 0, s, s, 0, -s, s, 0};
    data.triangles = {0, 1, 2, 0, 2, 3};
    data.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  }
}

} // namespace prism::nsi
