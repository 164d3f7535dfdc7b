// The frame channels the viewer shows and reads (ANARI's channel.*), and
// their names as the UI and the script spell them.
#pragma once

#include <optional>
#include <string>

namespace prism::viewer {

enum class Channel {
  Color,
  Depth,
  Normal,
  Albedo,
  ObjectId,
  PrimitiveId,
  InstanceId
};

constexpr Channel kAllChannels[] = {Channel::Color,
    Channel::Depth,
    Channel::Normal,
    Channel::Albedo,
    Channel::ObjectId,
    Channel::PrimitiveId,
    Channel::InstanceId};

// "color", "depth", ... "instanceId".
const char *channelName(Channel channel);
// "channel.color", ...
std::string channelParameter(Channel channel);
// From "color" or "channel.color"; nothing for other names.
std::optional<Channel> channelNamed(const std::string &name);

} // namespace prism::viewer
