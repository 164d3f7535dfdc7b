#include "FrameOutput.h"

#include "ImageIO.h"

#include <anari/frontend/type_utility.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>

namespace prism::render {
namespace {

bool endsWithPng(const std::string &path)
{
  std::string lower = path;
  for (char &c : lower)
    c = char(std::tolower((unsigned char)c));
  return lower.size() >= 4 && lower.compare(lower.size() - 4, 4, ".png") == 0;
}

// A well-spread color for an id; ~0u ("nothing") is black.
image::Rgba idColor(uint32_t id)
{
  if (id == 0xffffffffu)
    return {0.f, 0.f, 0.f, 1.f};
  uint32_t h = id + 0x9e3779b9u;
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  auto channel = [&](int shift) {
    return 0.15f + 0.85f * float((h >> shift) & 0xffu) / 255.f;
  };
  return {channel(0), channel(8), channel(16), 1.f};
}

std::string typeName(ANARIDataType type)
{
  return anari::toString(type);
}

} // namespace

std::vector<ChannelRequest> channelRequests(
    const Options &options, const std::string &colorPath)
{
  using Kind = ChannelRequest::Kind;
  std::vector<ChannelRequest> requests = {
      {"channel.color", ANARI_FLOAT32_VEC4, colorPath, Kind::Color}};
  if (!options.depthPath.empty())
    requests.push_back(
        {"channel.depth", ANARI_FLOAT32, options.depthPath, Kind::Depth});
  if (!options.normalPath.empty())
    requests.push_back({"channel.normal",
        ANARI_FLOAT32_VEC3,
        options.normalPath,
        Kind::Normal});
  if (!options.albedoPath.empty())
    requests.push_back({"channel.albedo",
        ANARI_FLOAT32_VEC3,
        options.albedoPath,
        Kind::Albedo});
  if (!options.idsPrefix.empty()) {
    for (const char *id : {"primitiveId", "objectId", "instanceId"})
      requests.push_back({std::string("channel.") + id,
          ANARI_UINT32,
          options.idsPrefix + "." + id + ".png",
          Kind::Id});
  }
  return requests;
}

const char *channelExtension(const ChannelRequest &request)
{
  if (request.channel == "channel.normal")
    return "ANARI_KHR_FRAME_CHANNEL_NORMAL";
  if (request.channel == "channel.albedo")
    return "ANARI_KHR_FRAME_CHANNEL_ALBEDO";
  if (request.channel == "channel.primitiveId")
    return "ANARI_KHR_FRAME_CHANNEL_PRIMITIVE_ID";
  if (request.channel == "channel.objectId")
    return "ANARI_KHR_FRAME_CHANNEL_OBJECT_ID";
  if (request.channel == "channel.instanceId")
    return "ANARI_KHR_FRAME_CHANNEL_INSTANCE_ID";
  return nullptr;
}

namespace {

// Each converter turns `count` mapped pixels of `type` into `pixels`;
// false when the channel came in a type it does not take.
bool convertColor(ANARIDataType type,
    const void *mapped,
    size_t count,
    std::vector<image::Rgba> &pixels)
{
  if (type == ANARI_FLOAT32_VEC4) {
    std::memcpy(pixels.data(), mapped, count * sizeof(image::Rgba));
    return true;
  }
  if (type != ANARI_UFIXED8_RGBA_SRGB && type != ANARI_UFIXED8_VEC4)
    return false;
  const auto *bytes = (const uint8_t *)mapped;
  for (size_t i = 0; i < count; i++) {
    for (int c = 0; c < 3; c++) {
      const float v = bytes[4 * i + c] / 255.f;
      pixels[i][c] =
          type == ANARI_UFIXED8_RGBA_SRGB ? image::linearFromSrgb(v) : v;
    }
    pixels[i].a = bytes[4 * i + 3] / 255.f;
  }
  return true;
}

// Distances as they are (EXR, PFM), or for PNG near bright and far dim, the
// range filling [0.15, 1] so the farthest surface stays distinct from the
// background; nothing hit is 0 (and transparent where alpha exists).
bool convertDepth(ANARIDataType type,
    const void *mapped,
    size_t count,
    bool png,
    std::vector<image::Rgba> &pixels)
{
  if (type != ANARI_FLOAT32)
    return false;
  const auto *depth = (const float *)mapped;
  float nearest = std::numeric_limits<float>::infinity();
  float farthest = -nearest;
  for (size_t i = 0; i < count; i++)
    if (std::isfinite(depth[i])) {
      nearest = std::min(nearest, depth[i]);
      farthest = std::max(farthest, depth[i]);
    }
  for (size_t i = 0; i < count; i++) {
    const float d = depth[i];
    if (!std::isfinite(d)) {
      pixels[i] = {0.f, 0.f, 0.f, png ? 1.f : 0.f};
    } else if (png) {
      const float span = farthest - nearest;
      const float t = span > 0.f ? (farthest - d) / span : 1.f;
      const float v = 0.15f + 0.85f * t;
      pixels[i] = {v, v, v, 1.f};
    } else {
      pixels[i] = {d, d, d, 1.f};
    }
  }
  return true;
}

// Normals (PNG: n * 0.5 + 0.5) and albedo (float or 8-bit).
bool convertVector(ANARIDataType type,
    const void *mapped,
    size_t count,
    bool isNormal,
    bool png,
    std::vector<image::Rgba> &pixels)
{
  if (type == ANARI_FLOAT32_VEC3) {
    const auto *v = (const float *)mapped;
    for (size_t i = 0; i < count; i++) {
      float rgb[3] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
      if (isNormal && png)
        for (float &c : rgb)
          c = c * 0.5f + 0.5f;
      pixels[i] = {rgb[0], rgb[1], rgb[2], 1.f};
    }
    return true;
  }
  if (isNormal
      || (type != ANARI_UFIXED8_VEC3 && type != ANARI_UFIXED8_RGB_SRGB))
    return false;
  const auto *bytes = (const uint8_t *)mapped;
  for (size_t i = 0; i < count; i++) {
    for (int c = 0; c < 3; c++) {
      const float v = bytes[3 * i + c] / 255.f;
      pixels[i][c] =
          type == ANARI_UFIXED8_RGB_SRGB ? image::linearFromSrgb(v) : v;
    }
    pixels[i].a = 1.f;
  }
  return true;
}

bool convertIds(ANARIDataType type,
    const void *mapped,
    size_t count,
    std::vector<image::Rgba> &pixels)
{
  if (type != ANARI_UINT32)
    return false;
  for (size_t i = 0; i < count; i++) {
    uint32_t id;
    std::memcpy(&id, (const unsigned char *)mapped + 4 * i, 4);
    pixels[i] = idColor(id);
  }
  return true;
}

bool convert(const ChannelRequest &request,
    ANARIDataType type,
    const void *mapped,
    size_t count,
    std::vector<image::Rgba> &pixels)
{
  using Kind = ChannelRequest::Kind;
  const bool png = endsWithPng(request.path);
  switch (request.kind) {
  case Kind::Color:
    return convertColor(type, mapped, count, pixels);
  case Kind::Depth:
    return convertDepth(type, mapped, count, png, pixels);
  case Kind::Normal:
  case Kind::Albedo:
    return convertVector(
        type, mapped, count, request.kind == Kind::Normal, png, pixels);
  case Kind::Id:
    return convertIds(type, mapped, count, pixels);
  }
  return false;
}

} // namespace

std::string readChannels(ANARIDevice device,
    ANARIFrame frame,
    const std::vector<ChannelRequest> &requests,
    uint32_t width,
    uint32_t height,
    std::vector<OutputImage> &images,
    std::vector<std::string> &warnings)
{
  for (const ChannelRequest &request : requests) {
    uint32_t w = 0, h = 0;
    ANARIDataType type = ANARI_UNKNOWN;
    const void *mapped =
        anariMapFrame(device, frame, request.channel.c_str(), &w, &h, &type);
    if (!mapped || w == 0 || h == 0) {
      if (mapped)
        anariUnmapFrame(device, frame, request.channel.c_str());
      return "the device delivered no " + request.channel + " for '"
             + request.path + "'";
    }
    if (w != width || h != height)
      warnings.push_back("the device delivered a " + std::to_string(w) + "x"
                         + std::to_string(h) + " " + request.channel + " for a "
                         + std::to_string(width) + "x" + std::to_string(height)
                         + " frame; '" + request.path
                         + "' gets what it delivered");
    OutputImage out{request.path, image::Image(w, h)};
    const bool converted =
        convert(request, type, mapped, size_t(w) * h, out.image.pixels);
    anariUnmapFrame(device, frame, request.channel.c_str());
    if (!converted)
      return request.channel + " came as " + typeName(type) + ", not "
             + typeName(request.type) + "; '" + request.path + "' not written";
    images.push_back(std::move(out));
  }
  return {};
}

std::string writeImages(const std::vector<OutputImage> &images)
{
  for (const OutputImage &out : images) {
    // EXR as float32: the files carry data (depth, references) as often
    // as pictures, and float keeps every value.
    const image::Status status = image::write(out.path, out.image);
    if (!status.ok())
      return status.error;
  }
  return {};
}

} // namespace prism::render
