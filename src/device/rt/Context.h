// The Embree device of one prism device. Embree's errors and memory
// warnings go to the prism device's status callback.
#pragma once

#include <functional>
#include <string>

struct RTCDeviceTy;

namespace prism::rt {

class Context
{
 public:
  using ErrorSink = std::function<void(const std::string &message)>;

  explicit Context(ErrorSink onError);
  ~Context();
  Context(const Context &) = delete;
  Context &operator=(const Context &) = delete;

  RTCDeviceTy *handle() const
  {
    return m_device;
  }
  // Whether Embree could be initialised at all.
  bool isValid() const
  {
    return m_device != nullptr;
  }
  void reportError(const std::string &message) const
  {
    if (m_onError)
      m_onError(message);
  }

 private:
  ErrorSink m_onError;
  RTCDeviceTy *m_device{nullptr};
};

} // namespace prism::rt
