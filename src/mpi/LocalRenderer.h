// What one process renders by itself for the collective frames of
// DataParallelDevice, and what of a frame the processes compare first: the
// narrow interface between the collective parts (Rendezvous, compositing,
// row gathering, distributed transport) and the device that renders.
// CoreRenderer is the prism core in this process; WrappedDevice is any
// other library's device, reached through the forwarding device.
#pragma once

#include "FrameAgreement.h"
#include "RenderMode.h"

#include "math/Vec.h"

#include "anari/backend/DeviceImpl.h"

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace prism::mpi {

// This process's linear color and depth of a frame (each NULL or empty
// when it has none); owned by the renderer until its next render.
struct LinearImage
{
  const std::vector<float4> *color{nullptr};
  const std::vector<float> *depth{nullptr};
};

class LocalRenderer
{
 public:
  virtual ~LocalRenderer() = default;

  // The device the application's calls are forwarded to.
  virtual anari::DeviceImpl &device() = 0;
  // What renders, for messages: "the built-in prism core", "library 'x'".
  virtual std::string description() const = 0;
  // Whether frames render in `mode` (those of the others are composited).
  virtual bool renders(RenderMode mode) const = 0;
  // Whether the frame's channels hold the application's pixels after a
  // local render (the prism core), or linear color and depth that must be
  // converted (a wrapped device, even without MPI).
  virtual bool rendersApplicationPixels() const = 0;
  // The object type of a live handle; ANARI_UNKNOWN for any other.
  virtual ANARIDataType typeOf(ANARIObject handle) = 0;
  // The device's worker threads (the `numThreads` device parameter).
  virtual void setThreads(int threads) = 0;

  // The committed frame as the processes compare it (pending commits
  // applied first); false (and `d` untouched) if `frame` is no live frame.
  virtual bool describe(
      ANARIFrame frame, RenderMode mode, FrameDescriptor &d) = 0;
  // The application's pixel type of kChannelNames[channel] (ANARI_UNKNOWN:
  // not enabled).
  virtual ANARIDataType channelType(ANARIFrame frame, int channel) = 0;
  // Whether the frame's renderer asks for denoising.
  virtual bool denoises(ANARIFrame frame) = 0;
  // Renders a frame some process cannot render, so it reports what it
  // lacks.
  virtual void renderAlone(ANARIFrame frame) = 0;

  // Composite mode: this process's linear color and depth, without the
  // background, lit by what the processes exchange over `communicator`
  // (counted in `bytesSent`).
  virtual LinearImage renderForCompositing(
      ANARIFrame frame, MPI_Comm communicator, uint64_t &bytesSent) = 0;
  // The background rank 0 puts under the composite: its value at pixel
  // (x, y) of a `width` x `height` image.
  using BackgroundAt = std::function<float4(uint32_t x, uint32_t y)>;
  virtual BackgroundAt backgroundOf(
      ANARIFrame frame, uint32_t width, uint32_t height) = 0;

  // Replicated mode (renders(Replicated)): rows of tiles `part` of `parts`,
  // tiles `tileSize()` pixels wide.
  virtual void renderTileRows(ANARIFrame frame, uint32_t part, uint32_t parts)
  {}
  virtual uint32_t tileSize() const
  {
    return 0;
  }

  // Pathtracer mode (renders(PathTracer)): whether the frame's renderer
  // traces wavefronts, and then the frame traced across the processes.
  virtual bool tracesWavefronts(ANARIFrame frame)
  {
    return false;
  }
  virtual void renderPathsAcross(
      ANARIFrame frame, MPI_Comm communicator, uint64_t &bytesSent)
  {}
};

} // namespace prism::mpi
