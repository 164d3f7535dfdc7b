#include "Environment.h"

#include "Objects.h"
#include "TextureFile.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace prism::scene_io {
namespace {

using scenes::Vec3;
using scenes::operator+;
using scenes::operator*;

constexpr float kPi = std::numbers::pi_v<float>;

// A soft-edged round light source in the studio: radiance inside
// `radius` (radians) around (azimuth, elevation), fading over a tenth more.
struct Softbox
{
  float azimuth, elevation, radius;
  Vec3 radiance;
};

float smoothstep(float edge0, float edge1, float x)
{
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

// Radiance of the studio towards (azimuth, elevation): a bright neutral sky
// over a darker floor, a key light up front to one side and a weaker fill
// behind, so shapes read and glossy surfaces show highlights. The average
// over the sphere is about 1, so diffuse surfaces look near their albedo.
Vec3 studioRadiance(float azimuth, float elevation)
{
  static const Softbox boxes[] = {
      {0.7f, 0.75f, 0.28f, {7.f, 6.8f, 6.5f}},
      {-2.1f, 0.45f, 0.35f, {2.f, 2.1f, 2.3f}},
  };
  const float e = std::sin(elevation);
  const Vec3 horizon{1.f, 1.f, 1.f};
  const Vec3 zenith{0.85f, 0.9f, 1.f};
  const Vec3 floor{0.32f, 0.3f, 0.28f};
  Vec3 radiance = e >= 0.f
                      ? horizon * (1.f - std::sqrt(e)) + zenith * std::sqrt(e)
                      : horizon * 0.6f * (1.f - smoothstep(0.f, 0.25f, -e))
                            + floor * smoothstep(0.f, 0.25f, -e);
  for (const Softbox &box : boxes) {
    // Angle between the direction and the box's centre on the sphere.
    const float cosAngle = std::sin(elevation) * std::sin(box.elevation)
                           + std::cos(elevation) * std::cos(box.elevation)
                                 * std::cos(azimuth - box.azimuth);
    const float angle = std::acos(std::clamp(cosAngle, -1.f, 1.f));
    const float inside =
        1.f - smoothstep(box.radius * 0.9f, box.radius * 1.1f, angle);
    radiance = radiance + box.radiance * inside;
  }
  return radiance;
}

// The studio as an equirectangular image, first row towards `up`.
std::vector<Vec3> studioImage(size_t width, size_t height)
{
  std::vector<Vec3> texels(width * height);
  for (size_t j = 0; j < height; j++) {
    const float elevation = kPi * (0.5f - (float(j) + 0.5f) / float(height));
    for (size_t i = 0; i < width; i++) {
      const float azimuth =
          2.f * kPi * ((float(i) + 0.5f) / float(width) - 0.5f);
      texels[j * width + i] = studioRadiance(azimuth, elevation);
    }
  }
  return texels;
}

// A direction across `up` for the image's centre column, turned by
// `degrees` about `up`.
Vec3 centreDirection(const Vec3 &up, float degrees)
{
  const Vec3 u = scenes::normalize(up);
  // Towards +z for y-up scenes (where viewers put the camera), else any.
  Vec3 forward = std::abs(u[2]) < 0.9f ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  forward = scenes::normalize(forward + u * -scenes::dot(forward, u));
  const Vec3 side = scenes::cross(u, forward);
  const float a = degrees * kPi / 180.f;
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
    width = 256;
    height = 128;
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
