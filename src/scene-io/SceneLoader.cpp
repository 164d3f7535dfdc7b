#include "SceneLoader.h"

#include "GltfLoader.h"
#include "NanoVdbLoader.h"
#ifdef PRISM_SCENE_IO_HAS_NSI
#include "NsiLoader.h"
#endif
#include "ObjLoader.h"

namespace prism::scene_io {
namespace {

scenes::Scene buildDemo(ANARIDevice device,
    const scenes::DemoScene &demo,
    const TransferFunctionOptions &transferFunction)
{
  if (transferFunction.given && demo.buildWithVolumeStyle) {
    scenes::TransferFunction style = demo.volumeStyle();
    applyTransferFunctionOptions(transferFunction, style);
    return demo.buildWithVolumeStyle(device, style);
  }
  return demo.build(device);
}

LoadResult loadRaw(
    ANARIDevice device, const SceneSource &source, const LoadOptions &options)
{
  RawVolumeFormat format = options.raw;
  LoadResult result;
  result.error = resolveRawFormat(source.path, format);
  if (!result.ok())
    return result;
  return loadRawVolume(device, source.path, format, options.transferFunction);
}

} // namespace

LoadResult loadScene(
    ANARIDevice device, const SceneSource &source, const LoadOptions &options)
{
  LoadResult result;
  switch (source.format) {
  case SceneFormat::Demo:
    if (source.demo)
      result.scene = buildDemo(device, *source.demo, options.transferFunction);
    else
      result.error = "no demo scene '" + source.name + "'";
    return result;
  case SceneFormat::Gltf: {
    GltfOptions gltf;
    gltf.cameraIndex = options.gltfCamera;
    gltf.variant = options.gltfVariant;
    gltf.time = options.gltfTime;
    return loadGltf(device, source.path, gltf);
  }
  case SceneFormat::Obj:
    return loadObj(device, source.path);
  case SceneFormat::Raw:
    return loadRaw(device, source, options);
  case SceneFormat::NanoVdb:
    return loadNanoVdb(
        device, source.path, options.gridName, options.transferFunction);
  case SceneFormat::Nsi:
#ifdef PRISM_SCENE_IO_HAS_NSI
    return loadNsi(device, source.path);
#else
    break;
#endif
  }
  result.error = "'" + source.path
                 + "' is an NSI stream, and this build has no libnsi to "
                   "load it with";
  return result;
}

LoadResult loadScene(
    ANARIDevice device, const std::string &source, const LoadOptions &options)
{
  const SourceResult identified = identifySceneSource(source);
  if (!identified.ok()) {
    LoadResult result;
    result.error = identified.error;
    return result;
  }
  return loadScene(device, identified.source, options);
}

} // namespace prism::scene_io
