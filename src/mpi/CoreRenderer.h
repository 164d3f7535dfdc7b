// The prism core in this process as the local renderer of prism_mpi: its
// device renders every frame, shared as the collective parts ask
// (Frame::share: tile rows, kept depth, no background, lockstep), lit by
// the lights the processes exchange, its paths traced across processes
// through the device's transport source.
#pragma once

#include "LocalRenderer.h"

namespace prism {
class Device;
class Frame;
class World;
} // namespace prism

namespace prism::mpi {

class CoreRenderer : public LocalRenderer
{
 public:
  explicit CoreRenderer(ANARILibrary library);
  ~CoreRenderer() override;
  CoreRenderer(const CoreRenderer &) = delete;
  CoreRenderer &operator=(const CoreRenderer &) = delete;

  anari::DeviceImpl &device() override;
  std::string description() const override;
  bool renders(RenderMode mode) const override;
  bool rendersApplicationPixels() const override;
  ANARIDataType typeOf(ANARIObject handle) override;
  void setThreads(int threads) override;
  bool describe(ANARIFrame frame, RenderMode mode, FrameDescriptor &d) override;
  ANARIDataType channelType(ANARIFrame frame, int channel) override;
  bool denoises(ANARIFrame frame) override;
  void renderAlone(ANARIFrame frame) override;
  LinearImage renderForCompositing(
      ANARIFrame frame, MPI_Comm communicator, uint64_t &bytesSent) override;
  BackgroundAt backgroundOf(
      ANARIFrame frame, uint32_t width, uint32_t height) override;
  void renderTileRows(ANARIFrame frame, uint32_t part, uint32_t parts) override;
  uint32_t tileSize() const override;
  bool tracesWavefronts(ANARIFrame frame) override;
  void renderPathsAcross(
      ANARIFrame frame, MPI_Comm communicator, uint64_t &bytesSent) override;

 private:
  // The live frame behind `handle`, or NULL.
  Frame *frameOf(ANARIFrame handle) const;
  // shareLights() for `world`, its problem reported as a warning on the
  // frame; returns the bytes sent.
  uint64_t shareWorldLights(ANARIFrame handle,
      World &world,
      MPI_Comm communicator,
      bool withEmitters);

  Device *m_device{nullptr};
};

} // namespace prism::mpi
