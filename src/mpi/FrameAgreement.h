// What every process of a communicator must agree on before a collective
// render, exchanged in one allgather so a disagreement is reported on every
// process instead of leaving some of them waiting in a collective forever.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>

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
  uint32_t width{0};
  uint32_t height{0};
  uint32_t mode{0};
  uint32_t valid{0}; // whether the frame has a valid world, camera, renderer
  // ANARIDataType of each of kChannelNames, ANARI_UNKNOWN when not enabled.
  uint32_t channelTypes[kChannelCount]{};
  char renderer[32]{}; // the renderer's subtype, cut to fit
};

// Empty when every process of `communicator` gave the same descriptor,
// otherwise one line naming each disagreement and the ranks on each side.
std::string disagreement(
    const FrameDescriptor &local, MPI_Comm communicator, bool &allValid);

} // namespace prism::mpi
