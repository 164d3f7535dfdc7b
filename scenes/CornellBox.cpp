// The Cornell box, in its own proportions (not the measured data): a 2 x 2 x 2
// room open towards +z, floor at y = 0, with a square light in the ceiling.
#include "DemoScenes.h"
#include "Meshes.h"
#include "Objects.h"

namespace prism::scenes {

Scene buildCornellBox(ANARIDevice device)
{
  Scene scene;
  scene.name = "cornell-box";
  scene.description = "the Cornell box";
  scene.camera.valid = true;
  // A hair off the symmetry axis: from the exact center, pixel rays run
  // through the wall-floor seams and the color there is a rounding tie.
  scene.camera.eye = {0.0031f, 1.0017f, 3.9f};
  scene.camera.at = {0.f, 1.f, 0.f};
  scene.camera.up = {0.f, 1.f, 0.f};
  scene.camera.fovyDegrees = 40.f;

  TriangleMesh white, red, green, boxes, panel;
  white.addQuad({-1, 0, 1}, {2, 0, 0}, {0, 0, -2}); // floor
  white.addQuad({-1, 2, -1}, {2, 0, 0}, {0, 0, 2}); // ceiling
  white.addQuad({-1, 0, -1}, {2, 0, 0}, {0, 2, 0}); // back
  red.addQuad({-1, 0, 1}, {0, 0, -2}, {0, 2, 0});   // left, faces +x
  green.addQuad({1, 0, -1}, {0, 0, 2}, {0, 2, 0});  // right, faces -x
  boxes.addBox(translationMatrix({-0.35f, 0.6f, -0.3f}) * rotationYMatrix(0.3f)
               * scaleMatrix({0.6f, 1.2f, 0.6f}));
  boxes.addBox(translationMatrix({0.35f, 0.3f, 0.35f}) * rotationYMatrix(-0.3f)
               * scaleMatrix({0.6f, 0.6f, 0.6f}));
  // Just below the ceiling so the two never fight for the same depth.
  const Vec3 panelCorner{-0.25f, 1.995f, -0.25f};
  const Vec3 panelEdge1{0.5f, 0.f, 0.f}, panelEdge2{0.f, 0.f, 0.5f};
  panel.addQuad(panelCorner, panelEdge1, panelEdge2);
  for (const TriangleMesh *mesh : {&white, &red, &green, &boxes})
    scene.bounds.extend(mesh->bounds());

  std::vector<ANARIObject> lights;
  ANARILight light = newLightIfSupported(device, "quad", scene, lights);
  if (light) {
    // The front side, edge2 x edge1 (spec 5.7.4), must face down.
    setVec3(device, light, "position", panelCorner + Vec3{0.f, -0.001f, 0.f});
    setVec3(device, light, "edge1", panelEdge2);
    setVec3(device, light, "edge2", panelEdge1);
    setVec3(device, light, "color", {1.f, 0.85f, 0.6f});
    setFloat(device, light, "intensity", 12.f);
    anariCommitParameters(device, light);
  }

  const Vec3 kWhite{0.73f, 0.73f, 0.73f};
  ANARIMaterial whiteMaterial = newMatte(device, kWhite);
  ANARIMaterial redMaterial = newMatte(device, {0.65f, 0.05f, 0.05f});
  ANARIMaterial greenMaterial = newMatte(device, {0.12f, 0.45f, 0.15f});
  // The panel glows by itself when there is no quad light to do it, so a
  // path tracer still sees a lit room.
  ANARIMaterial panelMaterial = anariNewMaterial(device, "physicallyBased");
  setVec3(device, panelMaterial, "baseColor", {1.f, 1.f, 1.f});
  const float dielectric = 0.f;
  anariSetParameter(
      device, panelMaterial, "metallic", ANARI_FLOAT32, &dielectric);
  if (!light)
    setVec3(device, panelMaterial, "emissive", {12.f, 10.2f, 7.2f});
  anariCommitParameters(device, panelMaterial);

  std::vector<ANARIObject> surfaces;
  struct Part
  {
    const TriangleMesh *mesh;
    ANARIMaterial material;
  };
  const Part parts[] = {{&white, whiteMaterial},
      {&red, redMaterial},
      {&green, greenMaterial},
      {&boxes, whiteMaterial},
      {&panel, panelMaterial}};
  uint32_t id = 0;
  for (const Part &part : parts) {
    ANARIGeometry geometry = newTriangleGeometry(device, *part.mesh);
    ANARISurface surface = newListedSurface(device,
        scene.surfaces,
        geometry,
        "triangle",
        part.material,
        part.material == panelMaterial ? "physicallyBased" : "matte",
        id);
    anariRelease(device, geometry);
    surfaces.push_back(surface);
    id++;
  }
  for (ANARIMaterial m :
      {whiteMaterial, redMaterial, greenMaterial, panelMaterial})
    anariRelease(device, m);
  finishWorld(device, scene, surfaces, {}, lights);
  return scene;
}

} // namespace prism::scenes
