// From a rendered frame to image files: the channels requested on the
// command line are mapped, checked against what was asked for, converted to
// images and only then written, so a failure leaves no partial set behind.
#pragma once

#include "Image.h"
#include "Options.h"

#include <anari/anari.h>

#include <string>
#include <vector>

namespace prism::render {

// One file to write: which frame channel, in which mapped type, where.
struct ChannelRequest
{
  std::string channel; // "channel.color", ...
  ANARIDataType type;
  std::string path;
  enum class Kind { Color, Depth, Normal, Albedo, Id } kind;
};

// The channels `options` asks for; `colorPath` is the main output.
std::vector<ChannelRequest> channelRequests(
    const Options &options, const std::string &colorPath);

// The extension a channel needs ("ANARI_KHR_FRAME_CHANNEL_NORMAL"), or
// nullptr for core channels.
const char *channelExtension(const ChannelRequest &request);

struct OutputImage
{
  std::string path;
  image::Image image;
};

// Maps each requested channel of `frame` and converts it. Warnings (e.g. a
// frame smaller than requested) are appended; the error names the channel.
std::string readChannels(ANARIDevice device,
    ANARIFrame frame,
    const std::vector<ChannelRequest> &requests,
    uint32_t width,
    uint32_t height,
    std::vector<OutputImage> &images,
    std::vector<std::string> &warnings);

// Writes every image (each atomically); the error names the file.
std::string writeImages(const std::vector<OutputImage> &images);

} // namespace prism::render
