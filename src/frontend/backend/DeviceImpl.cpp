// Base behaviour of a device, shared by libanari and device libraries.
#include "anari/backend/DeviceImpl.h"

namespace anari {

ANARIObject DeviceImpl::newObject(const char *, const char *)
{
  return nullptr;
}

void (*DeviceImpl::getProcAddress(const char *))(void)
{
  return nullptr;
}

DeviceImpl::DeviceImpl(ANARILibrary library)
{
  auto *impl = (LibraryImpl *)library;
  if (impl) {
    m_defaultStatusCB = impl->defaultStatusCB();
    m_defaultStatusCBUserPtr = impl->defaultStatusCBUserPtr();
  }
}

ANARIDevice DeviceImpl::this_device() const
{
  return (ANARIDevice)this;
}

ANARIStatusCallback DeviceImpl::defaultStatusCallback() const
{
  return m_defaultStatusCB;
}

const void *DeviceImpl::defaultStatusCallbackUserPtr() const
{
  return m_defaultStatusCBUserPtr;
}

bool DeviceImpl::handleIsDevice(ANARIObject object) const
{
  return (ANARIObject)this_device() == object;
}

} // namespace anari
