// The prism_mpi device (KHR_DATA_PARALLEL_MPI): the prism device, with
// anariRenderFrame, waiting world bounds queries and frame mapping made
// collective over each frame's MPI communicator. Everything else (objects,
// parameters, local rendering) is the prism device's, unchanged -- or, with
// the device parameter `wrappedLibrary`, another library's device, to which
// every object call is forwarded and whose frames are composited
// (PassThrough.cpp).
#pragma once

#include "FrameAgreement.h"
#include "MpiSession.h"
#include "RenderMode.h"
#include "Rendezvous.h"

#include "Device.h"
#include "LoadedLibrary.h"
#include "math/Vec.h"

#include <mpi.h>

#include <atomic>
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

  ANARIArray1D newArray1D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1) override;
  ANARIArray2D newArray2D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1,
      uint64_t numItems2) override;
  ANARIArray3D newArray3D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1,
      uint64_t numItems2,
      uint64_t numItems3) override;
  ANARIGeometry newGeometry(const char *subtype) override;
  ANARIMaterial newMaterial(const char *subtype) override;
  ANARISampler newSampler(const char *subtype) override;
  ANARISurface newSurface() override;
  ANARISpatialField newSpatialField(const char *subtype) override;
  ANARIVolume newVolume(const char *subtype) override;
  ANARILight newLight(const char *subtype) override;
  ANARIGroup newGroup() override;
  ANARIInstance newInstance(const char *subtype) override;
  ANARIWorld newWorld() override;
  ANARICamera newCamera(const char *subtype) override;
  ANARIRenderer newRenderer(const char *subtype) override;
  ANARIFrame newFrame() override;
  ANARIObject newObject(const char *objectType, const char *subtype) override;
  void setParameter(ANARIObject object,
      const char *name,
      ANARIDataType type,
      const void *mem) override;
  void unsetParameter(ANARIObject object, const char *name) override;
  void unsetAllParameters(ANARIObject object) override;
  void *mapParameterArray1D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t *elementStride) override;
  void *mapParameterArray2D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t numElements2,
      uint64_t *elementStride) override;
  void *mapParameterArray3D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t numElements2,
      uint64_t numElements3,
      uint64_t *elementStride) override;
  void unmapParameterArray(ANARIObject object, const char *name) override;
  void commitParameters(ANARIObject object) override;
  void release(ANARIObject object) override;
  void retain(ANARIObject object) override;
  void *mapArray(ANARIArray array) override;
  void unmapArray(ANARIArray array) override;
  int getProperty(ANARIObject object,
      const char *name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;
  const char **getObjectSubtypes(ANARIDataType objectType) override;
  const void *getObjectInfo(ANARIDataType objectType,
      const char *objectSubtype,
      const char *infoName,
      ANARIDataType infoType) override;
  const void *getParameterInfo(ANARIDataType objectType,
      const char *objectSubtype,
      const char *parameterName,
      ANARIDataType parameterType,
      const char *infoName,
      ANARIDataType infoType) override;
  const void *frameBufferMap(ANARIFrame frame,
      const char *channel,
      uint32_t *width,
      uint32_t *height,
      ANARIDataType *pixelType) override;
  void frameBufferUnmap(ANARIFrame frame, const char *channel) override;
  void renderFrame(ANARIFrame frame) override;
  int frameReady(ANARIFrame frame, ANARIWaitMask mask) override;
  void discardFrame(ANARIFrame frame) override;
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
  // What the application set on a frame of the wrapped device that the
  // wrapped frame sees otherwise (it always renders linear color and depth).
  struct WrappedFrameParameters
  {
    uint32_t width{0};
    uint32_t height{0};
    // The application's ANARIDataType of each of kChannelNames.
    ANARIDataType channelTypes[kChannelCount]{};
    ANARIObject renderer{nullptr};
    bool world{false};
    bool camera{false};
  };
  struct FrameState
  {
    WrappedFrameParameters staged;    // wrapped device only
    WrappedFrameParameters committed; // wrapped device only
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
  // The wrapped device, chosen (loaded, or the built-in core: NULL) at the
  // first call that creates an object; the choice never changes.
  anari::DeviceImpl *wrapped();
  // Whether `wrappedLibrary` may still change (no object was created yet).
  bool wrapOpen() const
  {
    return !m_wrapChosen.load();
  }
  void chooseWrapped();
  // Whether `object` is a live handle of the wrapped device the
  // application holds; if not, reports it for `call`.
  bool liveWrapped(ANARIObject object, const char *call);
  void setWrapParameter(
      const std::string &name, ANARIDataType type, const void *mem);
  // A device parameter of the application that is not this device's own:
  // the wrapped device gets it too (kept until the device is chosen).
  void passDeviceParameter(
      const std::string &name, ANARIDataType type, const void *mem);
  // Records a handle the wrapped device created, as `type`.
  template <typename T>
  T created(T handle, ANARIDataType type)
  {
    if (handle) {
      std::lock_guard lock(m_stateMutex);
      m_wrappedObjects[(ANARIObject)handle] = WrappedObject{type, 1};
    }
    return handle;
  }
  // Frame and renderer parameters the wrapped device sees otherwise;
  // true when the call is done.
  bool setWrappedParameter(ANARIObject object,
      const std::string &name,
      ANARIDataType type,
      const void *mem);
  bool unsetWrappedParameter(ANARIObject object, const std::string &name);
  void unsetAllWrappedParameters(ANARIObject object);
  void commitWrapped(ANARIObject object);
  void releaseWrapped(ANARIObject object);
  FrameDescriptor describeWrapped(const FrameState &state) const;
  void renderWrapped(ANARIFrame handle);
  void renderWrappedComposited(
      ANARIFrame handle, FrameState &state, MPI_Comm communicator);
  void setMode(ANARIDataType type, const void *mem);
  void setTimeout(ANARIDataType type, const void *mem);
  void setThreads(ANARIDataType type, const void *mem);
  // The parameter entry of a frame or world; NULL for other objects.
  CommunicatorParameter *communicatorOf(ANARIObject object);
  FrameDescriptor describe(Frame *frame, const FrameState &state) const;
  // Replicated mode: what must be the same in every process's world.
  static void fingerprintWorld(const World &world, FrameDescriptor &d);
  // shareLights() for the frame `handle` renders, its problem reported;
  // returns the bytes sent.
  uint64_t shareWorldLights(ANARIFrame handle,
      World &world,
      MPI_Comm communicator,
      bool withEmitters);
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

  // wrappedLibrary / wrappedDevice (PassThrough.cpp).
  std::string m_wrappedSpec; // empty: the built-in core
  std::string m_wrappedSubtype{"default"};
  bool m_modeExplicit{false}; // `mode` set by parameter or environment
  bool m_wrappedModeWarned{false};
  std::mutex m_wrapMutex; // guards the choice and the staged parameters
  std::atomic<bool> m_wrapChosen{false};
  std::shared_ptr<frontend::LoadedLibrary> m_wrappedLibrary;
  anari::DeviceImpl *m_wrappedDevice{nullptr};
  struct DeviceParameter
  {
    std::string name;
    ANARIDataType type{ANARI_UNKNOWN};
    std::vector<unsigned char> value; // a string's characters and a NUL
  };
  std::vector<DeviceParameter> m_stagedDeviceParameters;
  // Every handle the wrapped device gave the application (guarded by
  // m_stateMutex), with its type and the application's references.
  struct WrappedObject
  {
    ANARIDataType type{ANARI_OBJECT};
    int64_t references{1};
  };
  std::map<ANARIObject, WrappedObject> m_wrappedObjects;
  // A renderer of the wrapped device renders with a transparent background;
  // rank 0 adds the application's under the composite.
  struct WrappedRenderer
  {
    std::string subtype;
    float4 stagedBackground{0.f, 0.f, 0.f, 1.f};
    float4 background{0.f, 0.f, 0.f, 1.f}; // committed
  };
  std::map<ANARIObject, WrappedRenderer> m_wrappedRenderers;
};

} // namespace prism::mpi
