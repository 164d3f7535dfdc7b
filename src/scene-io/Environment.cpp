#include "Environment.h"

#include "EnvironmentStudio.h"
#include "Objects.h"
#include "TextureFile.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace prism::scene_io {
namespace {

using scenes::Vec3;
using scenes::operator+;
using scenes::operator*;

// A direction across `up` for the image's centre column, turned by
// `degrees` about `up`.
Vec3 centreDirection(const Vec3 &up, float degrees)
{
  const Vec3 u = scenes::normalize(up);
  // Towards +z for y-up scenes (where viewers put the camera), else any.
  Vec3 forward = std::abs(u[2]) < 0.9f ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  forward = scenes::normalize(forward + u * -scenes::dot(forward, u));
  const Vec3 side = scenes::cross(u, forward);
  const float a = degrees * std::numbers::pi_v<float> / 180.f;
  return forward * std::cos(a) + side * std::sin(a);
}

} // namespace

Environment makeEnvironment(
    ANARIDevice device, const EnvironmentChoice &choice, const Vec3 &up)
{
  Environment out;
  if (choice.source == "none")
    return out;
  std::vector<Vec3> texels;
  size_t width = 0, height = 0;
  if (choice.source == "studio") {
    width = kStudioWidth;
    height = kStudioHeight;
    texels = studioImage(width, height);
    out.description = "a neutral studio environment";
  } else {
    TextureResult file = readTexture(choice.source);
    if (!file.ok()) {
      out.error = "--env " + file.error;
      return out;
    }
    width = file.image.width;
    height = file.image.height;
    texels.resize(width * height);
    // Files have row 0 at the bottom; the hdri's first row is `up`.
    for (size_t j = 0; j < height; j++)
      for (size_t i = 0; i < width; i++) {
        const auto &p = file.image.pixels[(height - 1 - j) * width + i];
        texels[j * width + i] = {p[0], p[1], p[2]};
      }
    out.description = "the environment '" + choice.source + "'";
  }
  // A shared array over memory the tool owns: mapping a managed array
  // would trust the device to hand out enough memory (the tests' recording
  // device maps 256 bytes).
  ANARIArray2D radiance = scenes::newArray2D(
      device, ANARI_FLOAT32_VEC3, texels.data(), width, height, sizeof(Vec3));
  out.light = anariNewLight(device, "hdri");
  const Vec3 direction = centreDirection(up, choice.rotateDegrees);
  anariSetParameter(device, out.light, "radiance", ANARI_ARRAY2D, &radiance);
  anariSetParameter(device, out.light, "up", ANARI_FLOAT32_VEC3, up.data());
  anariSetParameter(
      device, out.light, "direction", ANARI_FLOAT32_VEC3, direction.data());
  anariSetParameter(
      device, out.light, "scale", ANARI_FLOAT32, &choice.intensity);
  anariCommitParameters(device, out.light);
  anariRelease(device, radiance);
  return out;
}

Lighting lightingFor(
    const scenes::Scene &scene, const EnvironmentChoice &choice)
{
  Lighting lighting;
  lighting.environment = choice;
  if (choice.source == "none")
    return lighting;
  if (choice.given) {
    lighting.add = true;
  } else if (scene.expectsEnvironment) {
    lighting.add = true;
    if (!scene.lights.empty())
      lighting.environment.intensity *= kFillIntensity;
  }
  return lighting;
}

void addWorldLight(ANARIDevice device, scenes::Scene &scene, ANARILight light)
{
  std::vector<ANARIObject> lights(scene.lights.begin(), scene.lights.end());
  lights.push_back(light);
  scenes::setObjectArray(device, scene.world, "light", ANARI_LIGHT, lights);
  anariCommitParameters(device, scene.world);
  scene.lights.push_back(light);
}

} // namespace prism::scene_io
