// The neutral studio prism-render lights files with by default (see
// Environment.h), as float radiance: a sky over a floor with two soft
// lights. Smooth everywhere, and fine enough (1024 x 512, 0.35 degrees a
// texel) that mirror reflections show no texel structure: the hdri light
// filters bilinearly, but a coarse image still blurs and a step in the
// function still shows on the background and in reflections.
#pragma once

#include "Math.h"

#include <cstddef>
#include <vector>

namespace prism::scene_io {

constexpr size_t kStudioWidth = 1024, kStudioHeight = 512;

// Radiance towards (azimuth, elevation), in radians.
scenes::Vec3 studioRadiance(float azimuth, float elevation);

// The studio as an equirectangular image, first row towards up, at texel
// centres.
std::vector<scenes::Vec3> studioImage(size_t width, size_t height);

// The mean radiance over the sphere of an equirectangular image, each row
// weighted by the solid angle it covers.
scenes::Vec3 meanRadiance(
    const std::vector<scenes::Vec3> &texels, size_t width, size_t height);

} // namespace prism::scene_io
