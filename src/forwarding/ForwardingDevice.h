// A device that forwards every call to an inner device -- another library's,
// loaded, or one made in this process -- for layers that check calls (the
// validation layer) or make some collective (prism_mpi). A layer overrides
// only the calls it changes, and the three hooks every object creation and
// parameter array map end at; what it does not override reaches the inner
// device as the application made it (this device's own handle becomes the
// inner device's).
#pragma once

#include "anari/backend/DeviceImpl.h"

namespace prism {

class ForwardingDevice : public anari::DeviceImpl
{
 public:
  explicit ForwardingDevice(ANARILibrary library);

  // Every anariNew* ends at newObjectOf or newArrayOf.
  ANARIArray1D newArray1D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1) final;
  ANARIArray2D newArray2D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1,
      uint64_t numItems2) final;
  ANARIArray3D newArray3D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1,
      uint64_t numItems2,
      uint64_t numItems3) final;
  ANARIGeometry newGeometry(const char *subtype) final;
  ANARIMaterial newMaterial(const char *subtype) final;
  ANARISampler newSampler(const char *subtype) final;
  ANARISurface newSurface() final;
  ANARISpatialField newSpatialField(const char *subtype) final;
  ANARIVolume newVolume(const char *subtype) final;
  ANARILight newLight(const char *subtype) final;
  ANARIGroup newGroup() final;
  ANARIInstance newInstance(const char *subtype) final;
  ANARIWorld newWorld() final;
  ANARICamera newCamera(const char *subtype) final;
  ANARIRenderer newRenderer(const char *subtype) final;
  ANARIFrame newFrame() final;
  ANARIObject newObject(const char *objectType, const char *subtype) override;

  // Every anariMapParameterArray*D ends at mapParameterArrayOf.
  void *mapParameterArray1D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t *elementStride) final;
  void *mapParameterArray2D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t numElements2,
      uint64_t *elementStride) final;
  void *mapParameterArray3D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t numElements2,
      uint64_t numElements3,
      uint64_t *elementStride) final;

  // Forwarded as they are, if admits() lets them.
  void setParameter(ANARIObject object,
      const char *name,
      ANARIDataType type,
      const void *mem) override;
  void unsetParameter(ANARIObject object, const char *name) override;
  void unsetAllParameters(ANARIObject object) override;
  void unmapParameterArray(ANARIObject object, const char *name) override;
  void commitParameters(ANARIObject object) override;
  // Releasing or retaining this device itself is the layer's affair: it
  // reaches the inner device only for the inner device's objects.
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

  // The anariNew* function that creates objects of `type` (for messages).
  static const char *newFunctionName(ANARIDataType type);
  // The anariMapParameterArray*D function of `arrayType`.
  static const char *mapParameterArrayFunctionName(ANARIDataType arrayType);

 protected:
  // The device calls go to; NULL until the layer has one (calls are then
  // dropped and answer NULL or 0).
  anari::DeviceImpl *inner() const
  {
    return m_inner;
  }
  void setInner(anari::DeviceImpl *device)
  {
    m_inner = device;
  }
  // `object` as the inner device knows it: its own handle for this
  // device's, any other as it is.
  ANARIObject innerHandle(ANARIObject object) const;
  // Whether the call `function` on `object` (never this device's own
  // handle) may reach the inner device; a layer that checks handles
  // reports those it refuses. Every forwarded call on an object asks.
  virtual bool admits(ANARIObject object, const char *function);

  // Before every anariNew* (ANARI_OBJECT for anariNewObject) reaches the
  // hooks below: a layer may choose its inner device here.
  virtual void beforeCreating(ANARIDataType type);
  // anariNew* of every object but arrays (`subtype` is NULL for surfaces,
  // groups, worlds and frames).
  virtual ANARIObject newObjectOf(ANARIDataType type, const char *subtype);
  // anariNewArray1D/2D/3D: `items` has 0 past the array's dimensions.
  virtual ANARIArray newArrayOf(ANARIDataType arrayType,
      const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      const uint64_t items[3]);
  // anariMapParameterArray1D/2D/3D, `items` as for newArrayOf.
  virtual void *mapParameterArrayOf(ANARIObject object,
      const char *name,
      ANARIDataType arrayType,
      ANARIDataType elementType,
      const uint64_t items[3],
      uint64_t *elementStride);

 private:
  // An inner device, and admits() (or `object` is this device).
  bool forwards(ANARIObject object, const char *function);

  anari::DeviceImpl *m_inner{nullptr};
};

} // namespace prism
