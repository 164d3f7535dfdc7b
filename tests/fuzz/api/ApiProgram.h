// The bytecode fuzz_api interprets: a program of ANARI calls, shared by the
// interpreter (ApiInterpreter) and the seed-corpus writer (SeedCorpus).
//
// A program is one flags byte, then operations, each `opcode length payload`
// with `length` payload bytes. An operation reads its operands from its own
// payload (zeros past its end), so a mutation inside one operation never
// shifts the ones after it.
//
// Objects live in one pool, in creation order: every object an operation
// creates (even one the device refuses, whose handle is NULL) appends one
// entry, and operands name entries by index modulo the pool size. Entries
// outlive their release, so later operations can use stale handles. Besides
// the creating operations, a SetParameter/SetNamedParameter of an array type
// whose value selector is below 100 creates a fresh array (one entry; an
// array of arrays first appends its inner arrays). A fresh array's value
// bytes are [element type][n1][n2][n3][sharing][elements...]: the element
// type indexes the parameter's accepted ones, sizes are n % 17 (1D), n % 9
// (2D) or n % 5 (3D), 0 meaning 1.
#pragma once

#include "anari/anari.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace prism::fuzz {

// Program flags (the first byte).
enum ProgramFlags : uint8_t {
  kLeaveObjectsToDevice = 1, // end: release the devices, not the objects
  kNoFinalWait = 2, // end: release without waiting for frames in flight
};

enum class Op : uint8_t {
  // [device][category][subtype][twist][name length][name...]: a named
  // subtype when the name is given, else introspected subtype `subtype`
  // (one past the last: an unknown subtype). twist 1: anariNewObject.
  NewObject,
  // [device][dimensions][element type][n1][n2][n3][sharing][values...]:
  // element type indexes kElementTypes (below kAnyElementType); sizes are n %
  // 17 (0 is refused);
  // sharing % 3: managed, shared with a deleter, shared without one (its
  // memory freed right after the program's last release of the array).
  NewArray,
  // [object][parameter][twist][values...]: the introspected (name, type)
  // pair `parameter` of the object's subtype with a value drawn from
  // `values`; twist 0 a valid value, others one corruption (Twist).
  SetParameter,
  // [object][type][twist][name length][name...][values...]: type indexes
  // kAnyTypes.
  SetNamedParameter,
  // [object][parameter][all]
  UnsetParameter,
  CommitParameters, // [object]
  Release,          // [object]: a stale handle is released again
  Retain,           // [object]
  // [object][unmap][values...]: maps an array, writes its elements.
  MapArray,
  UnmapArray, // [object]
  // [object][parameter][element type][dimensions][n1][n2][n3][unmap]
  // [values...]: anariMapParameterArray on the introspected parameter; the
  // element type is one the parameter accepts below 64, else as NewArray's.
  // Sizes are n % 9 (0 is refused).
  MapParameterArray,
  UnmapParameterArray, // [object][parameter]
  RenderFrame,         // [object][wait]
  FrameReady,          // [object][wait]
  MapFrame,            // [object][channel]
  DiscardFrame,        // [object]
  GetProperty,         // [object][name][type][wait][size]
  // [device][category][subtype][parameter][info][info type]
  Introspect,
  NewDevice,          // []
  ReleaseDevice,      // [device]
  SetDeviceParameter, // [device][which]
  // [kind][object][object]: reference cycles (Cycle enum).
  MakeCycle,
  // [device][geometry][material][light][camera][renderer][flags]: a whole
  // renderable scene, every object appended to the pool (kSceneObjects).
  BuildScene,
  // [category][count]: create and release `count` objects (slot reuse).
  Churn,
  WaitAll, // []: waits for every frame
  // [which][device][name]: device subtypes and extensions, modules, an
  // initialized device, extension functions.
  LibraryQuery,
  // [world][camera][renderer][frames]: two threads at once each render
  // frames % 4 + 1 8x8 frames of their own on the same world, camera and
  // renderer entries (whatever they are), map and release them. Calls
  // naming a shared entry are serialized, as KHR_DEVICE_SYNCHRONIZATION
  // asks of the application; the rest overlap. Each thread holds a public
  // reference to a live world while it works and drops it at its end,
  // while the other's frames may still render it.
  SharedThreads,
  Count
};

// Corruptions of SetParameter (its twist operand, modulo kTwistCount).
enum class Twist : uint8_t {
  None,
  WrongType,     // a type the parameter does not take
  NullHandle,    // NULL for an object, a NULL value pointer otherwise
  StaleHandle,   // a released object
  ForeignHandle, // an object of another device
  WrongObject,   // a live object of another type
  BogusHandle,   // a handle value no device ever made
  Extreme,       // huge, NaN, infinite, denormal or -0 values
  Count
};

enum class Cycle : uint8_t {
  ArrayHoldsItself,
  ArraysHoldEachOther,
  GeometryHoldsItsArray,      // a geometry parameter holding an array of it
  MappedParameterHoldsObject, // a parameter array holding its object
  Count
};

// BuildScene flags.
enum SceneFlags : uint8_t {
  kSceneInstanced = 1, // surfaces in a group in an instance, else direct
  kSceneNoLight = 2,
  kSceneRender = 4,  // render and wait once
  kSceneSampler = 8, // the material's color from an image2D sampler
  kSceneAccumulate = 16,
};
// Objects BuildScene appends to the pool, in this order: position array,
// geometry, sampler image, sampler, material, surface, surface array, group,
// instance, instance array, light, light array, world, camera, renderer,
// frame.
constexpr int kSceneObjects = 16;

// Object categories of NewObject, Introspect and Churn.
inline constexpr ANARIDataType kCategories[] = {ANARI_GEOMETRY,
    ANARI_MATERIAL,
    ANARI_SAMPLER,
    ANARI_LIGHT,
    ANARI_CAMERA,
    ANARI_RENDERER,
    ANARI_SURFACE,
    ANARI_GROUP,
    ANARI_INSTANCE,
    ANARI_WORLD,
    ANARI_FRAME,
    ANARI_SPATIAL_FIELD,
    ANARI_VOLUME};
constexpr int kCategoryCount = sizeof(kCategories) / sizeof(kCategories[0]);

// Element types of NewArray and MapParameterArray.
inline constexpr ANARIDataType kElementTypes[] = {ANARI_FLOAT32,
    ANARI_FLOAT32_VEC2,
    ANARI_FLOAT32_VEC3,
    ANARI_FLOAT32_VEC4,
    ANARI_UINT32,
    ANARI_UINT32_VEC2,
    ANARI_UINT32_VEC3,
    ANARI_UINT32_VEC4,
    ANARI_UINT64,
    ANARI_UINT8,
    ANARI_UFIXED8_VEC4,
    ANARI_UFIXED8_RGBA_SRGB,
    ANARI_UFIXED16_VEC2,
    ANARI_FIXED16_VEC3,
    ANARI_FLOAT32_MAT4,
    ANARI_FLOAT32_QUAT_IJKW,
    ANARI_FLOAT64,
    ANARI_FLOAT16_VEC3,
    ANARI_INT8_VEC2,
    ANARI_SURFACE,
    ANARI_INSTANCE,
    ANARI_LIGHT,
    ANARI_GEOMETRY,
    ANARI_ARRAY1D,
    ANARI_VOLUME,
    ANARI_RENDERER,
    ANARI_DATA_TYPE, // not an element type: refused
    ANARI_STRING};   // not an element type: refused
constexpr int kElementTypeCount =
    sizeof(kElementTypes) / sizeof(kElementTypes[0]);
// Element type selectors from this one on pick any plain data type.
constexpr uint8_t kAnyElementType = 128;

// Types of SetNamedParameter and of SetParameter's WrongType twist: values,
// handles, pointers and types no parameter has.
inline constexpr ANARIDataType kAnyTypes[] = {ANARI_BOOL,
    ANARI_INT32,
    ANARI_UINT32,
    ANARI_FLOAT32,
    ANARI_FLOAT32_VEC2,
    ANARI_FLOAT32_VEC3,
    ANARI_FLOAT32_VEC4,
    ANARI_UINT32_VEC2,
    ANARI_INT32_VEC3,
    ANARI_FLOAT32_MAT4,
    ANARI_FLOAT32_MAT3x4,
    ANARI_FLOAT32_BOX1,
    ANARI_FLOAT32_BOX2,
    ANARI_FLOAT32_BOX3,
    ANARI_UINT64,
    ANARI_UINT64_REGION1,
    ANARI_STRING,
    ANARI_DATA_TYPE,
    ANARI_FLOAT64,
    ANARI_FLOAT16_VEC3,
    ANARI_UFIXED8_VEC4,
    ANARI_UFIXED8_RGBA_SRGB,
    ANARI_FLOAT32_QUAT_IJKW,
    ANARI_INT8,
    ANARI_VOID_POINTER,
    ANARI_FRAME_COMPLETION_CALLBACK,
    ANARI_STATUS_CALLBACK,
    ANARI_FUNCTION_POINTER,
    ANARI_MEMORY_DELETER,
    ANARI_STRING_LIST,
    ANARI_DATA_TYPE_LIST,
    ANARI_PARAMETER_LIST,
    ANARI_ARRAY1D,
    ANARI_ARRAY2D,
    ANARI_ARRAY3D,
    ANARI_ARRAY,
    ANARI_OBJECT,
    ANARI_SURFACE,
    ANARI_GEOMETRY,
    ANARI_MATERIAL,
    ANARI_SAMPLER,
    ANARI_LIGHT,
    ANARI_CAMERA,
    ANARI_RENDERER,
    ANARI_GROUP,
    ANARI_INSTANCE,
    ANARI_WORLD,
    ANARI_FRAME,
    ANARI_VOLUME,
    ANARI_SPATIAL_FIELD,
    ANARI_DEVICE,
    ANARI_LIBRARY,
    ANARI_UNKNOWN,
    ANARIDataType(9999),
    ANARIDataType(-1)};
constexpr int kAnyTypeCount = sizeof(kAnyTypes) / sizeof(kAnyTypes[0]);

// Index of `type` in `list` (for writers), -1 if absent.
template <size_t N>
constexpr int indexOf(const ANARIDataType (&list)[N], ANARIDataType type)
{
  for (size_t i = 0; i < N; i++) {
    if (int(list[i]) == int(type))
      return int(i);
  }
  return -1;
}

// Value selectors: one byte picks a scalar. Floats below kFloatUnit are
// +-(byte >> 1) / 8, negative when the byte is odd (0 is 0, 16 is 1.0, 17 is
// -1.0); [kFloatUnit, kFloatExtreme) are (byte - 128) / 63 in [0, 1]; from
// kFloatExtreme on, the extremes listed in ApiInterpreter.cpp (in
// SetParameter only with the Extreme twist). Integers below kIntExtreme are
// byte % 32.
constexpr uint8_t kFloatUnit = 128;
constexpr uint8_t kFloatExtreme = 192;
constexpr uint8_t kIntExtreme = 240;
// Handle selectors (array elements, object parameters): below 200 a live
// object of the wanted type, then NULL, stale, foreign, wrong-type, bogus.
constexpr uint8_t kHandleNull = 200;
constexpr uint8_t kHandleStale = 220;
constexpr uint8_t kHandleForeign = 230;
constexpr uint8_t kHandleWrongType = 240;
constexpr uint8_t kHandleBogus = 250;

// Selector byte of a float value a writer wants (exact for multiples of
// 1/8 in [-7.875, 7.875]).
inline uint8_t floatSelector(float value)
{
  const float magnitude = value < 0.f ? -value : value;
  int steps = int(magnitude * 8.f + 0.5f);
  steps = steps > 63 ? 63 : steps;
  return uint8_t((steps << 1) | (value < 0.f ? 1 : 0));
}

// Builds programs (the seed corpus writes meaningful ones with it).
class ProgramWriter
{
 public:
  explicit ProgramWriter(uint8_t flags = 0)
  {
    m_bytes.push_back(flags);
  }

  // One operation; `payload` is cut at 255 bytes.
  ProgramWriter &op(Op op, const std::vector<uint8_t> &payload)
  {
    const size_t n = payload.size() < 255 ? payload.size() : 255;
    m_bytes.push_back(uint8_t(op));
    m_bytes.push_back(uint8_t(n));
    m_bytes.insert(m_bytes.end(), payload.begin(), payload.begin() + n);
    return *this;
  }
  // Appends `name` as a length byte and its characters to `payload`.
  static void appendName(std::vector<uint8_t> &payload, const std::string &name)
  {
    payload.push_back(uint8_t(name.size()));
    payload.insert(payload.end(), name.begin(), name.end());
  }
  const std::vector<uint8_t> &bytes() const
  {
    return m_bytes;
  }

 private:
  std::vector<uint8_t> m_bytes;
};

} // namespace prism::fuzz
