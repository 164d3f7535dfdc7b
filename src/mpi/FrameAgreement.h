// What every process of a communicator must agree on before a collective
// render, so a disagreement is reported on every process instead of leaving
// some of them waiting in a collective forever.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace prism::mpi {

// Every channel a frame may enable, in the order descriptors list them.
inline const char *const kChannelNames[] = {"channel.color",
    "channel.depth",
    "channel.normal",
    "channel.albedo",
    "channel.primitiveId",
    "channel.objectId",
    "channel.instanceId"};
constexpr int kChannelCount = 7;

struct FrameDescriptor
{
  uint64_t frameIndex{0};  // creation order of the frame on this device
  uint64_t renderIndex{0}; // how many collective renders it had before
  // This process's count of meetings at anariRenderFrame, so each answer is
  // matched to its question (processes may count differently: not compared).
  uint64_t attempt{0};
  uint32_t width{0};
  uint32_t height{0};
  uint32_t mode{0};
  uint32_t valid{0}; // whether the frame has a valid world, camera, renderer
  // ANARIDataType of each of kChannelNames, ANARI_UNKNOWN when not enabled.
  uint32_t channelTypes[kChannelCount]{};
  char renderer[32]{}; // the renderer's subtype, cut to fit
  // Content hashes (Object::contentHash(): subtype and committed parameters,
  // in no particular order of setting) of the frame's renderer and camera,
  // in every mode: the spec wants their parameters alike on every process.
  // 0 when the frame has none.
  uint64_t rendererContent{0};
  uint64_t cameraContent{0};
  // A cheap fingerprint of the world, set only where every process must
  // hold the same one (replicated mode): its bounds and how many surface
  // primitives, lights and volumes it places, and a hash of its contents
  // (Object::contentHash()) for worlds alike in those.
  float worldBounds[6]{};
  uint64_t worldPrimitives{0};
  uint32_t worldLights{0};
  uint32_t worldVolumes{0};
  uint64_t worldContent{0};
};

// Empty when every descriptor (one per rank, in rank order) is the same,
// otherwise one line naming each disagreement and the ranks on each side.
std::string describeDisagreement(const std::vector<FrameDescriptor> &all);

} // namespace prism::mpi
