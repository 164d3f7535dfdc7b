// Compile-time mapping from C++ types to ANARIDataType values, used by the
// C++ wrappers to infer parameter, property and array element types.
#pragma once

#include "../anari.h"
#include "../frontend/type_utility.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace anari {

namespace detail {

template <int Value>
struct DataTypeConstant
{
  static constexpr int value = Value;
};

} // namespace detail

// ANARI_UNKNOWN unless a specialization (ours or the application's) says
// otherwise; `value` stays an int as in the SDK.
template <typename T>
struct ANARITypeFor : detail::DataTypeConstant<int(ANARI_UNKNOWN)>
{};

// One specialization; ANARI_TYPEFOR_SPECIALIZATION is built from it.
#define ANARI_TYPEFOR_DETAIL_SPECIALIZE(type, anari_type)  \
  template <>                                              \
  struct ANARITypeFor<type>                                \
      : ::anari::detail::DataTypeConstant<int(anari_type)> \
  {};

// Maps `type` and `const type` (textually, so `void *` also maps
// `const void *`); use inside namespace anari, as with the SDK.
#define ANARI_TYPEFOR_SPECIALIZATION(type, anari_type) \
  ANARI_TYPEFOR_DETAIL_SPECIALIZE(type, anari_type)    \
  ANARI_TYPEFOR_DETAIL_SPECIALIZE(const type, anari_type)

// The SDK needed out-of-line definitions before C++17; here it only checks
// that `type` has been mapped.
#define ANARI_TYPEFOR_DEFINITION(type)                                    \
  static_assert(::anari::ANARITypeFor<type>::value != int(ANARI_UNKNOWN), \
      "ANARI_TYPEFOR_DEFINITION(" #type                                   \
      ") needs an ANARI_TYPEFOR_SPECIALIZATION first")

// Scalars and the C-array vectors and matrices //////////////////////////////

ANARI_TYPEFOR_SPECIALIZATION(bool, ANARI_BOOL);

ANARI_TYPEFOR_SPECIALIZATION(int8_t, ANARI_INT8);
ANARI_TYPEFOR_SPECIALIZATION(int8_t[2], ANARI_INT8_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(int8_t[3], ANARI_INT8_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(int8_t[4], ANARI_INT8_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(uint8_t, ANARI_UINT8);
ANARI_TYPEFOR_SPECIALIZATION(uint8_t[2], ANARI_UINT8_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(uint8_t[3], ANARI_UINT8_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(uint8_t[4], ANARI_UINT8_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(int16_t, ANARI_INT16);
ANARI_TYPEFOR_SPECIALIZATION(int16_t[2], ANARI_INT16_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(int16_t[3], ANARI_INT16_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(int16_t[4], ANARI_INT16_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(uint16_t, ANARI_UINT16);
ANARI_TYPEFOR_SPECIALIZATION(uint16_t[2], ANARI_UINT16_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(uint16_t[3], ANARI_UINT16_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(uint16_t[4], ANARI_UINT16_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(int32_t, ANARI_INT32);
ANARI_TYPEFOR_SPECIALIZATION(int32_t[2], ANARI_INT32_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(int32_t[3], ANARI_INT32_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(int32_t[4], ANARI_INT32_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(uint32_t, ANARI_UINT32);
ANARI_TYPEFOR_SPECIALIZATION(uint32_t[2], ANARI_UINT32_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(uint32_t[3], ANARI_UINT32_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(uint32_t[4], ANARI_UINT32_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(int64_t, ANARI_INT64);
ANARI_TYPEFOR_SPECIALIZATION(int64_t[2], ANARI_INT64_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(int64_t[3], ANARI_INT64_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(int64_t[4], ANARI_INT64_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(uint64_t, ANARI_UINT64);
ANARI_TYPEFOR_SPECIALIZATION(uint64_t[2], ANARI_UINT64_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(uint64_t[3], ANARI_UINT64_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(uint64_t[4], ANARI_UINT64_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(float, ANARI_FLOAT32);
ANARI_TYPEFOR_SPECIALIZATION(float[2], ANARI_FLOAT32_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(float[3], ANARI_FLOAT32_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(float[4], ANARI_FLOAT32_VEC4);
ANARI_TYPEFOR_SPECIALIZATION(float[12], ANARI_FLOAT32_MAT3x4);
ANARI_TYPEFOR_SPECIALIZATION(float[16], ANARI_FLOAT32_MAT4);
ANARI_TYPEFOR_SPECIALIZATION(double, ANARI_FLOAT64);
ANARI_TYPEFOR_SPECIALIZATION(double[2], ANARI_FLOAT64_VEC2);
ANARI_TYPEFOR_SPECIALIZATION(double[3], ANARI_FLOAT64_VEC3);
ANARI_TYPEFOR_SPECIALIZATION(double[4], ANARI_FLOAT64_VEC4);

// `long`/`long long` (whichever of them is not int64_t on this platform) get
// the integer type of their size; an alias that already is intN_t maps to a
// placeholder so nothing is specialized twice.
namespace detail {

template <int Tag>
struct NotAnIntegerType;

template <typename T, typename... Candidates>
constexpr bool isOneOf = (std::is_same_v<T, Candidates> || ...);

template <typename T>
constexpr bool isFixedWidthInteger = isOneOf<T,
    int8_t,
    uint8_t,
    int16_t,
    uint16_t,
    int32_t,
    uint32_t,
    int64_t,
    uint64_t>;

template <typename T, int Tag>
using UnlessFixedWidth =
    std::conditional_t<isFixedWidthInteger<T>, NotAnIntegerType<Tag>, T>;

template <typename T>
constexpr int integerTypeFor()
{
  // INT8, INT16, INT32, INT64 are 8 apart; each unsigned variant is 4 on.
  int step = 0;
  for (size_t size = sizeof(T); size > 1; size /= 2)
    ++step;
  return int(ANARI_INT8) + 8 * step + (std::is_unsigned_v<T> ? 4 : 0);
}

using LongIfDistinct = UnlessFixedWidth<long, 0>;
using ULongIfDistinct = UnlessFixedWidth<unsigned long, 1>;
using LongLongIfDistinct = UnlessFixedWidth<long long, 2>;
using ULongLongIfDistinct = UnlessFixedWidth<unsigned long long, 3>;

} // namespace detail

ANARI_TYPEFOR_SPECIALIZATION(
    detail::LongIfDistinct, detail::integerTypeFor<long>());
ANARI_TYPEFOR_SPECIALIZATION(
    detail::ULongIfDistinct, detail::integerTypeFor<unsigned long>());
ANARI_TYPEFOR_SPECIALIZATION(
    detail::LongLongIfDistinct, detail::integerTypeFor<long long>());
ANARI_TYPEFOR_SPECIALIZATION(
    detail::ULongLongIfDistinct, detail::integerTypeFor<unsigned long long>());

// Pointers, strings and callbacks ///////////////////////////////////////////

ANARI_TYPEFOR_SPECIALIZATION(void *, ANARI_VOID_POINTER);
ANARI_TYPEFOR_DETAIL_SPECIALIZE(void *const, ANARI_VOID_POINTER);
ANARI_TYPEFOR_DETAIL_SPECIALIZE(const void *const, ANARI_VOID_POINTER);

ANARI_TYPEFOR_SPECIALIZATION(char *, ANARI_STRING);
ANARI_TYPEFOR_SPECIALIZATION(char[], ANARI_STRING);
ANARI_TYPEFOR_DETAIL_SPECIALIZE(char *const, ANARI_STRING);
ANARI_TYPEFOR_DETAIL_SPECIALIZE(const char *const, ANARI_STRING);

ANARI_TYPEFOR_SPECIALIZATION(char **, ANARI_STRING_LIST);
ANARI_TYPEFOR_SPECIALIZATION(char *[], ANARI_STRING_LIST);
ANARI_TYPEFOR_DETAIL_SPECIALIZE(const char *const *, ANARI_STRING_LIST);

ANARI_TYPEFOR_SPECIALIZATION(ANARIDataType, ANARI_DATA_TYPE);

ANARI_TYPEFOR_SPECIALIZATION(ANARIStatusCallback, ANARI_STATUS_CALLBACK);
ANARI_TYPEFOR_SPECIALIZATION(ANARIMemoryDeleter, ANARI_MEMORY_DELETER);
ANARI_TYPEFOR_SPECIALIZATION(
    ANARIFrameCompletionCallback, ANARI_FRAME_COMPLETION_CALLBACK);

// Handles ///////////////////////////////////////////////////////////////////

ANARI_TYPEFOR_SPECIALIZATION(ANARILibrary, ANARI_LIBRARY);
ANARI_TYPEFOR_SPECIALIZATION(ANARIObject, ANARI_OBJECT);
ANARI_TYPEFOR_SPECIALIZATION(ANARIDevice, ANARI_DEVICE);
ANARI_TYPEFOR_SPECIALIZATION(ANARICamera, ANARI_CAMERA);
ANARI_TYPEFOR_SPECIALIZATION(ANARIArray, ANARI_ARRAY);
ANARI_TYPEFOR_SPECIALIZATION(ANARIArray1D, ANARI_ARRAY1D);
ANARI_TYPEFOR_SPECIALIZATION(ANARIArray2D, ANARI_ARRAY2D);
ANARI_TYPEFOR_SPECIALIZATION(ANARIArray3D, ANARI_ARRAY3D);
ANARI_TYPEFOR_SPECIALIZATION(ANARIFrame, ANARI_FRAME);
ANARI_TYPEFOR_SPECIALIZATION(ANARIGeometry, ANARI_GEOMETRY);
ANARI_TYPEFOR_SPECIALIZATION(ANARIGroup, ANARI_GROUP);
ANARI_TYPEFOR_SPECIALIZATION(ANARIInstance, ANARI_INSTANCE);
ANARI_TYPEFOR_SPECIALIZATION(ANARILight, ANARI_LIGHT);
ANARI_TYPEFOR_SPECIALIZATION(ANARIMaterial, ANARI_MATERIAL);
ANARI_TYPEFOR_SPECIALIZATION(ANARIRenderer, ANARI_RENDERER);
ANARI_TYPEFOR_SPECIALIZATION(ANARISampler, ANARI_SAMPLER);
ANARI_TYPEFOR_SPECIALIZATION(ANARISurface, ANARI_SURFACE);
ANARI_TYPEFOR_SPECIALIZATION(ANARISpatialField, ANARI_SPATIAL_FIELD);
ANARI_TYPEFOR_SPECIALIZATION(ANARIVolume, ANARI_VOLUME);
ANARI_TYPEFOR_SPECIALIZATION(ANARIWorld, ANARI_WORLD);

// std::array ////////////////////////////////////////////////////////////////

// Partial specializations rather than explicit ones, so an application that
// maps a std::array type itself (as SDK users without ext/std.h do) still
// compiles: its explicit specialization simply wins.
namespace detail {

// The VECn type of a numeric scalar type (each scalar starts a run of four).
constexpr int vectorTypeOf(int scalar, size_t n)
{
  const bool numeric = scalar >= int(ANARI_INT8) && scalar <= int(ANARI_FLOAT64)
                       && (scalar - int(ANARI_INT8)) % 4 == 0;
  return numeric && n >= 1 && n <= 4 ? scalar + int(n) - 1 : int(ANARI_UNKNOWN);
}

// M vectors of N scalars: two are a box (lower, upper), otherwise M columns
// of a column-major float matrix with N rows.
constexpr int nestedTypeOf(int scalar, size_t n, size_t m)
{
  if (n < 1 || n > 4)
    return int(ANARI_UNKNOWN);
  const int offset = int(n) - 1;
  if (m == 2) {
    if (scalar == int(ANARI_INT32))
      return int(ANARI_INT32_BOX1) + offset;
    if (scalar == int(ANARI_FLOAT32))
      return int(ANARI_FLOAT32_BOX1) + offset;
    if (scalar == int(ANARI_FLOAT64))
      return int(ANARI_FLOAT64_BOX1) + offset;
    if (scalar == int(ANARI_UINT64))
      return int(ANARI_UINT64_REGION1) + offset;
    return int(ANARI_UNKNOWN);
  }
  if (scalar != int(ANARI_FLOAT32))
    return int(ANARI_UNKNOWN);
  if (n == 3 && m == 3)
    return int(ANARI_FLOAT32_MAT3);
  if (n == 4 && m == 4)
    return int(ANARI_FLOAT32_MAT4);
  if (n == 3 && m == 4)
    return int(ANARI_FLOAT32_MAT3x4);
  return int(ANARI_UNKNOWN);
}

} // namespace detail

template <typename T, size_t N>
struct ANARITypeFor<std::array<T, N>>
    : detail::DataTypeConstant<detail::vectorTypeOf(ANARITypeFor<T>::value, N)>
{};

template <typename T, size_t N, size_t M>
struct ANARITypeFor<std::array<std::array<T, N>, M>>
    : detail::DataTypeConstant<detail::nestedTypeOf(
          ANARITypeFor<T>::value, N, M)>
{};

template <typename T, size_t N>
struct ANARITypeFor<const std::array<T, N>> : ANARITypeFor<std::array<T, N>>
{};

} // namespace anari
