// The trace's lines for the calls the layer forwards (docs/debug-layer.md).
#include "DebugDevice.h"
#include "trace/TraceFormat.h"

#include "anari/frontend/type_utility.h"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace prism::debug {

void DebugDevice::openTrace()
{
  const char *path = std::getenv("ANARI_DEBUG_TRACE");
  if (!path || !*path)
    return;
  // Each device of the process writes its own trace: FILE, FILE.2, ...
  static std::atomic<int> devices{0};
  const int n = ++devices;
  const std::string file =
      n == 1 ? std::string(path) : std::string(path) + "." + std::to_string(n);
  auto writer = std::make_unique<trace::TraceWriter>(file);
  if (!writer->ok()) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "ANARI_DEBUG_TRACE: cannot write the trace '" + file + "'");
    return;
  }
  m_trace = std::move(writer);
  traceDeviceLine();
}

void DebugDevice::traceDeviceLine()
{
  trace(
      "Device " + trace::quote(m_subtype) + " " + trace::quote(m_wrappedSpec));
  // A replay cannot make the application's device: it replays on the
  // library it is given (anari-replay --library).
  if (!m_ownsWrapped)
    trace(
        "# the wrapped device is one the application created and handed "
        "over ('wrappedDevice')");
}

uint64_t DebugDevice::trace(const std::string &line)
{
  return m_trace ? m_trace->line(line) : 0;
}

std::string DebugDevice::refusedLine(
    const char *call, ANARIObject handle, const std::string &operands)
{
  return std::string(call)
      .append(" ")
      .append(traceName(handle))
      .append(operands);
}

std::string DebugDevice::traceName(ANARIObject handle)
{
  if (!handle)
    return "null";
  if (isDevice(handle))
    return "device";
  const ObjectRecord *record = m_objects.find(handle);
  // Appended, not concatenated: GCC 12 raises a false -Wrestrict.
  // A handle the layer never made (another device's, corrupt): `foreign`.
  return record ? std::string("o").append(std::to_string(record->serial))
                : "foreign";
}

std::string DebugDevice::traceValue(ANARIDataType type, const void *mem)
{
  if (!trace::isTraceable(type) || (!mem && type != ANARI_VOID_POINTER))
    return {};
  if (type == ANARI_STRING)
    return trace::quote((const char *)mem);
  if (anari::isObject(type)) {
    ANARIObject handle = nullptr;
    std::memcpy(&handle, mem, sizeof(handle));
    return traceName(handle);
  }
  if (type == ANARI_DATA_TYPE) {
    ANARIDataType value;
    std::memcpy(&value, mem, sizeof(value));
    return trace::typeName(value);
  }
  return trace::encodeValue(type, mem);
}

std::string DebugDevice::traceContents(ANARIDataType elementType,
    const void *memory,
    uint64_t count,
    uint64_t stride)
{
  if (!memory)
    return "-";
  const uint64_t size = anari::sizeOf(elementType);
  const uint64_t step = stride ? stride : size;
  if (anari::isObject(elementType)) {
    std::string out = "[";
    for (uint64_t i = 0; i < count; ++i) {
      ANARIObject handle = nullptr;
      std::memcpy(&handle, (const char *)memory + i * step, sizeof(handle));
      out.append(i ? " " : "").append(traceName(handle));
    }
    return out + "]";
  }
  if (step == size)
    return m_trace->blob(memory, count * size);
  std::vector<unsigned char> packed(count * size);
  for (uint64_t i = 0; i < count; ++i)
    std::memcpy(
        packed.data() + i * size, (const char *)memory + i * step, size);
  return m_trace->blob(packed.data(), packed.size());
}

} // namespace prism::debug
