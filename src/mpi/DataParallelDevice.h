// The prism_mpi device (KHR_DATA_PARALLEL_MPI): a forwarding device over a
// local renderer -- the prism core in this process (CoreRenderer) or,
// with the device parameter `wrappedLibrary`, another library's device
// (WrappedDevice) -- that makes anariRenderFrame, waiting world bounds
// queries and frame mapping collective over each frame's MPI communicator.
// Every other call reaches the local renderer's device unchanged.
#pragma once

#include "CoreRenderer.h"
#include "FrameAgreement.h"
#include "MpiSession.h"
#include "RenderMode.h"
#include "Rendezvous.h"
#include "WrappedDevice.h"

#include "ForwardingDevice.h"

#include <mpi.h>

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace prism::mpi {

struct CompositedImage;
class DepthCompositor;

class DataParallelDevice : public ForwardingDevice
{
 public:
  explicit DataParallelDevice(ANARILibrary library);
  ~DataParallelDevice() override;

  // Collective: the render, the channels rank 0 assembled, and waiting
  // world bounds (CollectiveFrames.cpp, DataParallelDevice.cpp).
  void renderFrame(ANARIFrame frame) override;
  const void *frameBufferMap(ANARIFrame frame,
      const char *channel,
      uint32_t *width,
      uint32_t *height,
      ANARIDataType *pixelType) override;
  void frameBufferUnmap(ANARIFrame frame, const char *channel) override;
  int getProperty(ANARIObject object,
      const char *name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;

  // This device's parameters, and the communicators of frames and worlds
  // (DeviceParameters.cpp).
  void setParameter(ANARIObject object,
      const char *name,
      ANARIDataType type,
      const void *mem) override;
  void commitParameters(ANARIObject object) override;
  void unsetParameter(ANARIObject object, const char *name) override;
  void unsetAllParameters(ANARIObject object) override;

  // Lifetimes: the device's own, and the state kept for frames and worlds.
  void retain(ANARIObject object) override;
  void release(ANARIObject object) override;

 protected:
  // The local renderer is chosen at the first object created.
  void beforeCreating(ANARIDataType type) override;
  ANARIObject newObjectOf(ANARIDataType type, const char *subtype) override;

 private:
  // The `mpiCommunicator` parameter of a frame or world: the MPI_Comm read
  // when set, in effect from the object's next commit.
  struct CommunicatorParameter
  {
    MPI_Comm staged{MPI_COMM_WORLD};
    MPI_Comm committed{MPI_COMM_WORLD};
  };
  // One channel as rank 0 maps it after a collective render.
  struct MappedChannel
  {
    ANARIDataType type{ANARI_UNKNOWN};
    std::vector<unsigned char> pixels;
  };
  struct FrameState
  {
    uint64_t index{0};
    uint64_t renders{0};
    CommunicatorParameter communicator;
    uint32_t width{0};
    uint32_t height{0};
    uint64_t bytesSent{0}; // by this process in the last collective render
    // Replicated mode: the pixels every process's rows still sample
    // (adaptive sampling), summed over the processes.
    std::optional<uint64_t> activePixels;
    bool denoiseWarned{false};
    std::map<std::string, MappedChannel> assembled; // rank 0 only
  };
  struct WorldState
  {
    CommunicatorParameter communicator;
  };
  // The application's references to its frames and worlds, whose state
  // goes with the last.
  struct Kept
  {
    int64_t references{1};
  };

  // The inner devices' messages, as this device's.
  static void forwardStatus(const void *userPtr,
      ANARIDevice device,
      ANARIObject source,
      ANARIDataType sourceType,
      ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const char *message);
  void report(ANARIObject source,
      ANARIDataType sourceType,
      ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &message) const;
  void reportBadDeviceParameter(const std::string &message) const;

  // The local renderer, chosen (a loaded library, or the built-in core)
  // at the first call that creates an object; the choice never changes.
  LocalRenderer &local();
  void chooseLocal();
  bool wrapOpen() const
  {
    return !m_wrapChosen.load();
  }
  // The device that answers for this device's own parameters and
  // properties: the core's, whatever renders.
  anari::DeviceImpl &coreDevice()
  {
    return m_core->device();
  }
  ANARIObject coreHandle()
  {
    return (ANARIObject)&m_core->device();
  }

  // Device parameters (DeviceParameters.cpp).
  void setDeviceParameter(
      const std::string &name, ANARIDataType type, const void *mem);
  void unsetDeviceParameter(const std::string &name);
  void setWrapParameter(
      const std::string &name, ANARIDataType type, const void *mem);
  // A device parameter of the application that is not this device's own:
  // the wrapped device gets it too (kept until the device is chosen).
  void passDeviceParameter(
      const std::string &name, ANARIDataType type, const void *mem);
  void setMode(ANARIDataType type, const void *mem);
  void setTimeout(ANARIDataType type, const void *mem);
  void setThreads(ANARIDataType type, const void *mem);
  // The parameter entry of a frame or world; NULL for other objects.
  CommunicatorParameter *communicatorOf(ANARIObject object);
  bool setCommunicator(ANARIObject object, ANARIDataType type, const void *mem);

  // Collective renders (CollectiveFrames.cpp).
  void renderComposited(
      ANARIFrame handle, FrameState &state, MPI_Comm communicator);
  std::map<std::string, MappedChannel> assembleComposite(ANARIFrame handle,
      const FrameState &state,
      const CompositedImage &image,
      const LinearImage &own,
      DepthCompositor *compositor);
  void renderReplicated(
      ANARIFrame handle, FrameState &state, MPI_Comm communicator);
  // Whether `pathtracer` mode can trace this frame's paths across the
  // processes (a renderer that traces wavefronts, and MPI callable from
  // the render thread); other frames are composited.
  bool tracesPathsAcross(ANARIFrame handle);
  void renderPathTraced(
      ANARIFrame handle, FrameState &state, MPI_Comm communicator);
  // The mode frames render in: the device's, when the local renderer
  // renders it (a wrapped library composites; said once).
  RenderMode effectiveMode(ANARIFrame handle);
  // The frame properties this device adds (mpiBytesSent, mpiRank,
  // mpiSize); 0 when `name` is none of them.
  int getFrameProperty(ANARIObject object,
      const char *name,
      ANARIDataType type,
      void *mem,
      uint64_t size);
  bool collectiveWorldBounds(
      ANARIObject world, bool foundLocally, float bounds[6]);

  MpiSession m_session;
  Rendezvous m_rendezvous; // before m_session ends MPI
  RenderMode m_mode{RenderMode::PathTracer};
  bool m_modeExplicit{false}; // `mode` set by parameter or environment
  bool m_wrappedModeWarned{false};
  bool m_threadLevelWarned{false};
  double m_timeoutSeconds{0.0}; // <= 0: wait for every process forever
  uint32_t m_publicReferences{1};

  mutable std::mutex m_statusMutex;
  ANARIStatusCallback m_statusCallback{nullptr};
  const void *m_statusUserPtr{nullptr};

  uint64_t m_framesCreated{0};
  std::mutex m_stateMutex; // guards the maps below
  std::map<ANARIObject, FrameState> m_frames;
  std::map<ANARIObject, WorldState> m_worlds;
  std::map<ANARIObject, Kept> m_kept;

  // The local renderers: the core always (it answers for the device before
  // the choice), a wrapped library's device when one is chosen.
  std::unique_ptr<CoreRenderer> m_core;
  std::unique_ptr<WrappedDevice> m_wrapped;
  LocalRenderer *m_local{nullptr};
  std::string m_wrappedSpec; // empty: the built-in core
  std::string m_wrappedSubtype{"default"};
  std::mutex m_wrapMutex; // guards the choice and the staged parameters
  std::atomic<bool> m_wrapChosen{false};
  struct DeviceParameter
  {
    std::string name;
    ANARIDataType type{ANARI_UNKNOWN};
    std::vector<unsigned char> value; // a string's characters and a NUL
  };
  std::vector<DeviceParameter> m_stagedDeviceParameters;
};

} // namespace prism::mpi
