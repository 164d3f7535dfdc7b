#include "WrappedDevice.h"

#include "frame/PixelFormat.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cstring>

namespace prism::mpi {
namespace {

const float4 kTransparent{0.f, 0.f, 0.f, 0.f};
const float4 kDefaultBackground{0.f, 0.f, 0.f, 1.f}; // the spec's

} // namespace

std::unique_ptr<WrappedDevice> WrappedDevice::load(const std::string &spec,
    const std::string &subtype,
    ANARIStatusCallback status,
    const void *statusUserPtr,
    Report report,
    std::string &error)
{
  std::string loadError;
  auto library = frontend::LoadedLibrary::load(
      spec, status, statusUserPtr, "prism_mpi", loadError);
  if (!library) {
    error = "device: cannot load wrappedLibrary '" + spec + "' (" + loadError
            + "); the built-in prism core renders instead";
    return nullptr;
  }
  anari::DeviceImpl *device = nullptr;
  try {
    device = (anari::DeviceImpl *)library->library().newDevice(subtype.c_str());
  } catch (...) {
    device = nullptr;
  }
  if (!device) {
    error = "device: wrappedLibrary '" + spec + "' has no device of subtype '"
            + subtype
            + "' (wrappedDevice); the built-in prism core renders instead";
    return nullptr;
  }
  return std::unique_ptr<WrappedDevice>(
      new WrappedDevice(std::move(library), device, std::move(report)));
}

WrappedDevice::WrappedDevice(std::shared_ptr<frontend::LoadedLibrary> library,
    anari::DeviceImpl *device,
    Report report)
    : ForwardingDevice(nullptr),
      m_library(std::move(library)),
      m_report(std::move(report))
{
  setInner(device);
}

WrappedDevice::~WrappedDevice()
{
  // The wrapped device goes before its library (a member, closed after).
  inner()->release((ANARIObject)inner());
}

bool WrappedDevice::admits(ANARIObject object, const char *call)
{
  {
    std::lock_guard lock(m_mutex);
    if (object && m_handles.count(object))
      return true;
  }
  // Never forwarded: another library may not check its handles.
  m_report(object,
      ANARI_OBJECT,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      std::string(call)
          + ": the handle is no live object of this device (NULL, released"
            " or another device's); the call is ignored");
  return false;
}

ANARIObject WrappedDevice::created(ANARIObject handle, ANARIDataType type)
{
  if (handle) {
    std::lock_guard lock(m_mutex);
    m_handles[handle] = Handle{type, 1};
  }
  return handle;
}

void WrappedDevice::setLinearChannels(ANARIObject frame)
{
  // The wrapped frame always renders what compositing needs.
  const ANARIDataType color = ANARI_FLOAT32_VEC4;
  const ANARIDataType depth = ANARI_FLOAT32;
  inner()->setParameter(frame, "channel.color", ANARI_DATA_TYPE, &color);
  inner()->setParameter(frame, "channel.depth", ANARI_DATA_TYPE, &depth);
}

void WrappedDevice::clearBackground(ANARIObject renderer)
{
  inner()->setParameter(
      renderer, "background", ANARI_FLOAT32_VEC4, &kTransparent);
}

// Creation ///////////////////////////////////////////////////////////////////

ANARIObject WrappedDevice::newObjectOf(ANARIDataType type, const char *subtype)
{
  ANARIObject handle =
      created(ForwardingDevice::newObjectOf(type, subtype), type);
  if (handle && type == ANARI_FRAME) {
    setLinearChannels(handle);
    std::lock_guard lock(m_mutex);
    m_frames[handle] = FrameRecord{};
  } else if (handle && type == ANARI_RENDERER) {
    // Committed at once: a renderer the application never commits must
    // not render the spec's opaque black either.
    clearBackground(handle);
    inner()->commitParameters(handle);
    std::lock_guard lock(m_mutex);
    m_renderers[handle] = RendererRecord{
        subtype ? subtype : "default", kDefaultBackground, kDefaultBackground};
  }
  return handle;
}

ANARIArray WrappedDevice::newArrayOf(ANARIDataType arrayType,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    const uint64_t items[3])
{
  return (ANARIArray)created(
      ForwardingDevice::newArrayOf(
          arrayType, appMemory, deleter, userData, elementType, items),
      arrayType);
}

ANARIObject WrappedDevice::newObject(
    const char *objectType, const char *subtype)
{
  return created(
      ForwardingDevice::newObject(objectType, subtype), ANARI_OBJECT);
}

// Calls on handles the application holds
// //////////////////////////////////////////////////////

void WrappedDevice::retain(ANARIObject object)
{
  if (handleIsDevice(object))
    return; // the data-parallel device keeps this one
  {
    std::lock_guard lock(m_mutex);
    auto it = m_handles.find(object);
    if (it != m_handles.end())
      it->second.references++;
  }
  if (admits(object, "anariRetain"))
    inner()->retain(object);
}

void WrappedDevice::release(ANARIObject object)
{
  if (handleIsDevice(object) || !admits(object, "anariRelease"))
    return;
  {
    // The application's last reference gone: so is what this device kept
    // (renderers' backgrounds stay: a frame may still render with one).
    std::lock_guard lock(m_mutex);
    auto it = m_handles.find(object);
    if (it != m_handles.end() && --it->second.references <= 0) {
      m_handles.erase(it);
      m_frames.erase(object);
    }
  }
  inner()->release(object);
}

// Parameters the wrapped device sees otherwise ///////////////////////////////

void WrappedDevice::setParameter(
    ANARIObject object, const char *name, ANARIDataType type, const void *mem)
{
  if (handleIsDevice(object)) {
    ForwardingDevice::setParameter(object, name, type, mem);
    return;
  }
  const ANARIObject value =
      anari::isObject(type) && mem ? *(const ANARIObject *)mem : nullptr;
  if (!admits(object, "anariSetParameter")
      || (value && !admits(value, "anariSetParameter (its value)")))
    return;
  if (!setKeptParameter(object, name ? name : "", type, mem))
    inner()->setParameter(object, name, type, mem);
}

bool WrappedDevice::setKeptParameter(ANARIObject object,
    const std::string &name,
    ANARIDataType type,
    const void *mem)
{
  std::lock_guard lock(m_mutex);
  auto renderer = m_renderers.find(object);
  if (renderer != m_renderers.end() && name == "background") {
    float4 &background = renderer->second.stagedBackground;
    if (type == ANARI_FLOAT32_VEC4 && mem) {
      std::memcpy(&background, mem, sizeof(float4));
      return true;
    }
    if (type == ANARI_FLOAT32_VEC3 && mem) {
      std::memcpy(&background, mem, 3 * sizeof(float));
      background.w = 1.f;
      return true;
    }
    // An image (or a wrong type, for the wrapped device to report): every
    // process renders it; nothing is added under the composite.
    background = kTransparent;
    return false;
  }
  auto frame = m_frames.find(object);
  if (frame == m_frames.end())
    return false;
  return setKeptFrameParameter(frame->second.staged, object, name, type, mem);
}

bool WrappedDevice::setKeptFrameParameter(FrameParameters &p,
    ANARIObject frame,
    const std::string &name,
    ANARIDataType type,
    const void *mem)
{
  const ANARIObject value =
      anari::isObject(type) && mem ? *(const ANARIObject *)mem : nullptr;
  for (int c = 0; c < kChannelCount; c++) {
    if (name != kChannelNames[c])
      continue;
    const ANARIDataType channelType = type == ANARI_DATA_TYPE && mem
                                          ? *(const ANARIDataType *)mem
                                          : ANARI_UNKNOWN;
    if (c >= 2) {
      // The others the wrapped frame renders in the application's type.
      p.channelTypes[c] = channelType;
      return false;
    }
    // Color and depth stay linear float on the wrapped frame; rank 0
    // converts the composite to the application's type.
    const bool valid = c == 0 ? isValidColorFormat(channelType)
                              : isValidDepthFormat(channelType);
    if (!valid) {
      m_report(frame,
          ANARI_FRAME,
          ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_ARGUMENT,
          std::string("anariSetParameter: frame parameter '") + name
              + "' must be a DATA_TYPE naming a " + (c == 0 ? "color" : "depth")
              + " pixel type (got "
              + anari::toString(type == ANARI_DATA_TYPE ? channelType : type)
              + "); it is ignored");
      return true;
    }
    p.channelTypes[c] = channelType;
    return true;
  }
  if (name == "size") {
    uint32_t size[2] = {0, 0};
    if (type == ANARI_UINT32_VEC2 && mem)
      std::memcpy(size, mem, sizeof(size));
    p.width = size[0];
    p.height = size[1];
  } else if (name == "renderer") {
    p.renderer = type == ANARI_RENDERER ? value : nullptr;
  } else if (name == "world") {
    p.world = type == ANARI_WORLD && value;
  } else if (name == "camera") {
    p.camera = type == ANARI_CAMERA && value;
  }
  return false;
}

void WrappedDevice::unsetParameter(ANARIObject object, const char *name)
{
  if (handleIsDevice(object)) {
    ForwardingDevice::unsetParameter(object, name);
    return;
  }
  if (admits(object, "anariUnsetParameter")
      && !unsetKeptParameter(object, name ? name : ""))
    inner()->unsetParameter(object, name);
}

bool WrappedDevice::unsetKeptParameter(
    ANARIObject object, const std::string &name)
{
  std::lock_guard lock(m_mutex);
  auto renderer = m_renderers.find(object);
  if (renderer != m_renderers.end() && name == "background") {
    renderer->second.stagedBackground = kDefaultBackground;
    clearBackground(object);
    return true;
  }
  auto frame = m_frames.find(object);
  if (frame == m_frames.end())
    return false;
  FrameParameters &p = frame->second.staged;
  for (int c = 0; c < kChannelCount; c++) {
    if (name == kChannelNames[c]) {
      p.channelTypes[c] = ANARI_UNKNOWN;
      return c < 2; // the wrapped frame keeps linear color and depth
    }
  }
  if (name == "size")
    p.width = p.height = 0;
  else if (name == "renderer")
    p.renderer = nullptr;
  else if (name == "world")
    p.world = false;
  else if (name == "camera")
    p.camera = false;
  return false;
}

void WrappedDevice::unsetAllParameters(ANARIObject object)
{
  if (handleIsDevice(object)) {
    ForwardingDevice::unsetAllParameters(object);
    return;
  }
  if (!admits(object, "anariUnsetAllParameters"))
    return;
  inner()->unsetAllParameters(object);
  std::lock_guard lock(m_mutex);
  auto renderer = m_renderers.find(object);
  if (renderer != m_renderers.end()) {
    renderer->second.stagedBackground = kDefaultBackground;
    clearBackground(object);
  }
  auto frame = m_frames.find(object);
  if (frame != m_frames.end()) {
    frame->second.staged = {};
    setLinearChannels(object);
  }
}

void WrappedDevice::commitParameters(ANARIObject object)
{
  if (handleIsDevice(object)) {
    ForwardingDevice::commitParameters(object);
    return;
  }
  {
    std::lock_guard lock(m_mutex);
    auto renderer = m_renderers.find(object);
    if (renderer != m_renderers.end())
      renderer->second.background = renderer->second.stagedBackground;
    auto frame = m_frames.find(object);
    if (frame != m_frames.end())
      frame->second.committed = frame->second.staged;
  }
  if (admits(object, "anariCommitParameters"))
    inner()->commitParameters(object);
}

// The local renderer /////////////////////////////////////////////////////////

anari::DeviceImpl &WrappedDevice::device()
{
  return *this;
}

std::string WrappedDevice::description() const
{
  return "library '" + m_library->name() + "'";
}

bool WrappedDevice::renders(RenderMode mode) const
{
  return mode == RenderMode::Composite;
}

bool WrappedDevice::rendersApplicationPixels() const
{
  return false;
}

ANARIDataType WrappedDevice::typeOf(ANARIObject handle)
{
  std::lock_guard lock(m_mutex);
  auto it = m_handles.find(handle);
  return it != m_handles.end() ? it->second.type : ANARI_UNKNOWN;
}

void WrappedDevice::setThreads(int) {}

bool WrappedDevice::describe(ANARIFrame frame, RenderMode, FrameDescriptor &d)
{
  std::lock_guard lock(m_mutex);
  auto it = m_frames.find(frame);
  if (it == m_frames.end())
    return false;
  const FrameParameters &p = it->second.committed;
  d.width = p.width;
  d.height = p.height;
  d.valid = p.world && p.camera && p.renderer && p.width && p.height ? 1 : 0;
  for (int c = 0; c < kChannelCount; c++)
    d.channelTypes[c] = p.channelTypes[c];
  auto renderer = m_renderers.find(p.renderer);
  if (renderer != m_renderers.end()) {
    const std::string &subtype = renderer->second.subtype;
    std::memcpy(d.renderer,
        subtype.data(),
        std::min(subtype.size(), sizeof(d.renderer) - 1));
  }
  return true;
}

ANARIDataType WrappedDevice::channelType(ANARIFrame frame, int channel)
{
  std::lock_guard lock(m_mutex);
  auto it = m_frames.find(frame);
  return it != m_frames.end() ? it->second.committed.channelTypes[channel]
                              : ANARI_UNKNOWN;
}

bool WrappedDevice::denoises(ANARIFrame)
{
  return false;
}

void WrappedDevice::renderAlone(ANARIFrame frame)
{
  // The wrapped device reports what the frame lacks.
  if (!admits(frame, "anariRenderFrame"))
    return;
  inner()->renderFrame(frame);
  inner()->frameReady(frame, ANARI_WAIT);
}

template <typename Pixel>
void WrappedDevice::readLinear(ANARIFrame frame,
    const char *channel,
    ANARIDataType want,
    const FrameParameters &p,
    std::vector<Pixel> &to)
{
  to.clear();
  uint32_t w = 0, h = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const void *mapped = inner()->frameBufferMap(frame, channel, &w, &h, &type);
  if (!mapped)
    return;
  if (type == want && w == p.width && h == p.height) {
    to.assign(
        (const Pixel *)mapped, (const Pixel *)mapped + size_t(w) * size_t(h));
  }
  inner()->frameBufferUnmap(frame, channel);
}

LinearImage WrappedDevice::renderForCompositing(
    ANARIFrame frame, MPI_Comm, uint64_t &)
{
  FrameParameters p;
  {
    std::lock_guard lock(m_mutex);
    p = m_frames[frame].committed;
  }
  inner()->renderFrame(frame);
  inner()->frameReady(frame, ANARI_WAIT);
  // This process's linear color and depth, as the wrapped frame rendered
  // them (nothing, when it gave other types or sizes).
  readLinear(frame, "channel.color", ANARI_FLOAT32_VEC4, p, m_color);
  readLinear(frame, "channel.depth", ANARI_FLOAT32, p, m_depth);
  if (m_color.empty() || m_depth.empty()) {
    m_report(frame,
        ANARI_FRAME,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: library '" + m_library->name()
            + "' gave no FLOAT32_VEC4 channel.color and FLOAT32"
              " channel.depth of the frame's size; this process's pixels"
              " are left out");
    m_color.clear();
    m_depth.clear();
  }
  return {&m_color, &m_depth};
}

LocalRenderer::BackgroundAt WrappedDevice::backgroundOf(
    ANARIFrame frame, uint32_t, uint32_t)
{
  float4 background = kDefaultBackground;
  {
    std::lock_guard lock(m_mutex);
    auto it = m_frames.find(frame);
    auto renderer = it != m_frames.end()
                        ? m_renderers.find(it->second.committed.renderer)
                        : m_renderers.end();
    if (renderer != m_renderers.end())
      background = renderer->second.background;
  }
  return [background](uint32_t, uint32_t) {
    return background;
  };
}

} // namespace prism::mpi
