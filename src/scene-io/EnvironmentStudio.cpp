#include "EnvironmentStudio.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace prism::scene_io {
namespace {

using scenes::Vec3;
using scenes::operator+;
using scenes::operator*;

constexpr float kPi = std::numbers::pi_v<float>;

// A soft-edged round light source in the studio: radiance inside
// `radius` (radians) around (azimuth, elevation), fading from 0.6 to 1.4
// radii (wide enough to span dozens of texels, so the edge is no step).
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

} // namespace

// A bright neutral sky over a darker floor, a key light up front to one
// side and a weaker fill behind, so shapes read and glossy surfaces show
// highlights. The sky meets the floor without a step (the horizon fades
// down over sin(elevation) 0 to -0.25); the floor is as dark as keeps the
// mean radiance that of the first studio, about 0.83.
Vec3 studioRadiance(float azimuth, float elevation)
{
  static const Softbox boxes[] = {
      {0.7f, 0.75f, 0.28f, {7.f, 6.8f, 6.5f}},
      {-2.1f, 0.45f, 0.35f, {2.f, 2.1f, 2.3f}},
  };
  const float e = std::sin(elevation);
  const Vec3 horizon{1.f, 1.f, 1.f};
  const Vec3 zenith{0.85f, 0.9f, 1.f};
  const Vec3 floor{0.25f, 0.234f, 0.218f};
  const float down = smoothstep(0.f, 0.25f, -e);
  Vec3 radiance = e >= 0.f
                      ? horizon * (1.f - std::sqrt(e)) + zenith * std::sqrt(e)
                      : horizon * (1.f - down) + floor * down;
  for (const Softbox &box : boxes) {
    // Angle between the direction and the box's centre on the sphere.
    const float cosAngle = std::sin(elevation) * std::sin(box.elevation)
                           + std::cos(elevation) * std::cos(box.elevation)
                                 * std::cos(azimuth - box.azimuth);
    const float angle = std::acos(std::clamp(cosAngle, -1.f, 1.f));
    const float inside =
        1.f - smoothstep(box.radius * 0.6f, box.radius * 1.4f, angle);
    radiance = radiance + box.radiance * inside;
  }
  return radiance;
}

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

Vec3 meanRadiance(const std::vector<Vec3> &texels, size_t width, size_t height)
{
  double sum[3] = {0, 0, 0};
  for (size_t j = 0; j < height; j++) {
    // The band between polar angles j/h and (j+1)/h of pi: a fraction
    // (cos a - cos b) / 2 of the sphere, shared by the row's texels.
    const double a = std::numbers::pi * double(j) / double(height);
    const double b = std::numbers::pi * double(j + 1) / double(height);
    const double weight = (std::cos(a) - std::cos(b)) / 2 / double(width);
    for (size_t i = 0; i < width; i++)
      for (int c = 0; c < 3; ++c)
        sum[c] += weight * texels[j * width + i][c];
  }
  return {float(sum[0]), float(sum[1]), float(sum[2])};
}

} // namespace prism::scene_io
