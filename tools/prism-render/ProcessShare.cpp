#include "ProcessShare.h"

namespace prism::render {

std::optional<scenes::Partition> processShare(ANARIDevice device)
{
  // Every process creates this frame, in the same place of its sequence
  // of frames, so frames still correspond across processes by order.
  ANARIFrame frame = anariNewFrame(device);
  anariCommitParameters(device, frame);
  int32_t rank = -1, size = 0;
  const bool answered = anariGetProperty(device,
                            frame,
                            "mpiRank",
                            ANARI_INT32,
                            &rank,
                            sizeof(rank),
                            ANARI_NO_WAIT)
                        && anariGetProperty(device,
                            frame,
                            "mpiSize",
                            ANARI_INT32,
                            &size,
                            sizeof(size),
                            ANARI_NO_WAIT);
  anariRelease(device, frame);
  if (!answered || rank < 0 || size < 1 || rank >= size)
    return std::nullopt;
  return scenes::Partition{uint32_t(rank), uint32_t(size)};
}

} // namespace prism::render
