#include "ShaderTable.h"

#include <cmath>

namespace prism::nsi {

namespace {

float number(const Node &node, const char *name, float fallback)
{
  const Value *v = node.attribute(name);
  return v ? float(v->number(fallback)) : fallback;
}

bool color(const Node &node, const char *name, std::array<float, 3> &out)
{
  const Value *v = node.attribute(name);
  if (!v)
    return false;
  const auto n = v->numbers();
  if (n.size() >= 3)
    out = {float(n[0]), float(n[1]), float(n[2])};
  else if (n.size() == 1)
    out = {float(n[0]), float(n[0]), float(n[0])};
  else
    return false;
  return true;
}

std::array<float, 3> scaled(std::array<float, 3> c, float k)
{
  return {c[0] * k, c[1] * k, c[2] * k};
}

// The colour of a light or unknown shader, by the names clients use.
void anyColor(const Node &node, std::array<float, 3> &out)
{
  for (const char *name : {"i_color", "tint", "Cs", "color", "base_color"}) {
    if (color(node, name, out))
      return;
  }
}

void lightBrightness(const Node &node, ShaderDescription &d)
{
  d.color = {1.f, 1.f, 1.f};
  anyColor(node, d.color);
  if (node.attribute("power")) {
    d.hasPower = true;
    d.power = number(node, "power", 1.f);
  }
  d.intensity =
      number(node, "intensity", 1.f) * std::exp2(number(node, "exposure", 0.f));
  d.normalizeArea = number(node, "normalize_area", 1.f) != 0.f;
  d.decay = number(node, "decayRate", 2.f);
}

} // namespace

std::string shaderName(const std::string &shaderFilename)
{
  std::string name = shaderFilename;
  const size_t slash = name.find_last_of('/');
  if (slash != std::string::npos)
    name = name.substr(slash + 1);
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".oso") == 0)
    name.resize(name.size() - 4);
  return name;
}

ShaderDescription describeShader(const Node &shader)
{
  ShaderDescription d;
  const Value *file = shader.attribute("shaderfilename");
  d.shaderName = shaderName(file ? file->string() : std::string());
  const std::string &name = d.shaderName;
  using Kind = ShaderDescription::Kind;

  if (name == "dlPrincipled") {
    d.kind = Kind::PhysicallyBased;
    color(shader, "i_color", d.color);
    d.roughness = number(shader, "roughness", 0.3f);
    d.metallic = number(shader, "metallic", 0.f);
    d.specular = number(shader, "specular_level", 0.5f);
    d.clearcoat = number(shader, "coating_thickness", 0.f) > 0.f ? 1.f : 0.f;
    d.transmission = number(shader, "refract_weight", 0.f);
    d.ior = number(shader, "refract_ior", 1.5f);
    d.opacity = number(shader, "opacity", 1.f);
    std::array<float, 3> glow{0.f, 0.f, 0.f};
    color(shader, "incandescence", glow);
    d.emissive = scaled(glow, number(shader, "incandescence_intensity", 1.f));
  } else if (name == "dlStandard") {
    d.kind = Kind::PhysicallyBased;
    color(shader, "base_color", d.color);
    d.color = scaled(d.color, number(shader, "base", 1.f));
    d.roughness = number(shader, "specular_roughness", 0.3f);
    d.metallic = number(shader, "metalness", 0.f);
    d.ior = number(shader, "specular_IOR", 1.5f);
    d.clearcoat = number(shader, "coat", 0.f);
    std::array<float, 3> glow{0.f, 0.f, 0.f};
    color(shader, "emission_color", glow);
    d.emissive = scaled(glow, number(shader, "emission_w", 0.f));
    std::array<float, 3> opacity{1.f, 1.f, 1.f};
    color(shader, "opacity", opacity);
    d.opacity = (opacity[0] + opacity[1] + opacity[2]) / 3.f;
  } else if (name == "dlGlass") {
    d.kind = Kind::PhysicallyBased;
    d.color = {1.f, 1.f, 1.f};
    anyColor(shader, d.color);
    d.transmission = 1.f;
    d.roughness = number(shader, "roughness", 0.f);
    d.ior = number(shader, "ior", 1.5f);
  } else if (name == "dlMetal") {
    d.kind = Kind::PhysicallyBased;
    anyColor(shader, d.color);
    d.metallic = 1.f;
    d.roughness = number(shader, "roughness", 0.2f);
  } else if (name == "lambert" || name == "Surface/Constant"
             || name == "Constant") {
    d.kind = Kind::Matte;
    if (color(shader, "i_color", d.color))
      d.color = scaled(d.color, number(shader, "i_diffuse", 1.f));
    else
      color(shader, "Cs", d.color);
  } else if (name == "emitter" || name == "areaLight" || name == "pointLight"
             || name == "spotLight") {
    d.kind = Kind::Emitter;
    lightBrightness(shader, d);
    d.coneAngle = number(shader, "coneAngle", 40.f);
    d.penumbraAngle = number(shader, "penumbraAngle", 0.f);
  } else if (name == "environmentLight") {
    d.kind = Kind::EnvironmentLight;
    lightBrightness(shader, d);
    const Value *image = shader.attribute("image");
    d.image = image ? image->string() : std::string();
  } else if (name == "distantLight" || name == "directionalLight") {
    d.kind = Kind::DistantLight;
    lightBrightness(shader, d);
  } else if (name == "vdbVolume" || name == "dlVolume") {
    // `density` multiplies the grid's.
    d.kind = Kind::Volume;
    d.color = volumeShader().color;
    if (!color(shader, "scattering_color", d.color))
      color(shader, "color", d.color);
    d.density = number(shader, "density", 1.f);
  } else {
    d.kind = Kind::Matte;
    d.recognised = false;
    anyColor(shader, d.color);
  }
  return d;
}

ShaderDescription volumeShader()
{
  ShaderDescription d;
  d.kind = ShaderDescription::Kind::Volume;
  d.color = {1.f, 1.f, 1.f};
  return d;
}

} // namespace prism::nsi
