// The prism device: receives every ANARI call (DeviceImpl), owns the handle
// table, the queue of pending commits and the task pool frames render on.
#pragma once

#include "object/DeviceState.h"
#include "object/HandleTable.h"
#include "object/Object.h"
#include "object/SubtypeRegistry.h"
#include "parallel/TaskPool.h"
#include "rt/Context.h"

#include "anari/backend/DeviceImpl.h"

#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <unordered_set>
#include <vector>

namespace prism {

class Array;

class Device : public anari::DeviceImpl, public DeviceState
{
 public:
  explicit Device(ANARILibrary library);
  ~Device() override;

  // DeviceImpl //////////////////////////////////////////////////////////////
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

  // DeviceState: what objects may ask ///////////////////////////////////
  Object *lookup(ANARIObject handle) const override;
  const char *whyNotLive(ANARIObject handle) const override;
  void objectCreated(Object *object) override;
  void objectDestroyed(Object *object) override;
  void reportStatus(ANARIObject source,
      ANARIDataType sourceType,
      ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &message) const override;
  ANARIDevice apiHandle() const override
  {
    return this_device();
  }
  TaskPool &taskPool() override
  {
    return m_taskPool;
  }
  const rt::Context &rtContext() const override
  {
    return m_rtContext;
  }
  std::unique_ptr<RayTransport> transportFor(const World &world) override;
  // Where frames get their ray transport while `source` is set (a
  // data-parallel device's, during its collective renders); an empty
  // source: this process's world alone.
  using TransportSource =
      std::function<std::unique_ptr<RayTransport>(const World &)>;
  void setTransportSource(TransportSource source);
  void frameStarted() override;
  void frameFinished() override;

  // Applies every pending commit; waits for frames in flight first so no
  // frame ever sees a half-applied change.
  void flushCommits();
  // flushCommits(), then rebuilds what `object` derives from arrays or
  // children changed since their commit, as a frame start does.
  void flushCommitsAndRefresh(Object &object);
  void waitForFrames();

 protected:
  // What anariNew* creates; a device built on this one may extend it.
  SubtypeRegistry &subtypes()
  {
    return m_subtypes;
  }

 private:
  template <typename Handle>
  Handle create(ANARIDataType type, const char *subtype);
  ANARIObject track(Object *object);
  // The object behind `handle` if it is live and one of `types` (any type
  // when empty); otherwise reports why (naming `function`) and returns NULL.
  Object *checked(ANARIObject handle,
      const char *function,
      std::initializer_list<ANARIDataType> types = {}) const;
  ANARIArray newArray(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      int dimensions,
      const uint64_t size[3]);
  void *mapParameterArray(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      int dimensions,
      const uint64_t size[3],
      uint64_t *elementStride,
      const char *function);
  bool isMappedParameter(Object *object, const std::string &name) const;
  void setDeviceParameter(
      const char *name, ANARIDataType type, const void *mem);
  bool getDeviceProperty(
      const std::string &name, ANARIDataType type, void *mem, uint64_t size);
  void releaseAllObjects();
  // Reports the exception being handled; every entry point ends in it, so
  // nothing thrown inside the device reaches the application.
  void reportException(const char *function) const noexcept;
  // The application released its last handle to `array` while objects of
  // the device still use it.
  void keepArrayAfterRelease(Array *array);
  // Applies the pending commits, refreshing what they read with
  // `generation` (Object::refresh), which the refresh that follows may
  // share.
  void flushCommitsLocked(uint64_t generation);

  HandleTable m_handles;
  SubtypeRegistry m_subtypes;
  rt::Context m_rtContext;
  TaskPool m_taskPool;
  uint64_t m_refreshGeneration{0}; // guarded by m_flushMutex
  std::mutex m_transportMutex;
  TransportSource m_transportSource; // guarded by m_transportMutex
  uint32_t m_publicRefs{1};

  mutable std::mutex m_statusMutex;
  ANARIStatusCallback m_statusCallback{nullptr};
  const void *m_statusUserPtr{nullptr};

  std::mutex m_flushMutex; // serialises flushes and frame starts
  std::mutex m_commitMutex;
  std::vector<Object *> m_pendingCommits; // each holds an internal reference

  std::mutex m_frameMutex;
  std::condition_variable m_frameDone;
  int m_framesInFlight{0};

  std::mutex m_objectsMutex;
  std::unordered_set<Object *> m_objects;

  mutable std::mutex m_mappedMutex;
  std::map<std::pair<Object *, std::string>, Array *> m_mappedParameters;
};

} // namespace prism
