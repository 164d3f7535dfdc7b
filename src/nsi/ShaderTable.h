// NSI shader nodes recognised by the name of their shader (the basename of
// `shaderfilename` without ".oso") and described as ANARI materials or
// lights. OSL itself is not run; docs/nsi.md lists the table.
#pragma once

#include "Graph.h"

#include <array>
#include <string>

namespace prism::nsi {

struct ShaderDescription
{
  enum class Kind {
    Matte,
    PhysicallyBased,
    Emitter,
    EnvironmentLight,
    DistantLight,
    Volume
  };
  Kind kind{Kind::Matte};
  std::string shaderName;
  bool recognised{true};

  std::array<float, 3> color{0.8f, 0.8f, 0.8f};
  float roughness{0.3f};
  float metallic{0.f};
  float specular{0.5f};
  float clearcoat{0.f};
  float transmission{0.f};
  float ior{1.5f};
  float opacity{1.f};
  std::array<float, 3> emissive{0.f, 0.f, 0.f};
  float density{1.f}; // volumes: scales the extinction
  // Surfaces on geometry with Cs: the colour is the geometry's `color`
  // attribute instead of `color` (set where the shader meets the geometry).
  bool colorFromGeometry{false};

  // Lights: `power` in watts when given, else `intensity` · 2^exposure.
  bool hasPower{false};
  float power{0.f};
  float intensity{1.f};
  bool normalizeArea{true};
  // Point and spot lights: intensity / distance^decay (3Delight's
  // decayRate: 0 none, 1 linear, 2 quadratic, the physical default).
  float decay{2.f};
  std::string image;                     // environmentLight's map
  float coneAngle{40}, penumbraAngle{0}; // spotLight, degrees

  bool operator==(const ShaderDescription &) const = default;
};

// "/path/dlPrincipled.oso" -> "dlPrincipled".
std::string shaderName(const std::string &shaderFilename);

ShaderDescription describeShader(const Node &shader);

// What a volume without a volume shader is: white, density 1.
ShaderDescription volumeShader();

} // namespace prism::nsi
