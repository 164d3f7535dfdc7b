#include "Channel.h"

namespace prism::viewer {

const char *channelName(Channel channel)
{
  switch (channel) {
  case Channel::Color:
    return "color";
  case Channel::Depth:
    return "depth";
  case Channel::Normal:
    return "normal";
  case Channel::Albedo:
    return "albedo";
  case Channel::ObjectId:
    return "objectId";
  case Channel::PrimitiveId:
    return "primitiveId";
  case Channel::InstanceId:
    return "instanceId";
  }
  return "color";
}

std::string channelParameter(Channel channel)
{
  return std::string("channel.") + channelName(channel);
}

std::optional<Channel> channelNamed(const std::string &name)
{
  const std::string bare =
      name.rfind("channel.", 0) == 0 ? name.substr(8) : name;
  for (Channel c : kAllChannels)
    if (bare == channelName(c))
      return c;
  return std::nullopt;
}

} // namespace prism::viewer
