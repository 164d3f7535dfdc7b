#include "Resolver.h"

#include <cmath>

namespace prism::nsi {

std::array<float, 3> Resolver::toFloat(const std::array<double, 3> &v)
{
  return {float(v[0]), float(v[1]), float(v[2])};
}

// One planar quad or one particle with an emitter is an ANARI light.
bool Resolver::light(const GeometryData &data,
    const Matrix &world,
    const ShaderDescription &shader,
    bool cameraSees)
{
  auto point = [&](size_t i) {
    return transformPoint(world,
        {data.positions[3 * i],
            data.positions[3 * i + 1],
            data.positions[3 * i + 2]});
  };
  LightItem light;
  light.shader = shader;
  light.visibleToCamera = cameraSees;
  if (!data.spheres && data.positions.size() == 12
      && data.triangles.size() == 6) {
    const auto v0 = point(0), v1 = point(1), v3 = point(3);
    light.kind = LightItem::Kind::Quad;
    light.position = toFloat(v0);
    light.edge1 = toFloat({v3[0] - v0[0], v3[1] - v0[1], v3[2] - v0[2]});
    light.edge2 = toFloat({v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2]});
  } else if (data.spheres && data.radii.size() == 1) {
    light.position = toFloat(point(0));
    light.radius = data.radii[0];
    // Spots and rings face along N, else the node's -Z.
    std::array<double, 3> axis{0, 0, -1};
    if (data.normals.size() == 3)
      axis = {data.normals[0], data.normals[1], data.normals[2]};
    light.direction = toFloat(transformVector(world, axis));
    if (shader.shaderName == "spotLight") {
      // 3Delight's penumbra widens the cone rather than eating into it.
      light.kind = LightItem::Kind::Spot;
      light.openingAngle =
          float((shader.coneAngle + 2 * shader.penumbraAngle) * M_PI / 180);
      light.falloffAngle = float(shader.penumbraAngle * M_PI / 180);
    } else if (shader.shaderName == "areaLight" && data.normals.size() == 3) {
      light.kind = LightItem::Kind::Ring;
    } else {
      light.kind = LightItem::Kind::Point;
    }
  } else {
    return false;
  }
  m_scene.lights.push_back(light);
  return true;
}

void Resolver::environment(const std::string &handle,
    const Node &node,
    const Placement &placement,
    const std::vector<AttributesOnPath> &attributes)
{
  const Matrix &world = placement.front(); // lights do not move yet
  std::string shaderHandle;
  const Node *shaderNode = resolveShader(attributes, shaderHandle);
  if (!shaderNode) {
    warnOnce("environment '" + handle + "' has no shader; ignored");
    return;
  }
  LightItem light;
  light.shader = describeShader(*shaderNode);
  light.visibleToCamera =
      resolveFlag(attributes, "visibility.camera").value_or(1) != 0;
  const Value *angle = node.attribute("angle");
  const double degrees = angle ? angle->number(360) : 360;
  using Kind = ShaderDescription::Kind;
  if (degrees < 360 || light.shader.kind == Kind::DistantLight) {
    light.kind = LightItem::Kind::Directional;
    light.direction = toFloat(transformVector(world, {0, 0, -1}));
    light.angularDiameter = float(degrees * M_PI / 180);
  } else if (!light.shader.image.empty()) {
    light.kind = LightItem::Kind::Hdri;
    light.shader.image = m_expandPath(light.shader.image);
    light.direction = toFloat(transformVector(world, {0, 0, -1}));
    light.edge1 = toFloat(transformVector(world, {0, 1, 0})); // up
  } else {
    light.kind = LightItem::Kind::Ambient;
  }
  m_scene.lights.push_back(light);
}

} // namespace prism::nsi
