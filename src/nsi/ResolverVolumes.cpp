#include "Resolver.h"

namespace prism::nsi {

// A volume's placements with one shader gather in one item; its file is
// read when the ANARI objects are built.
void Resolver::volume(const std::string &handle,
    const Node &node,
    const Placement &world,
    const std::vector<AttributesOnPath> &attributes)
{
  if (resolveFlag(attributes, "visibility").value_or(1) == 0)
    return;
  std::string shaderHandle;
  const Node *shaderNode =
      resolveShader(attributes, shaderHandle, "volumeshader");
  auto [it, added] = m_volumeIndex.emplace(
      handle + '\n' + shaderHandle, m_scene.volumes.size());
  if (added) {
    VolumeItem item;
    item.handle = handle;
    item.shaderHandle = shaderHandle;
    const Value *file = node.attribute("vdbfilename");
    item.fileName = file ? m_expandPath(file->string()) : std::string();
    const Value *density = node.attribute("densitygrid");
    item.densityGrid = density ? density->string() : std::string();
    for (const char *grid : {"colorgrid",
             "emissiongrid",
             "emissionintensitygrid",
             "temperaturegrid",
             "velocitygrid"}) {
      if (node.attribute(grid))
        warnOnce("volume '" + handle + "': '" + grid
                 + "' is not supported yet (only the density grid "
                   "renders)");
    }
    item.shader = volumeShader();
    if (shaderNode) {
      const ShaderDescription shader = describeShader(*shaderNode);
      if (shader.kind == ShaderDescription::Kind::Volume)
        item.shader = shader;
      else
        warnOnce("shader '" + shaderHandle + "' ('" + shader.shaderName
                 + "') is not a volume shader; volume '" + handle
                 + "' is a white medium of density 1");
    }
    m_scene.volumes.push_back(std::move(item));
  }
  m_scene.volumes[it->second].worldFromObject.push_back(world);
}

} // namespace prism::nsi
