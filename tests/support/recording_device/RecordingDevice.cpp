// A device library for tests: it renders nothing and writes down every call
// it receives with its arguments, so tests can check that the front-end
// forwards each C entry point intact. Tests read the log through
// anariDeviceGetProcAddress(device, "recordingLastCall").
#include "anari/backend/DeviceImpl.h"

#include <atomic>
#include <cinttypes>
#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>

namespace {

std::mutex g_logMutex;
std::string g_lastCall;
std::atomic<int> g_liveDevices{0};

void record(const char *format, ...)
{
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  std::lock_guard lock(g_logMutex);
  g_lastCall = buffer;
}

const char *lastCall()
{
  std::lock_guard lock(g_logMutex);
  static thread_local std::string copy;
  copy = g_lastCall;
  return copy.c_str();
}

int liveDevices()
{
  return g_liveDevices;
}

const char *str(const char *s)
{
  return s ? s : "(null)";
}

// Distinct fake handles, one per kind of object, so tests can tell them apart.
template <typename Handle>
Handle fakeHandle(uintptr_t tag)
{
  return (Handle)(0x1000 + tag);
}

struct RecordingDevice : public anari::DeviceImpl
{
  explicit RecordingDevice(ANARILibrary library) : anari::DeviceImpl(library)
  {
    ++g_liveDevices;
  }
  ~RecordingDevice() override
  {
    --g_liveDevices;
  }

  ANARIArray1D newArray1D(const void *mem,
      ANARIMemoryDeleter deleter,
      const void *user,
      ANARIDataType type,
      uint64_t n1) override
  {
    record("newArray1D(%p, %p, %p, %d, %" PRIu64 ")",
        mem,
        (void *)deleter,
        user,
        int(type),
        n1);
    return fakeHandle<ANARIArray1D>(1);
  }
  ANARIArray2D newArray2D(const void *mem,
      ANARIMemoryDeleter deleter,
      const void *user,
      ANARIDataType type,
      uint64_t n1,
      uint64_t n2) override
  {
    record("newArray2D(%p, %p, %p, %d, %" PRIu64 ", %" PRIu64 ")",
        mem,
        (void *)deleter,
        user,
        int(type),
        n1,
        n2);
    return fakeHandle<ANARIArray2D>(2);
  }
  ANARIArray3D newArray3D(const void *mem,
      ANARIMemoryDeleter deleter,
      const void *user,
      ANARIDataType type,
      uint64_t n1,
      uint64_t n2,
      uint64_t n3) override
  {
    record("newArray3D(%p, %p, %p, %d, %" PRIu64 ", %" PRIu64 ", %" PRIu64 ")",
        mem,
        (void *)deleter,
        user,
        int(type),
        n1,
        n2,
        n3);
    return fakeHandle<ANARIArray3D>(3);
  }
  ANARIGeometry newGeometry(const char *t) override
  {
    record("newGeometry(%s)", str(t));
    return fakeHandle<ANARIGeometry>(4);
  }
  ANARIMaterial newMaterial(const char *t) override
  {
    record("newMaterial(%s)", str(t));
    return fakeHandle<ANARIMaterial>(5);
  }
  ANARISampler newSampler(const char *t) override
  {
    record("newSampler(%s)", str(t));
    return fakeHandle<ANARISampler>(6);
  }
  ANARISurface newSurface() override
  {
    record("newSurface()");
    return fakeHandle<ANARISurface>(7);
  }
  ANARISpatialField newSpatialField(const char *t) override
  {
    record("newSpatialField(%s)", str(t));
    return fakeHandle<ANARISpatialField>(8);
  }
  ANARIVolume newVolume(const char *t) override
  {
    record("newVolume(%s)", str(t));
    return fakeHandle<ANARIVolume>(9);
  }
  ANARILight newLight(const char *t) override
  {
    record("newLight(%s)", str(t));
    return fakeHandle<ANARILight>(10);
  }
  ANARIGroup newGroup() override
  {
    record("newGroup()");
    return fakeHandle<ANARIGroup>(11);
  }
  ANARIInstance newInstance(const char *t) override
  {
    record("newInstance(%s)", str(t));
    return fakeHandle<ANARIInstance>(12);
  }
  ANARIWorld newWorld() override
  {
    record("newWorld()");
    return fakeHandle<ANARIWorld>(13);
  }
  ANARICamera newCamera(const char *t) override
  {
    record("newCamera(%s)", str(t));
    return fakeHandle<ANARICamera>(14);
  }
  ANARIRenderer newRenderer(const char *t) override
  {
    record("newRenderer(%s)", str(t));
    return fakeHandle<ANARIRenderer>(15);
  }
  ANARIFrame newFrame() override
  {
    record("newFrame()");
    return fakeHandle<ANARIFrame>(16);
  }
  void setParameter(ANARIObject o,
      const char *name,
      ANARIDataType type,
      const void *mem) override
  {
    if (type == ANARI_FLOAT32 && mem) {
      record("setParameter(%p, %s, %d, %g)",
          (void *)o,
          str(name),
          int(type),
          double(*(const float *)mem));
    } else {
      record(
          "setParameter(%p, %s, %d, %p)", (void *)o, str(name), int(type), mem);
    }
  }
  void unsetParameter(ANARIObject o, const char *name) override
  {
    record("unsetParameter(%p, %s)", (void *)o, str(name));
  }
  void unsetAllParameters(ANARIObject o) override
  {
    record("unsetAllParameters(%p)", (void *)o);
  }
  void *mapParameterArray1D(ANARIObject o,
      const char *name,
      ANARIDataType type,
      uint64_t n1,
      uint64_t *stride) override
  {
    record("mapParameterArray1D(%p, %s, %d, %" PRIu64 ", %p)",
        (void *)o,
        str(name),
        int(type),
        n1,
        (void *)stride);
    return m_scratch;
  }
  void *mapParameterArray2D(ANARIObject o,
      const char *name,
      ANARIDataType type,
      uint64_t n1,
      uint64_t n2,
      uint64_t *stride) override
  {
    record("mapParameterArray2D(%p, %s, %d, %" PRIu64 ", %" PRIu64 ", %p)",
        (void *)o,
        str(name),
        int(type),
        n1,
        n2,
        (void *)stride);
    return m_scratch;
  }
  void *mapParameterArray3D(ANARIObject o,
      const char *name,
      ANARIDataType type,
      uint64_t n1,
      uint64_t n2,
      uint64_t n3,
      uint64_t *stride) override
  {
    record("mapParameterArray3D(%p, %s, %d, %" PRIu64 ", %" PRIu64 ", %" PRIu64
           ", %p)",
        (void *)o,
        str(name),
        int(type),
        n1,
        n2,
        n3,
        (void *)stride);
    return m_scratch;
  }
  void unmapParameterArray(ANARIObject o, const char *name) override
  {
    record("unmapParameterArray(%p, %s)", (void *)o, str(name));
  }
  void commitParameters(ANARIObject o) override
  {
    record("commitParameters(%p)", (void *)o);
  }
  void release(ANARIObject o) override
  {
    record("release(%p)", (void *)o);
    if (handleIsDevice(o) && --m_refs == 0)
      delete this;
  }
  void retain(ANARIObject o) override
  {
    record("retain(%p)", (void *)o);
    if (handleIsDevice(o))
      ++m_refs;
  }
  void *mapArray(ANARIArray a) override
  {
    record("mapArray(%p)", (void *)a);
    return m_scratch;
  }
  void unmapArray(ANARIArray a) override
  {
    record("unmapArray(%p)", (void *)a);
  }
  int getProperty(ANARIObject o,
      const char *name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override
  {
    record("getProperty(%p, %s, %d, %p, %" PRIu64 ", %u)",
        (void *)o,
        str(name),
        int(type),
        mem,
        size,
        unsigned(mask));
    return 7;
  }
  const char **getObjectSubtypes(ANARIDataType type) override
  {
    record("getObjectSubtypes(%d)", int(type));
    static const char *subtypes[] = {"recorded", nullptr};
    return subtypes;
  }
  const void *getObjectInfo(ANARIDataType type,
      const char *subtype,
      const char *info,
      ANARIDataType infoType) override
  {
    record("getObjectInfo(%d, %s, %s, %d)",
        int(type),
        str(subtype),
        str(info),
        int(infoType));
    return m_scratch;
  }
  const void *getParameterInfo(ANARIDataType type,
      const char *subtype,
      const char *param,
      ANARIDataType paramType,
      const char *info,
      ANARIDataType infoType) override
  {
    record("getParameterInfo(%d, %s, %s, %d, %s, %d)",
        int(type),
        str(subtype),
        str(param),
        int(paramType),
        str(info),
        int(infoType));
    return m_scratch;
  }
  const void *frameBufferMap(ANARIFrame f,
      const char *channel,
      uint32_t *width,
      uint32_t *height,
      ANARIDataType *pixelType) override
  {
    record("frameBufferMap(%p, %s)", (void *)f, str(channel));
    *width = 4;
    *height = 2;
    *pixelType = ANARI_UFIXED8_RGBA_SRGB;
    return m_scratch;
  }
  void frameBufferUnmap(ANARIFrame f, const char *channel) override
  {
    record("frameBufferUnmap(%p, %s)", (void *)f, str(channel));
  }
  void renderFrame(ANARIFrame f) override
  {
    record("renderFrame(%p)", (void *)f);
  }
  int frameReady(ANARIFrame f, ANARIWaitMask mask) override
  {
    record("frameReady(%p, %u)", (void *)f, unsigned(mask));
    return 1;
  }
  void discardFrame(ANARIFrame f) override
  {
    record("discardFrame(%p)", (void *)f);
  }
  ANARIObject newObject(const char *objectType, const char *t) override
  {
    record("newObject(%s, %s)", str(objectType), str(t));
    return fakeHandle<ANARIObject>(17);
  }
  void (*getProcAddress(const char *name))(void) override
  {
    const std::string n = name;
    if (n == "recordingLastCall")
      return (void (*)(void))(&lastCall);
    if (n == "recordingLiveDevices")
      return (void (*)(void))(&liveDevices);
    if (n == "recordingThrow")
      throw std::runtime_error("recording device was asked to throw");
    return nullptr;
  }

 private:
  int m_refs{1};
  alignas(16) unsigned char m_scratch[256]{};
};

struct RecordingLibrary : public anari::LibraryImpl
{
  using anari::LibraryImpl::LibraryImpl;

  ANARIDevice newDevice(const char *subtype) override
  {
    const std::string s = subtype;
    if (s != "default" && s != "second")
      return nullptr;
    return (ANARIDevice) new RecordingDevice(this_library());
  }
  const char **getDeviceExtensions(const char *) override
  {
    static const char *extensions[] = {"ANARI_KHR_RECORDING_TEST", nullptr};
    return extensions;
  }
  const char **getDeviceSubtypes() override
  {
    static const char *subtypes[] = {"default", "second", nullptr};
    return subtypes;
  }
  void loadModule(const char *name) override
  {
    record("loadModule(%s)", str(name));
  }
  void unloadModule(const char *name) override
  {
    record("unloadModule(%s)", str(name));
  }
};

} // namespace

ANARI_DEFINE_LIBRARY_ENTRYPOINT(recording, handle, scb, scbPtr)
{
  return (ANARILibrary) new RecordingLibrary(handle, scb, scbPtr);
}
