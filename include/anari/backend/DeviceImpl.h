// The backend interface a device implements: what ANARIDevice points to.
// Every virtual below is one C entry point; the order is the ABI (ABI.md).
#pragma once

#include "anari/backend/LibraryImpl.h"

namespace anari {

struct ANARI_BACKEND_INTERFACE DeviceImpl
{
  // Object creation
  virtual ANARIArray1D newArray1D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1) = 0;
  virtual ANARIArray2D newArray2D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1,
      uint64_t numItems2) = 0;
  virtual ANARIArray3D newArray3D(const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      uint64_t numItems1,
      uint64_t numItems2,
      uint64_t numItems3) = 0;
  virtual ANARIGeometry newGeometry(const char *subtype) = 0;
  virtual ANARIMaterial newMaterial(const char *subtype) = 0;
  virtual ANARISampler newSampler(const char *subtype) = 0;
  virtual ANARISurface newSurface() = 0;
  virtual ANARISpatialField newSpatialField(const char *subtype) = 0;
  virtual ANARIVolume newVolume(const char *subtype) = 0;
  virtual ANARILight newLight(const char *subtype) = 0;
  virtual ANARIGroup newGroup() = 0;
  virtual ANARIInstance newInstance(const char *subtype) = 0;
  virtual ANARIWorld newWorld() = 0;
  virtual ANARICamera newCamera(const char *subtype) = 0;
  virtual ANARIRenderer newRenderer(const char *subtype) = 0;
  virtual ANARIFrame newFrame() = 0;

  // Parameters and lifetime
  virtual void setParameter(ANARIObject object,
      const char *name,
      ANARIDataType type,
      const void *mem) = 0;
  virtual void unsetParameter(ANARIObject object, const char *name) = 0;
  virtual void unsetAllParameters(ANARIObject object) = 0;
  virtual void *mapParameterArray1D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t *elementStride) = 0;
  virtual void *mapParameterArray2D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t numElements2,
      uint64_t *elementStride) = 0;
  virtual void *mapParameterArray3D(ANARIObject object,
      const char *name,
      ANARIDataType elementType,
      uint64_t numElements1,
      uint64_t numElements2,
      uint64_t numElements3,
      uint64_t *elementStride) = 0;
  virtual void unmapParameterArray(ANARIObject object, const char *name) = 0;
  virtual void commitParameters(ANARIObject object) = 0;
  virtual void release(ANARIObject object) = 0;
  virtual void retain(ANARIObject object) = 0;
  virtual void *mapArray(ANARIArray array) = 0;
  virtual void unmapArray(ANARIArray array) = 0;
  virtual int getProperty(ANARIObject object,
      const char *name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) = 0;

  // Introspection
  virtual const char **getObjectSubtypes(ANARIDataType objectType) = 0;
  virtual const void *getObjectInfo(ANARIDataType objectType,
      const char *objectSubtype,
      const char *infoName,
      ANARIDataType infoType) = 0;
  virtual const void *getParameterInfo(ANARIDataType objectType,
      const char *objectSubtype,
      const char *parameterName,
      ANARIDataType parameterType,
      const char *infoName,
      ANARIDataType infoType) = 0;

  // Frames (frameBufferMap implements anariMapFrame)
  virtual const void *frameBufferMap(ANARIFrame frame,
      const char *channel,
      uint32_t *width,
      uint32_t *height,
      ANARIDataType *pixelType) = 0;
  virtual void frameBufferUnmap(ANARIFrame frame, const char *channel) = 0;
  virtual void renderFrame(ANARIFrame frame) = 0;
  virtual int frameReady(ANARIFrame frame, ANARIWaitMask mask) = 0;
  virtual void discardFrame(ANARIFrame frame) = 0;

  // Extensions: objects of types outside the core set; NULL by default.
  virtual ANARIObject newObject(const char *objectType, const char *subtype);
  // Extension functions by name; NULL by default.
  virtual void (*getProcAddress(const char *name))(void);

  explicit DeviceImpl(ANARILibrary library);
  DeviceImpl() = default;
  virtual ~DeviceImpl() = default;

  // `this` as the C handle.
  ANARIDevice this_device() const;

  ANARIStatusCallback m_defaultStatusCB{nullptr};
  const void *m_defaultStatusCBUserPtr{nullptr};

 protected:
  ANARIStatusCallback defaultStatusCallback() const;
  const void *defaultStatusCallbackUserPtr() const;
  bool handleIsDevice(ANARIObject object) const;
};

} // namespace anari
