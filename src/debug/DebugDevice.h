// The debug layer's device: checks every call, reports what is wrong at the
// call that did it, and forwards the call to the wrapped device with the
// wrapped device's handles. Calls whose handles are bad are not forwarded
// (the wrapped device never sees them); other findings are forwarded, so the
// wrapped device behaves as it would without the layer.
#pragma once

#include "Findings.h"
#include "ObjectTable.h"
#include "Rules.h"
#include "WithheldReports.h"
#include "WrappedLibrary.h"
#include "trace/TraceWriter.h"

#include "ForwardingDevice.h"
#include "introspection/Introspection.h"

#include <atomic>
#include <exception>
#include <memory>
#include <mutex>
#include <string>

namespace prism::debug {

class DebugDevice : public ForwardingDevice
{
 public:
  // Wraps a new device of `subtype` from the library `wrappedSpec` names.
  DebugDevice(ANARILibrary library,
      const std::string &wrappedSpec,
      const std::string &subtype);
  ~DebugDevice() override;

  // Why there is no wrapped device (empty if there is one).
  const std::string &failure() const
  {
    return m_failure;
  }
  // How the front-end (ours; the SDK's has none) tells whether a device
  // handle is live, so a released `wrappedDevice` handle is reported
  // rather than used.
  using DeviceCheck = int (*)(ANARIDevice);
  static void setDeviceCheck(DeviceCheck check);

  void setParameter(ANARIObject object,
      const char *name,
      ANARIDataType type,
      const void *mem) override;
  void unsetParameter(ANARIObject object, const char *name) override;
  void unsetAllParameters(ANARIObject object) override;
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

  ANARIObject newObject(const char *objectType, const char *subtype) override;
  ANARIObject newObjectOf(ANARIDataType type, const char *subtype) override;
  ANARIArray newArrayOf(ANARIDataType arrayType,
      const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      const uint64_t items[3]) override;
  void *mapParameterArrayOf(ANARIObject object,
      const char *name,
      ANARIDataType arrayType,
      ANARIDataType elementType,
      const uint64_t items[3],
      uint64_t *elementStride) override;
  // Extension functions take the layer's handles, which the wrapped device's
  // own functions cannot read: none is handed out, and one the wrapped
  // device has is reported.
  void (*getProcAddress(const char *name))(void) override;

 private:
  // The wrapped device's status messages, with the layer's handles.
  static void forwardStatus(const void *userPtr,
      ANARIDevice device,
      ANARIObject source,
      ANARIDataType sourceType,
      ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const char *message);
  // The wrapped device's frame completion, with the layer's handles.
  static void forwardFrameCompletion(
      const void *userPtr, ANARIDevice device, ANARIFrame frame);

  // Runs `body` as the API call `function`, counted; whatever it throws is
  // reported and `neutral` returned: nothing crosses the C boundary.
  template <typename R, typename F>
  R guarded(const char *function, R neutral, F &&body)
  {
    ++m_calls;
    try {
      return body();
    } catch (const std::exception &e) {
      report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_UNKNOWN_ERROR,
          std::string(function) + ": internal failure: " + e.what());
    } catch (...) {
      report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_UNKNOWN_ERROR,
          std::string(function) + ": internal failure");
    }
    return neutral;
  }
  template <typename F>
  void guarded(const char *function, F &&body)
  {
    guarded(function, 0, [&] {
      body();
      return 0;
    });
  }

  bool wrap(const std::string &wrappedSpec, const std::string &subtype);
  // Wraps `device`, which the application created and keeps: the layer
  // never releases it (VTK's way: the `wrappedDevice` handle).
  void adopt(anari::DeviceImpl *device);
  // Checks the catalog of what the wrapped device implements.
  void readWrappedDefinitions(const char **extensions);
  void dropWrapped();
  // The `wrappedDevice` parameter given as ANARI_DEVICE: checked, kept
  // until the commit.
  void stageWrappedHandle(Findings &f, const void *mem);
  // The `traceDir`/`traceMode` parameters (the ANARI-SDK debug device's).
  void stageTraceParameter(Findings &f,
      const std::string &name,
      ANARIDataType type,
      const void *mem);
  // Starts the trace in `traceDir` (committed) if asked to.
  void openTraceInDirectory(Findings &f);
  // Sends findings to the application (never under m_mutex's lock).
  void report(Findings &findings);
  void report(ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &text);
  // Withholds the wrapped device's reports while a call is forwarded whose
  // problems `f` has reported already (WithheldReports).
  WithheldReports withheldAfter(const Findings &f) const
  {
    return WithheldReports(this, f.any());
  }
  bool isDevice(ANARIObject object) const
  {
    return object == (ANARIObject)this_device();
  }
  // The record of a live handle; reports null, foreign, released and (if
  // `expected` is not ANARI_OBJECT) mistyped handles. Under the lock.
  ObjectRecord *live(Findings &f,
      ANARIObject handle,
      ANARIDataType expected = ANARI_OBJECT,
      const char *what = "object");
  // The common shape of a call on one object: under the lock, finds the
  // live record of `handle`, names it (and `parameter`) in `f` and runs
  // `check(record)`; then reports. Returns the wrapped handle to forward
  // the call to, or NULL if the handle is bad or `check` returned false.
  // When tracing, a call refused (NULL returned) is recorded as `Refused`
  // and the line `f.refused` returns, before its reports.
  template <typename Check>
  ANARIObject checked(Findings &f,
      ANARIObject handle,
      ANARIDataType expected,
      const char *parameter,
      Check &&check)
  {
    ANARIObject target = nullptr;
    {
      std::lock_guard lock(m_mutex);
      const char *what = expected == ANARI_OBJECT  ? "object"
                         : expected == ANARI_ARRAY ? "array"
                                                   : "frame";
      if (ObjectRecord *record = live(f, handle, expected, what)) {
        f.about(record, parameter);
        if (check(*record))
          target = record->wrapped;
      }
      if (!target && tracing() && f.refused) {
        const std::string line = f.refused();
        if (!line.empty())
          trace("Refused " + line);
      }
    }
    report(f);
    return target;
  }
  // The wrapped handle an object value stands for; reports bad handles.
  // Under the lock.
  bool translate(Findings &f,
      ANARIObject handle,
      ANARIDataType expected,
      const char *what,
      ANARIObject &wrapped);
  // A new object of the wrapped device, under a new layer handle.
  ANARIObject created(const char *function,
      ANARIDataType type,
      const char *subtype,
      ANARIObject wrapped,
      Findings &findings);
  // Reports why an array was not made (and traces it refused).
  ANARIArray refuseArray(Findings &f,
      ANARIDataType arrayType,
      ANARIDataType elementType,
      const uint64_t items[3]);
  // What the layer keeps of a new array: its shape, the application's
  // memory (for object arrays, the layer handles `copied` translated) and
  // its trace line. Under the lock.
  void recordArray(ANARIObject handle,
      ANARIDataType arrayType,
      ANARIDataType elementType,
      const uint64_t items[3],
      const void *appMemory,
      std::vector<ANARIObject> copied);
  // The wrapped handles for `count` layer handles at `source` (NULL: all
  // NULL), checked; `copied` holds the handles of the last translation
  // (slots unchanged since keep their object, released or not) and
  // receives these. Under the lock.
  std::vector<ANARIObject> translateHandles(Findings &f,
      const ANARIObject *source,
      uint64_t count,
      ANARIDataType elementType,
      std::vector<ANARIObject> &copied);
  // The same for an object array's current contents.
  std::vector<ANARIObject> translateObjectArray(
      Findings &f, ObjectRecord &array);
  void setDeviceParameter(
      const char *name, ANARIDataType type, const void *mem);
  void commitDevice();
  void reportLeaks();

  // The trace (TraceCalls.cpp), when ANARI_DEBUG_TRACE names a file or the
  // `traceDir` parameter a folder: each
  // forwarded call as a line, objects named by creation number. Under the
  // lock, so lines come in the order calls were checked.
  void openTrace();
  // The trace's first line: the device subtype and library wrapped.
  void traceDeviceLine();
  bool tracing() const
  {
    return m_trace != nullptr;
  }
  // Returns the line's number in the trace (0: not tracing).
  uint64_t trace(const std::string &line);
  // The line of a call the layer refused: `call`, the handle's name (it may
  // be released, `foreign` or `null`) and `operands`. Under the lock.
  std::string refusedLine(
      const char *call, ANARIObject handle, const std::string &operands = {});
  std::string traceName(ANARIObject handle);
  // The operand for a parameter value ("" if it cannot be traced).
  std::string traceValue(ANARIDataType type, const void *mem);
  // An array's contents as an operand: names of an object array's
  // elements, or the bytes in the side file (elements `stride` apart).
  std::string traceContents(ANARIDataType elementType,
      const void *memory,
      uint64_t count,
      uint64_t stride);

  std::recursive_mutex m_mutex; // NOTE: guards everything below
  ObjectTable m_objects;
  std::atomic<uint64_t> m_calls{0};

  ANARIStatusCallback m_statusCallback{nullptr};
  const void *m_statusUserPtr{nullptr};
  std::string m_subtype;
  std::string m_wrappedSpec;
  std::string m_pendingWrappedSpec;
  std::string m_pendingSubtype;                // the `wrappedDevice` parameter
  anari::DeviceImpl *m_pendingDevice{nullptr}; // ... as a handle
  std::string m_pendingTraceDir;
  std::string m_failure;
  std::shared_ptr<WrappedLibrary> m_wrappedLibrary;
  // False for a device the application handed over (never released here).
  bool m_ownsWrapped{true};
  std::unique_ptr<introspection::Catalog> m_catalog;
  std::unique_ptr<Rules> m_rules;
  int m_publicReferences{1};
  std::unique_ptr<trace::TraceWriter> m_trace;
};

} // namespace prism::debug
