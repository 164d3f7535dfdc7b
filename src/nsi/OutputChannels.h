// NSI output-layer variables and the ANARI frame channels that hold them:
// Ci -> channel.color, z -> channel.depth (distance to the camera, as ANARI
// defines it), N.world -> channel.normal, albedo -> channel.albedo.
#pragma once

#include "Image.h"

#include <anari/anari.h>

#include <string>

namespace prism::nsi {

struct FrameChannel
{
  const char *name;   // "channel.depth"
  ANARIDataType type; // what the frame is asked for
  int components;     // floats per pixel
};

// The channel for `variableName`, or nullptr when ANARI has none.
const FrameChannel *channelForVariable(const std::string &variableName);

// The channel of a rendered frame as an RGBA image: one component is
// grey, three are RGB; alpha is 1 unless the channel has one.
image::Image readFrameChannel(
    ANARIDevice device, ANARIFrame frame, const FrameChannel &channel);

} // namespace prism::nsi
