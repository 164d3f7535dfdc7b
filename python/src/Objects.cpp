// Objects and their parameters: values arrive from the Python half already
// converted to the exact bytes of their ANARI type; this file checks the
// byte count so a parameter is never read past its end.
#include "Binding.h"

#include <anari/frontend/type_utility.h>

#include <cstring>
#include <vector>

namespace prism::python {

Object::Object(std::shared_ptr<DeviceState> device,
    ANARIObject handle,
    ANARIDataType category,
    std::string subtype)
    : m_device(std::move(device)),
      m_handle(handle),
      m_category(category),
      m_subtype(std::move(subtype))
{}

Object::~Object()
{
  // The device's own handle belongs to DeviceState.
  ANARIObject handle = m_handle.exchange(nullptr);
  if (!handle || m_category == ANARI_DEVICE)
    return;
  withoutGil([&] {
    std::shared_lock lock(m_device->lock);
    if (!m_device->released)
      anariRelease(m_device->handle, handle);
  });
}

std::string Object::describe() const
{
  if (m_category == ANARI_DEVICE)
    return "the device";
  std::string category = anari::toString(m_category);
  category = category.substr(category.find('_') + 1);
  for (char &c : category)
    c = char(std::tolower((unsigned char)c));
  for (char &c : category)
    if (c == '_')
      c = ' ';
  if (m_subtype == category || m_subtype.empty())
    return "the " + category;
  return "the " + m_subtype + " " + category;
}

void Object::setBytes(
    const std::string &name, ANARIDataType type, py::buffer value)
{
  if (anari::isObject(type) || type == ANARI_STRING
      || type == ANARI_VOID_POINTER || anari::sizeOf(type) == 0)
    throw py::type_error(std::string("parameter '") + name + "' of "
                         + describe() + ": " + anari::toString(type)
                         + " values are not passed as bytes");
  py::buffer_info info = value.request();
  // C order: each stride is the next dimension's stride times its size.
  bool contiguous = true;
  py::ssize_t expected = info.itemsize;
  for (py::ssize_t i = info.ndim - 1; i >= 0; i--) {
    if (info.shape[i] > 1 && info.strides[i] != expected)
      contiguous = false;
    expected *= info.shape[i];
  }
  const size_t bytes = size_t(info.size) * size_t(info.itemsize);
  if (!contiguous || bytes != anari::sizeOf(type))
    throw py::value_error(std::string("parameter '") + name + "' of "
                          + describe() + ": " + anari::toString(type)
                          + " needs " + std::to_string(anari::sizeOf(type))
                          + " contiguous bytes, got " + std::to_string(bytes));
  // Copied: the device owns what it keeps after the call returns.
  std::vector<unsigned char> copy(bytes);
  std::memcpy(copy.data(), info.ptr, bytes);
  withHandle("setParameter", [&](ANARIDevice d, ANARIObject h) {
    anariSetParameter(d, h, name.c_str(), type, copy.data());
  });
}

void Object::setObject(
    const std::string &name, ANARIDataType type, Object &value)
{
  if (!anari::isObject(type))
    throw py::type_error(std::string("parameter '") + name + "' of "
                         + describe() + ": " + anari::toString(type)
                         + " is not an object type");
  if (value.device() != device())
    throw py::value_error(std::string("parameter '") + name + "' of "
                          + describe() + ": " + value.describe()
                          + " belongs to another device");
  if (value.isReleased())
    throw ReleasedError(std::string("parameter '") + name + "' of " + describe()
                        + ": " + value.describe() + " was released");
  ANARIObject handle = value.handle();
  withHandle("setParameter", [&](ANARIDevice d, ANARIObject h) {
    anariSetParameter(d, h, name.c_str(), type, &handle);
  });
}

void Object::setString(const std::string &name, const std::string &value)
{
  withHandle("setParameter", [&](ANARIDevice d, ANARIObject h) {
    anariSetParameter(d, h, name.c_str(), ANARI_STRING, value.c_str());
  });
}

void Object::unset(const std::string &name)
{
  withHandle("unsetParameter", [&](ANARIDevice d, ANARIObject h) {
    anariUnsetParameter(d, h, name.c_str());
  });
}

void Object::commit()
{
  withHandle("commitParameters",
      [&](ANARIDevice d, ANARIObject h) { anariCommitParameters(d, h); });
}

void Object::release()
{
  if (!m_handle.load())
    return;
  withHandle("release", [&](ANARIDevice d, ANARIObject) {
    if (ANARIObject handle = m_handle.exchange(nullptr))
      anariRelease(d, handle);
  });
}

py::object Object::getProperty(
    const std::string &name, ANARIDataType type, bool wait)
{
  const ANARIWaitMask mask = wait ? ANARI_WAIT : ANARI_NO_WAIT;
  if (type == ANARI_STRING) {
    uint64_t size = 0;
    const std::string sizeName = name + ".size";
    int found = withHandle("getProperty", [&](ANARIDevice d, ANARIObject h) {
      return anariGetProperty(
          d, h, sizeName.c_str(), ANARI_UINT64, &size, sizeof(size), mask);
    });
    if (!found || size == 0 || size > (1u << 20))
      return py::none();
    std::string text(size, '\0');
    found = withHandle("getProperty", [&](ANARIDevice d, ANARIObject h) {
      return anariGetProperty(
          d, h, name.c_str(), ANARI_STRING, text.data(), size, mask);
    });
    if (!found)
      return py::none();
    return py::str(text.c_str());
  }
  if (type == ANARI_STRING_LIST) {
    const char **list = nullptr;
    int found = withHandle("getProperty", [&](ANARIDevice d, ANARIObject h) {
      return anariGetProperty(
          d, h, name.c_str(), type, &list, sizeof(list), mask);
    });
    py::list out;
    for (; found && list && *list; list++)
      out.append(*list);
    return found ? py::object(out) : py::none();
  }
  const size_t size = anari::sizeOf(type);
  if (size == 0 || anari::isObject(type))
    throw py::type_error(std::string("property '") + name
                         + "': " + anari::toString(type)
                         + " properties cannot be read from Python");
  std::vector<char> bytes(size);
  int found = withHandle("getProperty", [&](ANARIDevice d, ANARIObject h) {
    return anariGetProperty(
        d, h, name.c_str(), type, bytes.data(), bytes.size(), mask);
  });
  if (!found)
    return py::none();
  return py::bytes(bytes.data(), bytes.size());
}

void bindObjects(py::module_ &m)
{
  py::class_<Object, std::shared_ptr<Object>>(m, "Object")
      .def_property_readonly(
          "category", [](const Object &o) { return int(o.category()); })
      .def_property_readonly("subtype", &Object::subtype)
      .def_property_readonly("isReleased", &Object::isReleased)
      .def("describe", &Object::describe)
      .def("setBytes",
          [](Object &o, const std::string &name, int type, py::buffer value) {
            o.setBytes(name, ANARIDataType(type), value);
          })
      .def("setObject",
          [](Object &o, const std::string &name, int type, Object &value) {
            o.setObject(name, ANARIDataType(type), value);
          })
      .def("setString", &Object::setString)
      .def("unset", &Object::unset)
      .def("commit", &Object::commit)
      .def("release", &Object::release)
      .def(
          "getProperty",
          [](Object &o, const std::string &name, int type, bool wait) {
            return o.getProperty(name, ANARIDataType(type), wait);
          },
          py::arg("name"),
          py::arg("type"),
          py::arg("wait") = true)
      .def("sameDevice", [](const Object &a, const Object &b) {
        return a.device() == b.device();
      });
}

} // namespace prism::python
