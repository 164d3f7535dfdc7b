// A device whose objects tests create, parameterise and commit directly
// (no flush), collecting every status message the device reports.
#pragma once

#include "Device.h"
#include "array/Array.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace prism::testing {

class ObjectTestFixture : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    ANARIStatusCallback callback = [](const void *user,
                                       ANARIDevice,
                                       ANARIObject,
                                       ANARIDataType,
                                       ANARIStatusSeverity severity,
                                       ANARIStatusCode,
                                       const char *message) {
      auto *fixture = (ObjectTestFixture *)user;
      fixture->m_messages.push_back({severity, message});
      if (severity <= ANARI_SEVERITY_ERROR)
        fixture->m_errors.push_back(message);
    };
    const auto device = (ANARIObject)m_device.this_device();
    m_device.setParameter(
        device, "statusCallback", ANARI_STATUS_CALLBACK, &callback);
    m_device.setParameter(
        device, "statusCallbackUserData", ANARI_VOID_POINTER, this);
  }
  void TearDown() override
  {
    for (Object *object : m_objects)
      object->releaseInternal();
    for (ANARIObject handle : m_handles)
      m_device.release(handle);
  }

  template <typename T>
  T *make()
  {
    auto *object = new T(m_device);
    m_objects.push_back(object);
    return object;
  }
  // A managed 1D array holding a copy of `values`.
  template <typename T>
  Array *array(ANARIDataType type, const std::vector<T> &values)
  {
    const uint64_t count = values.size() * sizeof(T) / anari::sizeOf(type);
    ANARIObject handle =
        m_device.newArray1D(nullptr, nullptr, nullptr, type, count);
    auto *result = (Array *)m_device.lookup(handle);
    if (count > 0)
      std::memcpy(result->map(), values.data(), values.size() * sizeof(T));
    result->unmap();
    m_handles.push_back(handle);
    return result;
  }
  // `handle`, released in TearDown.
  template <typename T>
  T keep(T handle)
  {
    m_handles.push_back(handle);
    return handle;
  }
  // The handle of a managed 1D array holding a copy of `count` values.
  ANARIArray1D managedArray(
      ANARIDataType type, const void *values, uint64_t count)
  {
    ANARIArray1D array =
        keep(m_device.newArray1D(nullptr, nullptr, nullptr, type, count));
    std::memcpy(m_device.mapArray(array), values, count * anari::sizeOf(type));
    m_device.unmapArray(array);
    return array;
  }
  static void set(
      Object *object, const char *name, ANARIDataType type, const void *mem)
  {
    Object *value = anari::isObject(type) ? (Object *)mem : nullptr;
    object->stageParameter(name, Parameter::make(type, mem, value));
  }
  static void commit(Object *object)
  {
    object->snapshotForCommit();
    object->applyCommit();
    object->finalize();
  }
  // Whether an error or fatal message contains every one of `parts`.
  bool reported(std::initializer_list<const char *> parts) const
  {
    for (const std::string &message : m_errors) {
      bool all = true;
      for (const char *part : parts)
        all = all && message.find(part) != std::string::npos;
      if (all)
        return true;
    }
    return false;
  }

  struct Message
  {
    ANARIStatusSeverity severity;
    std::string text;
  };
  std::vector<Message> m_messages;   // every message
  std::vector<std::string> m_errors; // the error and fatal ones
  Device m_device{nullptr};
  std::vector<Object *> m_objects;
  std::vector<ANARIObject> m_handles; // released in TearDown
};

} // namespace prism::testing
