#include "HandleRegistry.h"

namespace prism::frontend {

HandleRegistry &HandleRegistry::instance()
{
  static HandleRegistry registry;
  return registry;
}

void HandleRegistry::addLibrary(anari::LibraryImpl *library, StatusSink sink)
{
  std::lock_guard lock(m_mutex);
  m_libraries[library] =
      LibraryRecord{sink, library->libraryHandle(), 0, false, ++m_loadCounter};
}

bool HandleRegistry::hasLibrary(ANARILibrary handle) const
{
  std::lock_guard lock(m_mutex);
  auto it = m_libraries.find((anari::LibraryImpl *)handle);
  return it != m_libraries.end() && !it->second.unloaded;
}

void *HandleRegistry::removeLibrary(anari::LibraryImpl *library)
{
  std::lock_guard lock(m_mutex);
  auto it = m_libraries.find(library);
  if (it == m_libraries.end())
    return nullptr;
  void *dlHandle = it->second.dlHandle;
  if (it->second.liveDevices > 0) {
    it->second.unloaded = true;
    return nullptr;
  }
  m_libraries.erase(it);
  return dlHandle;
}

void HandleRegistry::addDevice(
    anari::DeviceImpl *device, anari::LibraryImpl *library)
{
  std::lock_guard lock(m_mutex);
  m_devices[device] = DeviceRecord{library, 1};
  m_libraries[library].liveDevices++;
}

bool HandleRegistry::hasDevice(ANARIDevice handle) const
{
  std::lock_guard lock(m_mutex);
  return m_devices.count((anari::DeviceImpl *)handle) != 0;
}

void HandleRegistry::retainDevice(anari::DeviceImpl *device)
{
  std::lock_guard lock(m_mutex);
  auto it = m_devices.find(device);
  if (it != m_devices.end())
    it->second.publicRefs++;
}

void *HandleRegistry::releaseDevice(anari::DeviceImpl *device)
{
  std::lock_guard lock(m_mutex);
  auto it = m_devices.find(device);
  if (it == m_devices.end() || --it->second.publicRefs > 0)
    return nullptr;
  auto *library = it->second.library;
  m_devices.erase(it);
  auto lib = m_libraries.find(library);
  if (lib == m_libraries.end() || --lib->second.liveDevices > 0
      || !lib->second.unloaded)
    return nullptr;
  void *dlHandle = lib->second.dlHandle;
  m_libraries.erase(lib);
  return dlHandle;
}

StatusSink HandleRegistry::fallbackSink() const
{
  std::lock_guard lock(m_mutex);
  const LibraryRecord *newest = nullptr;
  for (auto &[library, record] : m_libraries) {
    if (!record.unloaded && (!newest || record.loadOrder > newest->loadOrder))
      newest = &record;
  }
  return newest ? newest->sink : StatusSink{};
}

StatusSink HandleRegistry::sinkOf(ANARIDevice handle) const
{
  std::lock_guard lock(m_mutex);
  auto it = m_devices.find((anari::DeviceImpl *)handle);
  if (it == m_devices.end())
    return {};
  auto lib = m_libraries.find(it->second.library);
  return lib == m_libraries.end() ? StatusSink{} : lib->second.sink;
}

} // namespace prism::frontend
