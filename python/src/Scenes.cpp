// prism._native.loadScene: scene files and demos through prism_scene_io, the
// loaders prism-render uses, lit by the same rule (scene_io::lightingFor)
// and framed the same way (scene_io::frameCamera).
#include "Binding.h"

#ifdef PRISM_PYTHON_HAS_SCENE_IO
#include "CameraFraming.h"
#include "Environment.h"
#include "Objects.h"
#include "SceneLoader.h"
#endif

namespace prism::python {
namespace {

#ifdef PRISM_PYTHON_HAS_SCENE_IO

py::tuple vec3(const scenes::Vec3 &v)
{
  return py::make_tuple(v[0], v[1], v[2]);
}

struct LoadRequest
{
  scene_io::LoadOptions load;
  scene_io::EnvironmentChoice environment;
  float aspect{1.f};
};

// What the loader made, before the GIL is taken back.
struct Loaded
{
  std::string error;
  ANARIWorld world{nullptr};
  scenes::Scene scene;
  scene_io::CameraSetup view;
  std::string lighting; // what lights the scene, for the caller to say
};

Loaded load(ANARIDevice device, const std::string &path, const LoadRequest &r)
{
  Loaded out;
  scene_io::LoadResult loaded = scene_io::loadScene(device, path, r.load);
  if (!loaded.ok()) {
    scenes::releaseScene(device, loaded.scene);
    out.error = loaded.error;
    return out;
  }
  out.scene = std::move(loaded.scene);
  const scene_io::Lighting lighting =
      scene_io::lightingFor(out.scene, r.environment);
  if (lighting.add && scenes::hasSubtype(device, ANARI_LIGHT, "hdri")) {
    const scenes::Vec3 up =
        out.scene.camera.valid ? out.scene.camera.up : scenes::Vec3{0, 1, 0};
    scene_io::Environment environment =
        scene_io::makeEnvironment(device, lighting.environment, up);
    if (!environment.error.empty()) {
      scenes::releaseScene(device, out.scene);
      out.error = environment.error;
      return out;
    }
    scene_io::addWorldLight(device, out.scene, environment.light);
    out.lighting = environment.description;
  }
  out.view = scene_io::frameCamera(
      out.scene.camera, out.scene.bounds, r.aspect, {}, out.scene.outline);
  // The world holds its lights and surfaces; Python keeps the world alone.
  out.world = out.scene.world;
  scenes::releaseListedSurfaces(device, out.scene);
  for (ANARILight light : out.scene.lights)
    anariRelease(device, light);
  out.scene.lights.clear();
  return out;
}

py::dict loadScene(
    Device &device, const std::string &path, const py::dict &options)
{
  LoadRequest r;
  auto get = [&](const char *key) -> py::object {
    return options.contains(key) ? py::object(options[key]) : py::none();
  };
  if (!get("gltf_camera").is_none())
    r.load.gltfCamera = get("gltf_camera").cast<int>();
  if (!get("variant").is_none())
    r.load.gltfVariant = get("variant").cast<std::string>();
  if (!get("time").is_none())
    r.load.gltfTime = get("time").cast<double>();
  if (!get("grid").is_none())
    r.load.gridName = get("grid").cast<std::string>();
  if (!get("environment").is_none()) {
    r.environment.source = get("environment").cast<std::string>();
    r.environment.given = true;
  }
  if (!get("environment_intensity").is_none())
    r.environment.intensity = get("environment_intensity").cast<float>();
  if (!get("aspect").is_none())
    r.aspect = get("aspect").cast<float>();
  if (!(r.aspect > 0.f && r.aspect < 1e6f))
    throw py::value_error("aspect must be a positive width / height");
  if (!(r.environment.intensity >= 0.f && r.environment.intensity <= 1e6f))
    throw py::value_error("environment_intensity must be from 0 to 1000000");

  Loaded loaded = device.withHandle("load_scene",
      [&](ANARIDevice d, ANARIObject) { return load(d, path, r); });
  if (!loaded.error.empty())
    throw py::value_error(loaded.error);
  py::dict out;
  out["world"] =
      std::make_shared<Object>(device.device(), loaded.world, ANARI_WORLD, "");
  const scenes::Bounds &b = loaded.scene.bounds;
  out["bounds"] =
      b.empty() ? py::object(py::none())
                : py::object(py::make_tuple(vec3(b.lower), vec3(b.upper)));
  const scene_io::CameraSetup &v = loaded.view;
  py::dict camera;
  camera["position"] = vec3(v.eye);
  camera["at"] = vec3(v.at);
  camera["up"] = vec3(v.up);
  camera["fovy_degrees"] = v.fovyDegrees;
  camera["orthographic"] = v.orthographic;
  camera["height"] = v.height;
  camera["from_scene"] = !v.framed;
  out["camera"] = camera;
  out["notes"] = loaded.scene.notes;
  out["lighting"] = loaded.lighting;
  out["name"] = loaded.scene.name;
  return out;
}

#else

py::dict loadScene(Device &, const std::string &, const py::dict &)
{
  throw py::value_error(
      "this prism package was built without the scene loaders "
      "(PRISM_BUILD_TOOLS=OFF)");
}

#endif

} // namespace

void bindScenes(py::module_ &m)
{
  m.def("loadScene",
      &loadScene,
      py::arg("device"),
      py::arg("path"),
      py::arg("options"));
}

} // namespace prism::python
