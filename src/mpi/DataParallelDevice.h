// The prism_mpi device (KHR_DATA_PARALLEL_MPI): the prism device, with
// anariRenderFrame, waiting world bounds queries and frame mapping made
// collective over each frame's MPI communicator. Everything else (objects,
// parameters, local rendering) is the prism device's, unchanged.
#pragma once

#include "FrameAgreement.h"
#include "MpiSession.h"
#include "RenderMode.h"
#include "Rendezvous.h"

#include "Device.h"

#include <mpi.h>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace prism {
class Frame;
class World;
} // namespace prism

namespace prism::mpi {

class DataParallelDevice : public prism::Device
{
 public:
  explicit DataParallelDevice(ANARILibrary library);
  ~DataParallelDevice() override;

  ANARIFrame newFrame() override;
  ANARIWorld newWorld() override;
  void setParameter(ANARIObject object,
      const char *name,
      ANARIDataType type,
      const void *mem) override;
  void unsetParameter(ANARIObject object, const char *name) override;
  void unsetAllParameters(ANARIObject object) override;
  void commitParameters(ANARIObject object) override;
  void release(ANARIObject object) override;
  int getProperty(ANARIObject object,
      const char *name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;
  const void *frameBufferMap(ANARIFrame frame,
      const char *channel,
      uint32_t *width,
      uint32_t *height,
      ANARIDataType *pixelType) override;
  void renderFrame(ANARIFrame frame) override;
  std::unique_ptr<RayTransport> transportFor(const World &world) override;

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
    bool denoiseWarned{false};
    std::map<std::string, MappedChannel> assembled; // rank 0 only
  };

  void reportBadDeviceParameter(const std::string &message);
  void setMode(ANARIDataType type, const void *mem);
  void setTimeout(ANARIDataType type, const void *mem);
  void setThreads(ANARIDataType type, const void *mem);
  // The parameter entry of a frame or world; NULL for other objects.
  CommunicatorParameter *communicatorOf(ANARIObject object);
  FrameDescriptor describe(Frame *frame, const FrameState &state) const;
  // Replicated mode: what must be the same in every process's world.
  static void fingerprintWorld(const World &world, FrameDescriptor &d);
  // The lights `world` declares, not counting its emissive surfaces.
  static uint32_t declaredLights(const World &world);
  void renderComposited(ANARIFrame handle,
      Frame &frame,
      FrameState &state,
      MPI_Comm communicator);
  void renderReplicated(ANARIFrame handle,
      Frame &frame,
      FrameState &state,
      MPI_Comm communicator);
  // Whether `pathtracer` mode can trace this frame's paths across the
  // processes (the path tracer, and MPI callable from the render thread);
  // other renderers are composited.
  bool tracesPathsAcross(ANARIFrame handle, const Frame &frame);
  void renderPathTraced(ANARIFrame handle,
      Frame &frame,
      FrameState &state,
      MPI_Comm communicator);
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
  // During a `pathtracer` render: its communicator and byte count, for the
  // transport the frame asks for (guarded by m_stateMutex).
  struct PathTracing
  {
    MPI_Comm communicator;
    uint64_t *bytesSent;
  };
  std::optional<PathTracing> m_pathTracing;
  bool m_threadLevelWarned{false};
  double m_timeoutSeconds{0.0}; // <= 0: wait for every process forever
  uint64_t m_framesCreated{0};
  std::mutex m_stateMutex; // guards the maps below
  std::map<ANARIObject, FrameState> m_frames;
  std::map<ANARIObject, CommunicatorParameter> m_worlds;
};

} // namespace prism::mpi
