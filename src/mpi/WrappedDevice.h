// wrappedLibrary / wrappedDevice: another ANARI library's device as the
// local renderer of prism_mpi (Wald et al. 2024, section 5.1). Every call
// is forwarded with that device's handles, on handles the application holds
// only (another library may not check them). Its frames always render
// linear float color and depth, and its renderers a transparent background;
// what the application set instead (channel types, size, background) is
// kept here, for rank 0 to assemble the composite with.
#pragma once

#include "ForwardingDevice.h"
#include "LoadedLibrary.h"
#include "LocalRenderer.h"

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace prism::mpi {

class WrappedDevice : public ForwardingDevice, public LocalRenderer
{
 public:
  // How this device reports to the application.
  using Report = std::function<void(ANARIObject source,
      ANARIDataType sourceType,
      ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &message)>;
  // The device of `subtype` of the library `spec` names, its messages sent
  // to `status`; NULL (and `error` says why) if there is none.
  static std::unique_ptr<WrappedDevice> load(const std::string &spec,
      const std::string &subtype,
      ANARIStatusCallback status,
      const void *statusUserPtr,
      Report report,
      std::string &error);
  ~WrappedDevice() override;

  // ForwardingDevice: calls on live handles the application holds only
  // (admits); these also keep what compositing needs.
  ANARIObject newObject(const char *objectType, const char *subtype) override;
  void retain(ANARIObject object) override;
  void release(ANARIObject object) override;
  void setParameter(ANARIObject object,
      const char *name,
      ANARIDataType type,
      const void *mem) override;
  void commitParameters(ANARIObject object) override;
  void unsetParameter(ANARIObject object, const char *name) override;
  void unsetAllParameters(ANARIObject object) override;

  // LocalRenderer: composite mode only.
  anari::DeviceImpl &device() override;
  std::string description() const override;
  bool renders(RenderMode mode) const override;
  bool rendersApplicationPixels() const override;
  ANARIDataType typeOf(ANARIObject handle) override;
  void setThreads(int threads) override;
  bool describe(ANARIFrame frame, RenderMode mode, FrameDescriptor &d) override;
  ANARIDataType channelType(ANARIFrame frame, int channel) override;
  bool denoises(ANARIFrame frame) override;
  void renderAlone(ANARIFrame frame) override;
  LinearImage renderForCompositing(
      ANARIFrame frame, MPI_Comm communicator, uint64_t &bytesSent) override;
  BackgroundAt backgroundOf(
      ANARIFrame frame, uint32_t width, uint32_t height) override;

 protected:
  // Whether `object` is a live handle the application holds; if not,
  // reports it for `function`.
  bool admits(ANARIObject object, const char *function) override;
  ANARIObject newObjectOf(ANARIDataType type, const char *subtype) override;
  ANARIArray newArrayOf(ANARIDataType arrayType,
      const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *userData,
      ANARIDataType elementType,
      const uint64_t items[3]) override;

 private:
  WrappedDevice(std::shared_ptr<frontend::LoadedLibrary> library,
      anari::DeviceImpl *device,
      Report report);

  // What the application set on a frame that the wrapped frame sees
  // otherwise (it always renders linear color and depth).
  struct FrameParameters
  {
    uint32_t width{0};
    uint32_t height{0};
    // The application's ANARIDataType of each of kChannelNames.
    ANARIDataType channelTypes[kChannelCount]{};
    ANARIObject renderer{nullptr};
    bool world{false};
    bool camera{false};
  };
  struct FrameRecord
  {
    FrameParameters staged;
    FrameParameters committed;
  };
  // A renderer renders with a transparent background; rank 0 adds the
  // application's under the composite.
  struct RendererRecord
  {
    std::string subtype;
    float4 stagedBackground{0.f, 0.f, 0.f, 1.f};
    float4 background{0.f, 0.f, 0.f, 1.f}; // committed
  };
  // A handle the wrapped device gave the application, with its type and
  // the application's references.
  struct Handle
  {
    ANARIDataType type{ANARI_OBJECT};
    int64_t references{1};
  };

  ANARIObject created(ANARIObject handle, ANARIDataType type);
  void setLinearChannels(ANARIObject frame);
  void clearBackground(ANARIObject renderer);
  // Frame and renderer parameters the wrapped device sees otherwise;
  // true when the call is done.
  bool setKeptParameter(ANARIObject object,
      const std::string &name,
      ANARIDataType type,
      const void *mem);
  bool setKeptFrameParameter(FrameParameters &p,
      ANARIObject frame,
      const std::string &name,
      ANARIDataType type,
      const void *mem);
  bool unsetKeptParameter(ANARIObject object, const std::string &name);
  // Reads a channel of the wrapped frame rendered as `want` into `to`
  // (left empty when it has another type or size).
  template <typename Pixel>
  void readLinear(ANARIFrame frame,
      const char *channel,
      ANARIDataType want,
      const FrameParameters &p,
      std::vector<Pixel> &to);

  std::shared_ptr<frontend::LoadedLibrary> m_library;
  Report m_report;
  std::mutex m_mutex; // guards the maps below
  std::map<ANARIObject, Handle> m_handles;
  std::map<ANARIObject, FrameRecord> m_frames;
  std::map<ANARIObject, RendererRecord> m_renderers;
  // This process's pixels of the last render for compositing.
  std::vector<float4> m_color;
  std::vector<float> m_depth;
};

} // namespace prism::mpi
