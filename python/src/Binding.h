// The native half of the `prism` Python package (prism._native): thin,
// checked wrappers over the ANARI C API. Type inference, attribute syntax and
// logging live in the Python half (python/prism/); this half owns handles,
// the GIL and everything that must never read memory wrongly.
#pragma once

#include <anari/anari.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <type_traits>
#include <vector>

namespace prism::python {

namespace py = pybind11;

// False once the interpreter is shutting down: callbacks from device
// threads must not touch Python then.
bool pythonAlive();

// A loaded ANARI library; unloaded when the last device made from it goes.
struct LibraryState
{
  ANARILibrary handle{nullptr};
  std::string name;
  ~LibraryState();
};

// A device handle shared by every object made on it. `released` is set by
// Device.release(); objects check it (under `lock`) before each call.
struct DeviceState
{
  ANARIDevice handle{nullptr};
  std::shared_ptr<LibraryState> library;
  // NOTE: taken shared by every call on an object, unique by release();
  // always with the GIL released, so a status callback or array deleter
  // that needs the GIL on another thread cannot deadlock against it.
  std::shared_mutex lock;
  bool released{false};
  ~DeviceState();
};

// An ANARI object (the device is one too): its handle, category, subtype.
class Object
{
 public:
  Object(std::shared_ptr<DeviceState> device,
      ANARIObject handle,
      ANARIDataType category,
      std::string subtype);
  virtual ~Object();

  ANARIObject handle() const
  {
    return m_handle.load();
  }
  ANARIDataType category() const
  {
    return m_category;
  }
  const std::string &subtype() const
  {
    return m_subtype;
  }
  const std::shared_ptr<DeviceState> &device() const
  {
    return m_device;
  }
  bool isReleased() const
  {
    return m_handle.load() == nullptr;
  }
  // "the perspective camera" / "the world", for messages.
  std::string describe() const;

  void setBytes(const std::string &name, ANARIDataType type, py::buffer value);
  void setObject(const std::string &name, ANARIDataType type, Object &value);
  void setString(const std::string &name, const std::string &value);
  void unset(const std::string &name);
  void commit();
  virtual void release();
  // Raw bytes of a property of `type`, or None when the object has none.
  py::object getProperty(
      const std::string &name, ANARIDataType type, bool wait);

  // Runs `call(device, handle)` with the GIL released and the device held;
  // throws a Python error for a released object or device.
  template <typename Call>
  auto withHandle(const char *what, Call &&call);

 private:
  std::shared_ptr<DeviceState> m_device;
  // NOTE: atomic: release() on one Python thread may race a call on another
  // (the device then reports the stale handle; nothing is released twice).
  std::atomic<ANARIObject> m_handle{nullptr};
  ANARIDataType m_category{ANARI_UNKNOWN};
  std::string m_subtype;
};

// The device is an object too (device parameters, properties); release()
// releases it and marks every object made on it dead.
class Device : public Object
{
 public:
  explicit Device(std::shared_ptr<DeviceState> device);
  void release() override;
};

// A frame: render, wait and map its channels (Frames.cpp).
class Frame : public Object
{
 public:
  using Object::Object;
};

// An array: its element type and size per dimension (Arrays.cpp).
class Array : public Object
{
 public:
  Array(std::shared_ptr<DeviceState> device,
      ANARIObject handle,
      ANARIDataType elementType,
      std::vector<uint64_t> shape);
  ANARIDataType elementType() const
  {
    return m_elementType;
  }
  const std::vector<uint64_t> &shape() const
  {
    return m_shape;
  }

 private:
  ANARIDataType m_elementType;
  std::vector<uint64_t> m_shape;
};

// Runs `work` without the GIL when this thread holds it and Python is alive
// (destructors run both from Python and during interpreter shutdown).
template <typename Work>
void withoutGil(Work &&work)
{
  if (pythonAlive() && PyGILState_Check()) {
    py::gil_scoped_release noGil;
    work();
  } else {
    work();
  }
}

// prism.AnariError: an error the device reported while raise_on_error is on.
struct DeviceError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};
// prism.ReleasedError (an AnariError): a call on a released object, or on an
// object whose device was released.
struct ReleasedError : DeviceError
{
  using DeviceError::DeviceError;
};

// Status.cpp: the status callback libraries are loaded with, and the
// per-thread error raise_on_error turns into an exception.
void statusCallback(const void *userData,
    ANARIDevice device,
    ANARIObject source,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message);
// Starts collecting the device's errors of this thread's next call.
void beginCall();
// Throws prism.AnariError if that call reported an error and raising is on.
void endCall();

// Each file binds its concept onto the module.
void bindStatus(py::module_ &m);
void bindTypes(py::module_ &m);
void bindLibraryAndDevice(py::module_ &m);
void bindObjects(py::module_ &m);
void bindArrays(py::module_ &m);
void bindFrames(py::module_ &m);
void bindIntrospection(py::module_ &m);
void bindScenes(py::module_ &m);

template <typename Call>
auto Object::withHandle(const char *what, Call &&call)
{
  std::shared_ptr<DeviceState> device = m_device;
  auto guarded = [&] {
    py::gil_scoped_release noGil;
    std::shared_lock lock(device->lock);
    if (device->released)
      throw ReleasedError("the device of " + describe() + " was released; "
                          + what + " needs a live device");
    ANARIObject handle = m_handle.load();
    if (!handle)
      throw ReleasedError(
          describe() + " was released; " + what + " needs a live object");
    return call(device->handle, handle);
  };
  beginCall();
  if constexpr (std::is_void_v<decltype(guarded())>) {
    guarded();
    endCall();
  } else {
    auto result = guarded();
    endCall();
    return result;
  }
}

} // namespace prism::python
