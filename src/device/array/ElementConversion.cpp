// Element decoding: one switch per call picks a layout (component type,
// encoding, count); the per-element loops are templates over that layout so
// the common cases compile to straight, vectorisable code.
#include "ElementConversion.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace prism {

float srgbToLinear(float encoded)
{
  if (encoded <= 0.04045f)
    return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float linear)
{
  if (linear <= 0.0031308f)
    return 12.92f * linear;
  return 1.055f * std::pow(linear, 1.f / 2.4f) - 0.055f;
}

// Generated from the EOTF in 60-digit decimal arithmetic and rounded once to
// the nearest float, so the table is exact and identical on every platform
// (ElementConversionTest checks it against the formula).
// clang-format off
const std::array<float, 256> kSrgb8ToLinear = {
    0.0f, 0.000303526991f, 0.000607053982f, 0.000910580973f,
    0.00121410796f, 0.00151763496f, 0.00182116195f, 0.00212468882f,
    0.00242821593f, 0.0027317428f, 0.00303526991f, 0.00334653584f,
    0.00367650739f, 0.00402471703f, 0.00439144205f, 0.00477695325f,
    0.00518151652f, 0.00560539169f, 0.00604883302f, 0.00651209056f,
    0.00699541019f, 0.00749903219f, 0.00802319311f, 0.00856812578f,
    0.00913405884f, 0.00972121768f, 0.010329823f, 0.0109600937f,
    0.0116122449f, 0.012286488f, 0.0129830325f, 0.0137020834f,
    0.0144438436f, 0.0152085144f, 0.0159962941f, 0.0168073755f,
    0.0176419541f, 0.01850022f, 0.0193823613f, 0.0202885624f,
    0.0212190095f, 0.0221738853f, 0.0231533665f, 0.0241576321f,
    0.0251868591f, 0.0262412224f, 0.0273208916f, 0.02842604f,
    0.0295568351f, 0.0307134446f, 0.0318960324f, 0.0331047662f,
    0.0343398079f, 0.0356013142f, 0.0368894488f, 0.0382043719f,
    0.0395462364f, 0.0409151986f, 0.0423114114f, 0.043735031f,
    0.045186203f, 0.0466650873f, 0.0481718257f, 0.0497065671f,
    0.0512694567f, 0.0528606474f, 0.054480277f, 0.0561284907f,
    0.0578054301f, 0.0595112368f, 0.0612460524f, 0.0630100146f,
    0.064803265f, 0.0666259378f, 0.0684781671f, 0.0703600943f,
    0.0722718537f, 0.0742135718f, 0.0761853829f, 0.078187421f,
    0.0802198201f, 0.0822827071f, 0.0843762085f, 0.0865004584f,
    0.0886555836f, 0.0908417106f, 0.0930589661f, 0.0953074694f,
    0.097587347f, 0.0998987257f, 0.102241732f, 0.104616486f,
    0.107023105f, 0.10946171f, 0.111932427f, 0.114435375f,
    0.116970666f, 0.119538426f, 0.122138776f, 0.124771819f,
    0.127437681f, 0.130136475f, 0.13286832f, 0.135633335f,
    0.138431609f, 0.141263291f, 0.144128472f, 0.147027269f,
    0.149959788f, 0.152926147f, 0.155926466f, 0.158960834f,
    0.162029371f, 0.165132195f, 0.168269396f, 0.171441108f,
    0.174647406f, 0.177888423f, 0.18116425f, 0.18447499f,
    0.187820777f, 0.191201687f, 0.194617838f, 0.198069319f,
    0.20155625f, 0.205078736f, 0.208636865f, 0.212230757f,
    0.215860501f, 0.219526201f, 0.223227963f, 0.226965874f,
    0.230740055f, 0.23455058f, 0.238397568f, 0.242281124f,
    0.246201321f, 0.25015828f, 0.254152089f, 0.258182853f,
    0.262250662f, 0.266355604f, 0.270497799f, 0.274677306f,
    0.278894275f, 0.283148736f, 0.287440836f, 0.291770637f,
    0.296138257f, 0.300543785f, 0.304987311f, 0.309468925f,
    0.313988715f, 0.318546772f, 0.323143214f, 0.327778101f,
    0.332451522f, 0.337163627f, 0.341914415f, 0.346704066f,
    0.351532608f, 0.356400132f, 0.361306787f, 0.366252601f,
    0.371237695f, 0.376262128f, 0.38132602f, 0.386429429f,
    0.391572475f, 0.396755219f, 0.401977777f, 0.407240212f,
    0.412542611f, 0.417885065f, 0.423267663f, 0.428690493f,
    0.434153646f, 0.439657182f, 0.445201188f, 0.450785786f,
    0.456411034f, 0.462076992f, 0.467783809f, 0.473531485f,
    0.479320168f, 0.48514995f, 0.491020858f, 0.496932983f,
    0.502886474f, 0.50888133f, 0.514917672f, 0.520995557f,
    0.527115107f, 0.533276379f, 0.539479494f, 0.545724452f,
    0.55201143f, 0.558340371f, 0.564711511f, 0.571124852f,
    0.577580452f, 0.584078431f, 0.590618849f, 0.597201765f,
    0.603827357f, 0.610495567f, 0.617206573f, 0.623960376f,
    0.630757153f, 0.637596846f, 0.644479692f, 0.651405632f,
    0.658374846f, 0.665387273f, 0.672443151f, 0.679542482f,
    0.686685324f, 0.693871737f, 0.701101899f, 0.708375752f,
    0.715693474f, 0.723055124f, 0.730460763f, 0.73791039f,
    0.745404184f, 0.752942204f, 0.760524511f, 0.768151164f,
    0.775822222f, 0.783537805f, 0.791297913f, 0.799102724f,
    0.806952238f, 0.814846575f, 0.822785735f, 0.830769897f,
    0.838799f, 0.846873224f, 0.854992628f, 0.863157213f,
    0.871367097f, 0.8796224f, 0.887923121f, 0.896269381f,
    0.904661179f, 0.913098633f, 0.921581864f, 0.930110872f,
    0.938685715f, 0.947306514f, 0.955973327f, 0.964686275f,
    0.973445296f, 0.982250571f, 0.991102099f, 1.0f};
// clang-format on

namespace {

// How the stored components of an element map to float.
enum class Encoding {
  Integer, // INT*/UINT*: by value
  Unorm,   // UFIXED*: v / max
  Snorm,   // FIXED*: max(v / max, -1)
  Half,    // FLOAT16
  Float,   // FLOAT32/FLOAT64
  Srgb     // UFIXED8_*_SRGB: colour through the EOTF, alpha as Unorm
};

template <typename T, Encoding E, int N>
struct Layout
{
  using Component = T;
  static constexpr Encoding kEncoding = E;
  static constexpr int kComponents = N;
  static constexpr size_t kBytes = sizeof(T) * N;
};

template <typename T, Encoding E, typename Fn>
bool visitSized(ANARIDataType type, Fn &fn)
{
  switch (anari::componentsOf(type)) {
  case 1:
    return fn(Layout<T, E, 1>{});
  case 2:
    return fn(Layout<T, E, 2>{});
  case 3:
    return fn(Layout<T, E, 3>{});
  case 4:
    return fn(Layout<T, E, 4>{});
  default:
    return false;
  }
}

// Calls fn(Layout<...>{}) for every numeric element type and returns its
// result; false for every other type.
template <typename Fn>
bool visitLayout(ANARIDataType type, Fn &&fn)
{
  using E = Encoding;
  switch (int(type)) {
  case ANARI_INT8:
  case ANARI_INT8_VEC2:
  case ANARI_INT8_VEC3:
  case ANARI_INT8_VEC4:
    return visitSized<int8_t, E::Integer>(type, fn);
  case ANARI_UINT8:
  case ANARI_UINT8_VEC2:
  case ANARI_UINT8_VEC3:
  case ANARI_UINT8_VEC4:
    return visitSized<uint8_t, E::Integer>(type, fn);
  case ANARI_INT16:
  case ANARI_INT16_VEC2:
  case ANARI_INT16_VEC3:
  case ANARI_INT16_VEC4:
    return visitSized<int16_t, E::Integer>(type, fn);
  case ANARI_UINT16:
  case ANARI_UINT16_VEC2:
  case ANARI_UINT16_VEC3:
  case ANARI_UINT16_VEC4:
    return visitSized<uint16_t, E::Integer>(type, fn);
  case ANARI_INT32:
  case ANARI_INT32_VEC2:
  case ANARI_INT32_VEC3:
  case ANARI_INT32_VEC4:
    return visitSized<int32_t, E::Integer>(type, fn);
  case ANARI_UINT32:
  case ANARI_UINT32_VEC2:
  case ANARI_UINT32_VEC3:
  case ANARI_UINT32_VEC4:
    return visitSized<uint32_t, E::Integer>(type, fn);
  case ANARI_INT64:
  case ANARI_INT64_VEC2:
  case ANARI_INT64_VEC3:
  case ANARI_INT64_VEC4:
    return visitSized<int64_t, E::Integer>(type, fn);
  case ANARI_UINT64:
  case ANARI_UINT64_VEC2:
  case ANARI_UINT64_VEC3:
  case ANARI_UINT64_VEC4:
    return visitSized<uint64_t, E::Integer>(type, fn);
  case ANARI_FIXED8:
  case ANARI_FIXED8_VEC2:
  case ANARI_FIXED8_VEC3:
  case ANARI_FIXED8_VEC4:
    return visitSized<int8_t, E::Snorm>(type, fn);
  case ANARI_UFIXED8:
  case ANARI_UFIXED8_VEC2:
  case ANARI_UFIXED8_VEC3:
  case ANARI_UFIXED8_VEC4:
    return visitSized<uint8_t, E::Unorm>(type, fn);
  case ANARI_FIXED16:
  case ANARI_FIXED16_VEC2:
  case ANARI_FIXED16_VEC3:
  case ANARI_FIXED16_VEC4:
    return visitSized<int16_t, E::Snorm>(type, fn);
  case ANARI_UFIXED16:
  case ANARI_UFIXED16_VEC2:
  case ANARI_UFIXED16_VEC3:
  case ANARI_UFIXED16_VEC4:
    return visitSized<uint16_t, E::Unorm>(type, fn);
  case ANARI_FIXED32:
  case ANARI_FIXED32_VEC2:
  case ANARI_FIXED32_VEC3:
  case ANARI_FIXED32_VEC4:
    return visitSized<int32_t, E::Snorm>(type, fn);
  case ANARI_UFIXED32:
  case ANARI_UFIXED32_VEC2:
  case ANARI_UFIXED32_VEC3:
  case ANARI_UFIXED32_VEC4:
    return visitSized<uint32_t, E::Unorm>(type, fn);
  case ANARI_FIXED64:
  case ANARI_FIXED64_VEC2:
  case ANARI_FIXED64_VEC3:
  case ANARI_FIXED64_VEC4:
    return visitSized<int64_t, E::Snorm>(type, fn);
  case ANARI_UFIXED64:
  case ANARI_UFIXED64_VEC2:
  case ANARI_UFIXED64_VEC3:
  case ANARI_UFIXED64_VEC4:
    return visitSized<uint64_t, E::Unorm>(type, fn);
  case ANARI_FLOAT16:
  case ANARI_FLOAT16_VEC2:
  case ANARI_FLOAT16_VEC3:
  case ANARI_FLOAT16_VEC4:
    return visitSized<uint16_t, E::Half>(type, fn);
  case ANARI_FLOAT32:
  case ANARI_FLOAT32_VEC2:
  case ANARI_FLOAT32_VEC3:
  case ANARI_FLOAT32_VEC4:
    return visitSized<float, E::Float>(type, fn);
  case ANARI_FLOAT64:
  case ANARI_FLOAT64_VEC2:
  case ANARI_FLOAT64_VEC3:
  case ANARI_FLOAT64_VEC4:
    return visitSized<double, E::Float>(type, fn);
  case ANARI_UFIXED8_R_SRGB:
  case ANARI_UFIXED8_RA_SRGB:
  case ANARI_UFIXED8_RGB_SRGB:
  case ANARI_UFIXED8_RGBA_SRGB:
    return visitSized<uint8_t, E::Srgb>(type, fn);
  default:
    return false;
  }
}

template <typename T, Encoding E>
inline float decodeComponent(T v)
{
  if constexpr (E == Encoding::Half) {
    return halfToFloat(v);
  } else if constexpr (E == Encoding::Unorm || E == Encoding::Snorm) {
    constexpr T kMax = std::numeric_limits<T>::max();
    if constexpr (sizeof(T) <= 2) {
      // Both operands are exact floats, so one correctly rounded division.
      const float f = float(v) / float(kMax);
      return E == Encoding::Snorm ? std::max(f, -1.f) : f;
    } else {
      // 32/64-bit values need double to keep the quotient accurate.
      const double d = double(v) / double(kMax);
      return float(E == Encoding::Snorm ? std::max(d, -1.0) : d);
    }
  } else {
    return float(v);
  }
}

template <typename L>
inline float4 decodeElement(const std::byte *p)
{
  using T = typename L::Component;
  constexpr Encoding E = L::kEncoding;
  constexpr int N = L::kComponents;
  T c[N];
  std::memcpy(c, p, sizeof(c));
  float4 r{0.f, 0.f, 0.f, 1.f};
  if constexpr (E == Encoding::Srgb) {
    constexpr auto alpha = decodeComponent<uint8_t, Encoding::Unorm>;
    r.x = srgb8ToLinear(c[0]);
    if constexpr (N == 2)
      r.w = alpha(c[1]);
    if constexpr (N >= 3) {
      r.y = srgb8ToLinear(c[1]);
      r.z = srgb8ToLinear(c[2]);
    }
    if constexpr (N == 4)
      r.w = alpha(c[3]);
  } else {
    r.x = decodeComponent<T, E>(c[0]);
    if constexpr (N >= 2)
      r.y = decodeComponent<T, E>(c[1]);
    if constexpr (N >= 3)
      r.z = decodeComponent<T, E>(c[2]);
    if constexpr (N >= 4)
      r.w = decodeComponent<T, E>(c[3]);
  }
  return r;
}

template <typename Out>
constexpr int kOutComponents = 0;
template <>
constexpr int kOutComponents<float> = 1;
template <>
constexpr int kOutComponents<float2> = 2;
template <>
constexpr int kOutComponents<float3> = 3;
template <>
constexpr int kOutComponents<float4> = 4;

template <typename Out>
inline Out leading(float4 v)
{
  if constexpr (std::is_same_v<Out, float>)
    return v.x;
  else if constexpr (std::is_same_v<Out, float2>)
    return {v.x, v.y};
  else if constexpr (std::is_same_v<Out, float3>)
    return {v.x, v.y, v.z};
  else
    return v;
}

// FLOAT32 data already in the output's shape is a plain copy when packed.
template <typename L, typename Out>
constexpr bool kIsPlainCopy =
    L::kEncoding
    == Encoding::Float &&std::is_same_v<typename L::Component, float>
        &&L::kComponents == kOutComponents<Out>;

template <typename L, typename Out>
void convertLoop(const std::byte *__restrict src,
    size_t count,
    size_t stride,
    Out *__restrict out)
{
  if (stride == L::kBytes) {
    if constexpr (kIsPlainCopy<L, Out>) {
      std::memcpy(out, src, count * sizeof(Out));
    } else {
      // A constant stride lets the compiler vectorise this loop.
      for (size_t i = 0; i < count; i++)
        out[i] = leading<Out>(decodeElement<L>(src + i * L::kBytes));
    }
  } else {
    for (size_t i = 0; i < count; i++)
      out[i] = leading<Out>(decodeElement<L>(src + i * stride));
  }
}

template <typename Out>
void convertToFloats(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    Out *out)
{
  const auto *src = static_cast<const std::byte *>(begin);
  const size_t stride = strideBytes ? strideBytes : anari::sizeOf(type);
  const bool known = visitLayout(type, [&](auto layout) {
    convertLoop<decltype(layout), Out>(src, count, stride, out);
    return true;
  });
  if (!known)
    std::fill_n(out, count, leading<Out>(float4{0.f, 0.f, 0.f, 1.f}));
}

template <typename L, typename U>
void copyComponents(const std::byte *__restrict src,
    size_t count,
    size_t stride,
    U *__restrict out)
{
  using T = typename L::Component;
  constexpr int N = L::kComponents;
  if constexpr (std::is_same_v<T, U>) {
    if (stride == L::kBytes) {
      std::memcpy(out, src, count * L::kBytes);
      return;
    }
  }
  for (size_t i = 0; i < count; i++) {
    T c[N];
    std::memcpy(c, src + i * stride, sizeof(c));
    for (int k = 0; k < N; k++)
      out[i * N + k] = U(c[k]);
  }
}

template <typename U>
void convertToUints(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    U *out)
{
  const auto *src = static_cast<const std::byte *>(begin);
  const size_t stride = strideBytes ? strideBytes : anari::sizeOf(type);
  const bool known = visitLayout(type, [&](auto layout) {
    using L = decltype(layout);
    if constexpr (L::kEncoding == Encoding::Integer) {
      copyComponents<L, U>(src, count, stride, out);
      return true;
    } else {
      return false;
    }
  });
  if (!known)
    std::fill_n(out, count * size_t(anari::componentsOf(type)), U(0));
}

} // namespace

bool canReadAsFloat4(ANARIDataType type)
{
  return visitLayout(type, [](auto) { return true; });
}

float4 readAsFloat4(ANARIDataType type, const void *element)
{
  float4 result{0.f, 0.f, 0.f, 1.f};
  const auto *p = static_cast<const std::byte *>(element);
  visitLayout(type, [&](auto layout) {
    result = decodeElement<decltype(layout)>(p);
    return true;
  });
  return result;
}

void convertToFloat4(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    float4 *out)
{
  convertToFloats(type, begin, count, strideBytes, out);
}

void convertToFloat3(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    float3 *out)
{
  convertToFloats(type, begin, count, strideBytes, out);
}

void convertToFloat2(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    float2 *out)
{
  convertToFloats(type, begin, count, strideBytes, out);
}

void convertToFloat(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    float *out)
{
  convertToFloats(type, begin, count, strideBytes, out);
}

bool canReadAsUint(ANARIDataType type)
{
  return visitLayout(type, [](auto layout) {
    return decltype(layout)::kEncoding == Encoding::Integer;
  });
}

void convertToUint32(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    uint32_t *out)
{
  convertToUints(type, begin, count, strideBytes, out);
}

void convertToUint64(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    uint64_t *out)
{
  convertToUints(type, begin, count, strideBytes, out);
}

} // namespace prism
