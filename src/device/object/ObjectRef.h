// An internal reference on an object: what a parent holds on its children so
// they outlive frames in flight and the application's releases.
#pragma once

#include <utility>

namespace prism {

template <typename T>
class ObjectRef
{
 public:
  ObjectRef() = default;
  explicit ObjectRef(T *object) : m_object(object)
  {
    if (m_object)
      m_object->retainInternal();
  }
  ObjectRef(const ObjectRef &other) : ObjectRef(other.m_object) {}
  ObjectRef(ObjectRef &&other) noexcept
      : m_object(std::exchange(other.m_object, nullptr))
  {}
  ObjectRef &operator=(ObjectRef other) noexcept
  {
    std::swap(m_object, other.m_object);
    return *this;
  }
  ~ObjectRef()
  {
    reset();
  }

  void reset()
  {
    if (T *object = std::exchange(m_object, nullptr))
      object->releaseInternal();
  }
  T *get() const
  {
    return m_object;
  }
  T *operator->() const
  {
    return m_object;
  }
  explicit operator bool() const
  {
    return m_object != nullptr;
  }

 private:
  T *m_object{nullptr};
};

} // namespace prism
