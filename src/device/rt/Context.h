// The Embree device of one prism device. Embree's errors and memory
// warnings go to the prism device's status callback.
#pragma once

#include <atomic>
#include <cstdint>
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
  // What Embree holds now (BVHs, its copies and build scratch) and the
  // most it has held, in bytes, from its memory monitor.
  int64_t embreeBytes() const
  {
    return m_bytes.load(std::memory_order_relaxed);
  }
  int64_t embreePeakBytes() const
  {
    return m_peakBytes.load(std::memory_order_relaxed);
  }
  // Called by Embree's memory monitor for every allocation and release.
  void countBytes(int64_t change);

  // The Embree build quality of BVHs built from now on (the device's
  // bvhQuality parameter).
  enum class BuildQuality { Low, Medium, High };
  void setBuildQuality(BuildQuality quality)
  {
    m_buildQuality.store(quality, std::memory_order_relaxed);
  }
  BuildQuality buildQuality() const
  {
    return m_buildQuality.load(std::memory_order_relaxed);
  }
  // "low", "medium" or "high"; false (nothing set) for other names.
  bool setBuildQuality(const std::string &name);

 private:
  std::atomic<int64_t> m_bytes{0};
  std::atomic<int64_t> m_peakBytes{0};
  // Medium: Embree's default; on the big-scene benchmark high costs more
  // build time for no smaller BVH (docs/performance.md).
  std::atomic<BuildQuality> m_buildQuality{BuildQuality::Medium};
  ErrorSink m_onError;
  RTCDeviceTy *m_device{nullptr};
};

} // namespace prism::rt
