// NSI's screen window, field of view and crop turned into an ANARI camera
// sensor and image region (docs/nsi.md, "Cameras"). Pure arithmetic, no
// ANARI calls, so tests can check it on its own.
#pragma once

#include <array>
#include <cstdint>

namespace prism::nsi {

struct ScreenSettings
{
  uint32_t width{640}, height{480};
  double pixelAspectRatio{1.0};
  bool hasWindow{false};
  std::array<double, 4> window{};         // left, bottom, right, top
  std::array<double, 4> crop{0, 0, 1, 1}; // x0, y0 (top-left), x1, y1; y down
};

struct Framing
{
  float fovy{0};   // perspective: radians
  float height{0}; // orthographic: sensor height in camera units
  float aspect{1}; // sensor width / height
  std::array<float, 4> imageRegion{0, 0, 1, 1}; // ANARI box2: x0 y0 x1 y1
  uint32_t frameWidth{1}, frameHeight{1};       // the cropped image's pixels
};

// `fovDegrees` is ignored for orthographic cameras.
Framing frameCamera(
    bool orthographic, double fovDegrees, const ScreenSettings &screen);

} // namespace prism::nsi
