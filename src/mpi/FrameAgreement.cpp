#include "FrameAgreement.h"
#include "RenderMode.h"

#include "anari/frontend/type_utility.h"

#include <cstdio>
#include <cstring>
#include <map>
#include <vector>

namespace prism::mpi {
namespace {

// "name: A on ranks 0,2, B on rank 1" when the ranks' values differ;
// returns whether they did.
template <typename Value, typename Describe>
bool listDifferences(std::string &message,
    const char *name,
    const std::vector<FrameDescriptor> &all,
    Value value,
    Describe describe)
{
  std::map<decltype(value(all[0])), std::vector<int>> ranksByValue;
  for (size_t rank = 0; rank < all.size(); rank++)
    ranksByValue[value(all[rank])].push_back(int(rank));
  if (ranksByValue.size() < 2)
    return false;
  message += message.empty() ? "" : "; ";
  message += name;
  message += ":";
  bool first = true;
  for (const auto &[key, ranks] : ranksByValue) {
    message += first ? " " : ", ";
    first = false;
    message += describe(key);
    message += ranks.size() > 1 ? " on ranks " : " on rank ";
    for (size_t i = 0; i < ranks.size(); i++) {
      message += i ? "," : "";
      message += std::to_string(ranks[i]);
    }
  }
  return true;
}

// A hash as 16 hex digits.
std::string hexadecimal(uint64_t hash)
{
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", (unsigned long long)hash);
  return text;
}

} // namespace

std::string describeDisagreement(const std::vector<FrameDescriptor> &all)
{
  auto number = [](uint64_t v) {
    return std::to_string(v);
  };
  std::string message;
  listDifferences(
      message,
      "frame (creation order)",
      all,
      [](const FrameDescriptor &d) { return d.frameIndex; },
      number);
  listDifferences(
      message,
      "collective renders so far",
      all,
      [](const FrameDescriptor &d) { return d.renderIndex; },
      number);
  listDifferences(
      message,
      "size",
      all,
      [](const FrameDescriptor &d) {
        return (uint64_t(d.width) << 32) | d.height;
      },
      [](uint64_t v) {
        return std::to_string(v >> 32) + "x" + std::to_string(v & 0xffffffffu);
      });
  listDifferences(
      message,
      "mode",
      all,
      [](const FrameDescriptor &d) { return d.mode; },
      [](uint32_t v) { return std::string(toString(RenderMode(v))); });
  listDifferences(
      message,
      "frame validity",
      all,
      [](const FrameDescriptor &d) { return d.valid; },
      [](uint32_t v) { return std::string(v ? "valid" : "invalid"); });
  listDifferences(
      message,
      "channels",
      all,
      [](const FrameDescriptor &d) {
        std::string enabled;
        for (int c = 0; c < kChannelCount; c++) {
          if (d.channelTypes[c] == ANARI_UNKNOWN)
            continue;
          enabled += enabled.empty() ? "" : " ";
          enabled.append(kChannelNames[c])
              .append("=")
              .append(anari::toString(ANARIDataType(d.channelTypes[c])));
        }
        return enabled.empty() ? std::string("none") : enabled;
      },
      [](const std::string &v) { return std::string("{").append(v) + "}"; });
  const bool renderersDiffer = listDifferences(
      message,
      "renderer",
      all,
      [](const FrameDescriptor &d) {
        return std::string(d.renderer, strnlen(d.renderer, sizeof(d.renderer)));
      },
      [](const std::string &v) { return "'" + v + "'"; });
  // Parameters are compared where the subtypes agree (the hash covers the
  // subtype too, and a difference is named once).
  if (!renderersDiffer) {
    listDifferences(
        message,
        "renderer parameters (a hash of them)",
        all,
        [](const FrameDescriptor &d) { return d.rendererContent; },
        hexadecimal);
  }
  listDifferences(
      message,
      "camera (a hash of its subtype and parameters)",
      all,
      [](const FrameDescriptor &d) { return d.cameraContent; },
      hexadecimal);
  const bool worldsDiffer = listDifferences(
      message,
      "world (bounds, primitives, lights, volumes)",
      all,
      [](const FrameDescriptor &d) {
        const float *b = d.worldBounds;
        char text[256];
        std::snprintf(text,
            sizeof(text),
            "(%g,%g,%g)-(%g,%g,%g), %llu primitives, %u lights, %u volumes",
            b[0],
            b[1],
            b[2],
            b[3],
            b[4],
            b[5],
            (unsigned long long)d.worldPrimitives,
            d.worldLights,
            d.worldVolumes);
        return std::string(text);
      },
      [](const std::string &v) { return v; });
  // Contents are compared where the sizes agree, so a difference of sizes
  // is not named twice.
  if (!worldsDiffer) {
    listDifferences(
        message,
        "world contents (a hash of the committed world)",
        all,
        [](const FrameDescriptor &d) { return d.worldContent; },
        hexadecimal);
  }
  return message;
}

} // namespace prism::mpi
