#include "CameraFraming.h"

#include <algorithm>
#include <cmath>

namespace prism::nsi {

Framing frameCamera(
    bool orthographic, double fovDegrees, const ScreenSettings &screen)
{
  const double width = std::max<uint32_t>(screen.width, 1);
  const double height = std::max<uint32_t>(screen.height, 1);
  const double a = width * screen.pixelAspectRatio / height;
  double l = -a, b = -1, r = a, t = 1;
  auto finite = [](const std::array<double, 4> &v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])
           && std::isfinite(v[3]);
  };
  if (screen.hasWindow && finite(screen.window)) {
    l = screen.window[0];
    b = screen.window[1];
    r = screen.window[2];
    t = screen.window[3];
  }
  if (!(r > l))
    std::swap(l, r);
  if (!(t > b))
    std::swap(b, t);
  if (r == l) // a degenerate window: fall back to the default one
    l = -a, r = a;
  if (t == b)
    b = -1, t = 1;

  // The window at distance 1 (perspective) or in camera units (ortho).
  const double fov = std::clamp(fovDegrees, 1e-3, 179.0);
  const double s = orthographic ? 1.0 : std::tan(fov * M_PI / 360.0);
  // ANARI sensors are centred: take the symmetric one enclosing the window.
  const double halfWidth = std::max(std::abs(l), std::abs(r)) * s;
  const double halfHeight = std::max(std::abs(b), std::abs(t)) * s;

  Framing framing;
  framing.aspect = float(halfWidth / halfHeight);
  if (orthographic)
    framing.height = float(2 * halfHeight);
  else
    framing.fovy = float(2 * std::atan(halfHeight));

  // Crop whole pixels (y counts from the top), so a cropped image is
  // exactly those pixels of the uncropped one.
  auto pixelRange =
      [](double lo, double hi, double size, uint32_t &first, uint32_t &end) {
        lo = std::clamp(lo, 0.0, 1.0);
        hi = std::clamp(hi, 0.0, 1.0);
        first = uint32_t(std::floor(lo * size));
        end = uint32_t(std::ceil(hi * size));
        first = std::min<uint32_t>(first, uint32_t(size) - 1);
        end = std::max(end, first + 1);
      };
  uint32_t x0, x1, row0, row1;
  const std::array<double, 4> crop =
      finite(screen.crop) ? screen.crop : std::array<double, 4>{0, 0, 1, 1};
  pixelRange(crop[0], crop[2], width, x0, x1);
  pixelRange(crop[1], crop[3], height, row0, row1);
  framing.frameWidth = x1 - x0;
  framing.frameHeight = row1 - row0;

  // Window fractions of the cropped pixels (vertical from the bottom) ...
  const double fx0 = x0 / width, fx1 = x1 / width;
  const double fy0 = 1 - row1 / height, fy1 = 1 - row0 / height;
  // ... placed on the sensor.
  auto sensorX = [&](double f) {
    return float((((l + f * (r - l)) * s) + halfWidth) / (2 * halfWidth));
  };
  auto sensorY = [&](double f) {
    return float((((b + f * (t - b)) * s) + halfHeight) / (2 * halfHeight));
  };
  framing.imageRegion = {
      sensorX(fx0), sensorY(fy0), sensorX(fx1), sensorY(fy1)};
  return framing;
}

} // namespace prism::nsi
