// What image1D, image2D and image3D share (spec 5.10.1-3): the image decoded
// once to linear float4 texels, and Vulkan's nearest/linear filtering and
// wrap modes applied per dimension.
#pragma once

#include "Sampler.h"

#include "../array/Array.h"

#include <array>
#include <cstdint>
#include <vector>

namespace prism {

enum class Filter : uint8_t {
  Nearest,
  Linear,
};

enum class WrapMode : uint8_t {
  ClampToEdge,
  Repeat,
  MirrorRepeat,
  ClampToBorder, // KHR_SAMPLER_IMAGExD_CLAMP_TO_BORDER
};

class ImageSampler : public Sampler
{
 public:
  float4 sample(const AttributeValues &attributes) const override;
  // The filtered image at normalised texture coordinates (x, y, z), before
  // outTransform; (0, 0, 0, 1) while the sampler is invalid.
  float4 lookup(float4 coordinates) const;

  void finalize() override;
  bool isValid() const override
  {
    return !m_texels.empty();
  }
  void dropReferences() override;

  Filter filter() const
  {
    return m_filter;
  }
  WrapMode wrapMode(int dimension) const
  {
    return m_wrap[dimension];
  }

 protected:
  // `wrapParameters` names the wrap mode parameter of each dimension (the
  // JSON calls it "wrapMode" for image1D, "wrapMode1".. otherwise).
  ImageSampler(DeviceState &device,
      const std::string &subtype,
      int dimensions,
      std::array<const char *, 3> wrapParameters,
      bool (*acceptsElementType)(ANARIDataType));

  void commitParameters() override;

 private:
  // One dimension's texels to blend: index[1] weighs `weight`, index[0] the
  // rest; -1 stands for the border colour.
  struct Tap
  {
    int64_t index[2];
    float weight;
  };
  Tap tapAt(float coordinate, int dimension) const;
  // Blends dimensions 0..`dimension` of the texels at `offset`, highest
  // dimension first.
  float4 blend(
      const Tap *taps, int dimension, uint64_t offset, bool border) const;
  WrapMode readWrapMode(const char *name);

  const int m_dimensions;
  const std::array<const char *, 3> m_wrapParameters;
  bool (*const m_acceptsElementType)(ANARIDataType);

  Attribute m_inAttribute{Attribute::Attribute0};
  mat4 m_inTransform{kIdentityMat4};
  float4 m_inOffset{0.f, 0.f, 0.f, 0.f};
  Filter m_filter{Filter::Linear};
  WrapMode m_wrap[3]{
      WrapMode::ClampToEdge, WrapMode::ClampToEdge, WrapMode::ClampToEdge};
  float4 m_borderColor{0.f, 0.f, 0.f, 0.f};
  ObjectRef<Array> m_image;

  // Built by finalize(): x fastest, then y, then z.
  std::vector<float4> m_texels;
  uint64_t m_size[3]{1, 1, 1};
  uint64_t m_stride[3]{1, 1, 1}; // texels between neighbours along each axis
};

} // namespace prism
