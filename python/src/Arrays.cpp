// Arrays: an ndarray is shared with the device without a copy. The device
// gets the array's memory and a deleter; the ndarray is kept alive by one
// reference that the deleter drops, so it lives exactly as long as the
// device needs it. Lists of objects become managed object arrays.
#include "Binding.h"

#include <anari/frontend/type_utility.h>

#include <cstring>

namespace prism::python {

namespace {

// Shared ndarrays the device still holds, for tests and leak checks.
std::atomic<int64_t> g_sharedArraysHeld{0};

// NOTE: called by the device when it lets go of the memory, possibly on one
// of its own threads; takes the GIL to drop the reference.
void dropSharedArray(const void *userData, const void *)
{
  g_sharedArraysHeld--;
  if (!pythonAlive())
    return; // the interpreter is going away; its memory goes with it
  py::gil_scoped_acquire gil;
  Py_DECREF(reinterpret_cast<PyObject *>(const_cast<void *>(userData)));
}

ANARIArray newHandle(ANARIDevice d,
    const void *memory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType type,
    const std::vector<uint64_t> &shape)
{
  switch (shape.size()) {
  case 1:
    return anariNewArray1D(d, memory, deleter, userData, type, shape[0]);
  case 2:
    return anariNewArray2D(
        d, memory, deleter, userData, type, shape[0], shape[1]);
  default:
    return anariNewArray3D(
        d, memory, deleter, userData, type, shape[0], shape[1], shape[2]);
  }
}

std::string typeName(ANARIDataType type)
{
  return anari::toString(type);
}

std::shared_ptr<Array> newSharedArray(Device &device,
    ANARIDataType elementType,
    py::array values,
    std::vector<uint64_t> shape)
{
  if (shape.empty() || shape.size() > 3)
    throw py::value_error("arrays have 1, 2 or 3 dimensions");
  if (anari::isObject(elementType) || anari::sizeOf(elementType) == 0
      || elementType == ANARI_STRING)
    throw py::type_error(
        "arrays of " + typeName(elementType) + " cannot share an ndarray");
  uint64_t count = 1;
  for (uint64_t n : shape)
    count *= n;
  const uint64_t bytes = count * anari::sizeOf(elementType);
  const int flags = py::detail::array_proxy(values.ptr())->flags;
  const bool laidOut = (flags & py::detail::npy_api::NPY_ARRAY_C_CONTIGUOUS_)
                       && (flags & py::detail::npy_api::NPY_ARRAY_ALIGNED_);
  if (!laidOut)
    throw py::value_error(
        "the ndarray must be C-contiguous and aligned to be shared");
  if (uint64_t(values.nbytes()) != bytes)
    throw py::value_error("an array of " + std::to_string(count) + " "
                          + typeName(elementType) + " needs "
                          + std::to_string(bytes) + " bytes; the ndarray has "
                          + std::to_string(values.nbytes()));
  PyObject *keepAlive = values.ptr();
  Py_INCREF(keepAlive);
  g_sharedArraysHeld++;
  ANARIArray handle = nullptr;
  try {
    handle = device.withHandle("newArray", [&](ANARIDevice d, ANARIObject) {
      return newHandle(
          d, values.data(), dropSharedArray, keepAlive, elementType, shape);
    });
  } catch (...) {
    g_sharedArraysHeld--;
    Py_DECREF(keepAlive);
    throw;
  }
  if (!handle) {
    // A refused array never took the memory; its deleter is not called.
    g_sharedArraysHeld--;
    Py_DECREF(keepAlive);
    throw DeviceError("the device refused an array of " + typeName(elementType)
                      + " (see the log for why)");
  }
  return std::make_shared<Array>(
      device.device(), handle, elementType, std::move(shape));
}

std::shared_ptr<Array> newObjectArray(
    Device &device, ANARIDataType elementType, py::sequence objects)
{
  if (!anari::isObject(elementType))
    throw py::type_error(typeName(elementType) + " is not an object type");
  std::vector<ANARIObject> handles;
  std::vector<std::shared_ptr<Object>> keep;
  for (py::handle item : objects) {
    auto object = item.cast<std::shared_ptr<Object>>();
    if (object->device() != device.device())
      throw py::value_error(object->describe() + " belongs to another device");
    if (object->isReleased())
      throw ReleasedError(object->describe() + " was released");
    handles.push_back(object->handle());
    keep.push_back(std::move(object));
  }
  const uint64_t count = handles.size();
  ANARIArray handle =
      device.withHandle("newArray", [&](ANARIDevice d, ANARIObject) {
        ANARIArray array =
            anariNewArray1D(d, nullptr, nullptr, nullptr, elementType, count);
        if (!array)
          return array;
        void *memory = anariMapArray(d, array);
        if (memory && count)
          std::memcpy(memory, handles.data(), count * sizeof(ANARIObject));
        anariUnmapArray(d, array);
        return array;
      });
  if (!handle)
    throw DeviceError("the device refused an array of " + typeName(elementType)
                      + " (see the log for why)");
  return std::make_shared<Array>(
      device.device(), handle, elementType, std::vector<uint64_t>{count});
}

// The array's elements as the device holds them (mapped, copied, unmapped),
// as a uint8 ndarray.
py::array_t<uint8_t> contents(Array &array)
{
  std::vector<unsigned char> bytes;
  array.withHandle("contents", [&](ANARIDevice d, ANARIObject h) {
    const auto handle = static_cast<ANARIArray>(h);
    const void *memory = anariMapArray(d, handle);
    uint64_t count = 1;
    for (uint64_t n : array.shape())
      count *= n;
    if (memory) {
      const auto *begin = static_cast<const unsigned char *>(memory);
      bytes.assign(begin, begin + count * anari::sizeOf(array.elementType()));
    }
    anariUnmapArray(d, handle);
  });
  py::array_t<uint8_t> out(py::ssize_t(bytes.size()));
  if (!bytes.empty())
    std::memcpy(out.mutable_data(), bytes.data(), bytes.size());
  return out;
}

} // namespace

Array::Array(std::shared_ptr<DeviceState> device,
    ANARIObject handle,
    ANARIDataType elementType,
    std::vector<uint64_t> shape)
    : Object(std::move(device),
        handle,
        shape.size() == 1   ? ANARI_ARRAY1D
        : shape.size() == 2 ? ANARI_ARRAY2D
                            : ANARI_ARRAY3D,
        typeName(elementType)),
      m_elementType(elementType),
      m_shape(std::move(shape))
{}

void bindArrays(py::module_ &m)
{
  py::class_<Array, Object, std::shared_ptr<Array>>(m, "Array")
      .def_property_readonly(
          "elementType", [](const Array &a) { return int(a.elementType()); })
      .def_property_readonly("shape", &Array::shape)
      .def("contents", &contents);
  m.def("newSharedArray",
      [](Device &device,
          int type,
          py::array values,
          std::vector<uint64_t> shape) {
        return newSharedArray(device, ANARIDataType(type), values, shape);
      });
  m.def("newObjectArray", [](Device &device, int type, py::sequence objects) {
    return newObjectArray(device, ANARIDataType(type), objects);
  });
  m.def("sharedArraysHeld", [] { return g_sharedArraysHeld.load(); });
}

} // namespace prism::python
