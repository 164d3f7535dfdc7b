#include "ApiInterpreter.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace prism::fuzz {
namespace {

// Limits that keep one program fast (the fuzzer wants hundreds a second).
constexpr size_t kMaxOperations = 400;
constexpr size_t kMaxObjects = 256;
constexpr int kMaxDevices = 4;
constexpr uint32_t kMaxFrameSide = 8;
constexpr int32_t kMaxSamples = 4; // aoSamples, maxPathLength, ...
constexpr size_t kMaxNested = 16;  // inner arrays of one array of arrays

// Fails the run: libFuzzer records the input as a crash.
[[noreturn]] void violated(const char *what, const char *detail = "")
{
  std::fprintf(stderr, "fuzz_api: API promise broken: %s %s\n", what, detail);
  std::fflush(stderr);
  std::abort();
}

// Statistics //////////////////////////////////////////////////////////////

struct Counters
{
  std::atomic<uint64_t> programs{0}, calls{0}, messages{0}, errors{0},
      framesCompleted{0}, framesMapped{0};
  // Messages of the debug layer ("anariSetParameter(...): ..."), when the
  // run goes through it (ANARI_DEBUG_LAYER).
  std::atomic<uint64_t> layerMessages{0};
};
Counters g_counters;

// Whether libanari wraps prism in the debug layer for this run.
const bool g_throughDebugLayer = [] {
  const char *value = std::getenv("ANARI_DEBUG_LAYER");
  return value && *value && std::string(value) != "0";
}();

// The debug layer names the call first: "anariXxx(".
bool fromDebugLayer(const char *message)
{
  if (std::strncmp(message, "anari", 5) != 0)
    return false;
  const char *c = message + 5;
  while (std::isalnum((unsigned char)*c))
    ++c;
  return c > message + 5 && *c == '(';
}

// Status messages: every one must be well formed.
void checkStatus(const void *userPtr,
    ANARIDevice,
    ANARIObject,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message)
{
  if (userPtr != &g_counters)
    violated("status callback got a foreign user pointer");
  if (!message)
    violated("status message is NULL");
  const size_t length = std::strlen(message); // ASan: NUL-terminated
  if (length == 0)
    violated("status message is empty");
  if (message[length - 1] == '\n')
    violated("status message ends in a newline:", message);
  if (severity < ANARI_SEVERITY_FATAL_ERROR || severity > ANARI_SEVERITY_DEBUG)
    violated("status message has an invalid severity:", message);
  if (code < ANARI_STATUS_NO_ERROR || code > ANARI_STATUS_VERSION_MISMATCH)
    violated("status message has an invalid code:", message);
  if (!anari::isValidDataType(sourceType))
    violated("status message has an invalid source type:", message);
  g_counters.messages++;
  if (fromDebugLayer(message))
    g_counters.layerMessages++;
  if (severity <= ANARI_SEVERITY_ERROR)
    g_counters.errors++;
  static const bool verbose = std::getenv("PRISM_FUZZ_API_VERBOSE") != nullptr;
  if (verbose)
    std::fprintf(stderr, "  [%d/%d] %s\n", int(severity), int(code), message);
}

int g_completionToken;

void frameCompleted(const void *userPtr, ANARIDevice device, ANARIFrame frame)
{
  if (userPtr && userPtr != &g_completionToken)
    violated("frame completion callback got a foreign user pointer");
  if (!device || !frame)
    violated("frame completion callback got a NULL device or frame");
  g_counters.framesCompleted++;
}

// Values for the pointer-carrying types: valid pointers only (a device may
// call or follow them; garbage there is the application's fault).
void noFunction() {}
void noDeleter(const void *, const void *) {}
unsigned char g_userBuffer[256];
const float kOne = 1.f;
const char *g_stringList[] = {"a", "b", nullptr};
const ANARIDataType g_typeList[] = {ANARI_FLOAT32, ANARI_UNKNOWN};
const ANARIParameter g_parameterList[] = {
    {"a", ANARI_FLOAT32}, {nullptr, ANARI_UNKNOWN}};

// Application memory of shared arrays: freed by the deleter, which must run
// exactly once per array by the time its device is released.
std::atomic<int64_t> g_sharedLive{0};
int g_deleterToken;

struct SharedMemory
{
  uint32_t magic;
  uint32_t bytes;
  // the array's elements follow
};
constexpr uint32_t kSharedMagic = 0x5eed5eed;
constexpr uint32_t kSharedFreed = 0xdeadf4ee;

void *newSharedMemory(size_t bytes)
{
  auto *header = (SharedMemory *)std::malloc(sizeof(SharedMemory) + bytes);
  header->magic = kSharedMagic;
  header->bytes = uint32_t(bytes);
  g_sharedLive++;
  return header + 1;
}

void sharedDeleter(const void *userPtr, const void *memory)
{
  if (userPtr != &g_deleterToken)
    violated("array deleter got a foreign user pointer");
  if (!memory)
    violated("array deleter got NULL memory");
  auto *header = (SharedMemory *)memory - 1;
  if (header->magic != kSharedMagic)
    violated("array deleter called twice (or on foreign memory)");
  header->magic = kSharedFreed;
  g_sharedLive--;
  std::free(header);
}

// Introspection, cached per process (the device's answers never change).
struct ParameterInfo
{
  std::string name;
  ANARIDataType type = ANARI_UNKNOWN;
  std::vector<ANARIDataType> elementTypes;
  std::vector<std::string> values;       // accepted strings
  std::vector<ANARIDataType> typeValues; // accepted data types
};

struct Introspection
{
  std::map<int, std::vector<std::string>> subtypes;
  std::map<std::pair<int, std::string>, std::vector<ParameterInfo>> parameters;

  const std::vector<std::string> &subtypesOf(
      ANARIDevice device, ANARIDataType type)
  {
    auto it = subtypes.find(type);
    if (it != subtypes.end())
      return it->second;
    std::vector<std::string> list;
    if (const char **names = anariGetObjectSubtypes(device, type)) {
      for (; *names; ++names)
        list.push_back(*names);
    }
    return subtypes[type] = list;
  }

  const std::vector<ParameterInfo> &parametersOf(
      ANARIDevice device, ANARIDataType type, const std::string &subtype)
  {
    auto key = std::make_pair(int(type), subtype);
    auto it = parameters.find(key);
    if (it != parameters.end())
      return it->second;
    std::vector<ParameterInfo> list;
    auto *p = (const ANARIParameter *)anariGetObjectInfo(
        device, type, subtype.c_str(), "parameter", ANARI_PARAMETER_LIST);
    for (; p && p->name; ++p) {
      ParameterInfo info;
      info.name = p->name;
      info.type = p->type;
      const char *s = subtype.c_str();
      if (auto *e = (const ANARIDataType *)anariGetParameterInfo(device,
              type,
              s,
              p->name,
              p->type,
              "elementType",
              ANARI_DATA_TYPE_LIST)) {
        for (; *e != ANARI_UNKNOWN; ++e)
          info.elementTypes.push_back(*e);
      }
      if (p->type == ANARI_STRING) {
        if (auto *v = (const char **)anariGetParameterInfo(device,
                type,
                s,
                p->name,
                p->type,
                "value",
                ANARI_STRING_LIST)) {
          for (; *v; ++v)
            info.values.push_back(*v);
        }
      }
      if (p->type == ANARI_DATA_TYPE) {
        if (auto *v = (const ANARIDataType *)anariGetParameterInfo(device,
                type,
                s,
                p->name,
                p->type,
                "value",
                ANARI_DATA_TYPE_LIST)) {
          for (; *v != ANARI_UNKNOWN; ++v)
            info.typeValues.push_back(*v);
        }
      }
      list.push_back(std::move(info));
    }
    return parameters[key] = list;
  }
};
Introspection g_introspection;

ANARILibrary g_library = nullptr;

// Operands ////////////////////////////////////////////////////////////////

// One operation's payload. operand() is 0 past the end (no corruption, the
// first choice); value() continues with sane pseudo-random selectors (floats
// in [0, 1], small integers, live handles), so short payloads still make
// varied, valid-looking scenes.
class Payload
{
 public:
  Payload(const uint8_t *data, size_t size) : m_data(data), m_size(size)
  {
    m_state = 0x9e3779b97f4a7c15ull ^ size;
    for (size_t i = 0; i < size; i++)
      m_state = (m_state ^ data[i]) * 0x100000001b3ull;
  }
  uint8_t operand()
  {
    return m_next < m_size ? m_data[m_next++] : 0;
  }
  uint8_t value()
  {
    if (m_next < m_size)
      return m_data[m_next++];
    m_state ^= m_state << 13;
    m_state ^= m_state >> 7;
    m_state ^= m_state << 17;
    return uint8_t(kFloatUnit + (m_state & 0x3f));
  }
  uint32_t raw32()
  {
    uint32_t v = 0;
    for (int i = 0; i < 4; i++)
      v |= uint32_t(value()) << (8 * i);
    return v;
  }
  std::string name()
  {
    const size_t length = operand();
    std::string out;
    for (size_t i = 0; i < length && m_next < m_size; i++)
      out.push_back(char(m_data[m_next++]));
    // The device reads a C string: the name ends at its first NUL for the
    // interpreter too (or "frameCompletionCallbackUserData\0x" would get a
    // value the interpreter never meant for the completion callback).
    out.resize(std::strlen(out.c_str()));
    return out;
  }

 private:
  const uint8_t *m_data;
  size_t m_size;
  size_t m_next = 0;
  uint64_t m_state;
};

// What a scalar of a data type is.
enum class Scalar { I8, U8, I16, U16, I32, U32, I64, U64, F16, F32, F64 };

struct Shape
{
  Scalar scalar = Scalar::U8;
  int count = 0; // scalars per element; 0: not a plain value type
};

size_t scalarSize(Scalar s)
{
  switch (s) {
  case Scalar::I8:
  case Scalar::U8:
    return 1;
  case Scalar::I16:
  case Scalar::U16:
  case Scalar::F16:
    return 2;
  case Scalar::I32:
  case Scalar::U32:
  case Scalar::F32:
    return 4;
  default:
    return 8;
  }
}

Shape shapeOf(ANARIDataType type)
{
  static constexpr Scalar kInts[] = {Scalar::I8,
      Scalar::U8,
      Scalar::I16,
      Scalar::U16,
      Scalar::I32,
      Scalar::U32,
      Scalar::I64,
      Scalar::U64};
  const int t = int(type);
  Shape s;
  if (t >= 1000 && t < 1064) {
    s.scalar = kInts[((t - 1000) % 32) / 4];
    s.count = (t - 1000) % 4 + 1;
  } else if (t >= 1064 && t < 1076) {
    static constexpr Scalar kFloats[] = {Scalar::F16, Scalar::F32, Scalar::F64};
    s.scalar = kFloats[(t - 1064) / 4];
    s.count = (t - 1064) % 4 + 1;
  } else if (t >= 2000 && t <= 2003) {
    s = {Scalar::U8, t - 2000 + 1};
  } else if (t >= 2004 && t <= 2007) {
    s = {Scalar::I32, 2 * (t - 2004 + 1)};
  } else if (t >= 2008 && t <= 2011) {
    s = {Scalar::F32, 2 * (t - 2008 + 1)};
  } else if (t >= 2208 && t <= 2211) {
    s = {Scalar::F64, 2 * (t - 2208 + 1)};
  } else if (t >= 2104 && t <= 2107) {
    s = {Scalar::U64, 2 * (t - 2104 + 1)};
  } else if (t >= 2012 && t <= 2017) {
    s = {Scalar::F32, int(anari::sizeOf(type) / 4)};
  } else if (t == ANARI_BOOL) {
    s = {Scalar::U8, 1};
  } else if (t == ANARI_DATA_TYPE) {
    s = {Scalar::I32, 1};
  }
  if (s.count && size_t(s.count) * scalarSize(s.scalar) != anari::sizeOf(type))
    s.count = 0; // not the layout assumed: written as raw bytes
  return s;
}

// Selector byte -> float (see ApiProgram.h).
float floatOf(uint8_t s, Payload &p, bool extremes)
{
  if (s < kFloatUnit)
    return ((s & 1) ? -1.f : 1.f) * float(s >> 1) / 8.f; // 1: -0

  if (s < kFloatExtreme)
    return float(s - kFloatUnit) / 63.f;
  if (!extremes)
    return 1.f;
  switch (s - kFloatExtreme) {
  case 0:
    return 1e30f;
  case 1:
    return -1e30f;
  case 2:
    return std::numeric_limits<float>::quiet_NaN();
  case 3:
    return std::numeric_limits<float>::infinity();
  case 4:
    return -std::numeric_limits<float>::infinity();
  case 5:
    return -0.f;
  case 6:
    return 1e-40f; // denormal
  case 7:
    return std::numeric_limits<float>::max();
  case 8:
    return std::numeric_limits<float>::lowest();
  case 9:
    return std::numeric_limits<float>::min();
  case 10:
    return 1e-30f;
  case 11:
    return 1e6f;
  case 12:
    return -1e6f;
  case 13: {
    const uint32_t bits = p.raw32();
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  case 14:
    return std::numeric_limits<float>::denorm_min();
  case 15:
    return 65504.f;
  default:
    return float(s - kFloatExtreme - 16) / 4.f;
  }
}

// Selector byte -> integer bits (see ApiProgram.h).
uint64_t intOf(uint8_t s, Payload &p)
{
  if (s < kIntExtreme)
    return s % 32;
  switch (s - kIntExtreme) {
  case 0:
    return ~0ull;
  case 1:
    return 0x7fffffffull;
  case 2:
    return 0x80000000ull;
  case 3:
    return 0xffffull;
  case 4:
    return 256;
  case 5:
    return p.raw32();
  case 6:
    return 65536;
  case 7:
    return 1ull << 40;
  case 8:
    return 0x8000000000000000ull;
  default:
    return 32 + (s - kIntExtreme - 9);
  }
}

uint16_t halfOf(float f)
{
  // Enough of IEEE half for test values: sign, clamped exponent, mantissa.
  uint32_t bits;
  std::memcpy(&bits, &f, 4);
  const uint16_t sign = uint16_t((bits >> 16) & 0x8000);
  const int exponent = int((bits >> 23) & 0xff) - 127 + 15;
  const uint16_t mantissa = uint16_t((bits >> 13) & 0x3ff);
  if (std::isnan(f))
    return uint16_t(sign | 0x7e00);
  if (exponent >= 31)
    return uint16_t(sign | 0x7c00);
  if (exponent <= 0)
    return sign;
  return uint16_t(sign | (exponent << 10) | mantissa);
}

void writeScalar(
    Scalar s, uint8_t selector, Payload &p, bool extremes, void *out)
{
  switch (s) {
  case Scalar::F32: {
    const float f = floatOf(selector, p, extremes);
    std::memcpy(out, &f, 4);
    break;
  }
  case Scalar::F64: {
    const double d = floatOf(selector, p, extremes);
    std::memcpy(out, &d, 8);
    break;
  }
  case Scalar::F16: {
    const uint16_t h = halfOf(floatOf(selector, p, extremes));
    std::memcpy(out, &h, 2);
    break;
  }
  default: {
    const uint64_t v = extremes ? intOf(selector, p) : selector % 32;
    std::memcpy(out, &v, scalarSize(s)); // little-endian: the low bytes
    break;
  }
  }
}

// Every plain data type (any array may hold them).
const std::vector<ANARIDataType> &numericTypes()
{
  static const std::vector<ANARIDataType> types = [] {
    std::vector<ANARIDataType> out;
    for (int t = 1000; t < 2300; t++) {
      if (anari::isValidDataType(t) && anari::sizeOf(t) > 0)
        out.push_back(t);
    }
    return out;
  }();
  return types;
}

// An element type selector: kElementTypes, or from kAnyElementType on any
// plain data type.
ANARIDataType elementTypeOf(uint8_t s)
{
  if (s < kAnyElementType)
    return kElementTypes[s % kElementTypeCount];
  return numericTypes()[(s - kAnyElementType) % numericTypes().size()];
}

// The interpreter /////////////////////////////////////////////////////////

struct Entry
{
  ANARIObject handle = nullptr;
  ANARIDataType type = ANARI_UNKNOWN;
  std::string subtype;
  int device = 0;
  int refs = 0; // public references the program holds
  // Arrays made by NewArray and friends: what map returns.
  ANARIDataType elementType = ANARI_UNKNOWN;
  uint64_t capacity = 0;
  // Shared arrays without a deleter: the application's memory, freed right
  // after the last release (as the SDK's own scenes do).
  void *borrowed = nullptr;
  // Frames: the largest side any size set on it had.
  uint32_t largestSide = 0;
  bool absurdSize = false;
};

struct DeviceSlot
{
  ANARIDevice handle = nullptr;
  bool released = false;
  bool silenced = false; // its status callback was set to NULL
};

class Interpreter
{
 public:
  Interpreter()
  {
    m_entries.reserve(kMaxObjects + 2 * kMaxNested);
  }

  void run(const uint8_t *data, size_t size)
  {
    const uint8_t flags = size ? data[0] : 0;
    size_t at = size ? 1 : 0;
    newDevice();
    for (size_t ops = 0; at + 2 <= size && ops < kMaxOperations; ops++) {
      const uint8_t code = data[at];
      const size_t length = std::min<size_t>(data[at + 1], size - at - 2);
      Payload payload(data + at + 2, length);
      at += 2 + length;
      execute(Op(code % uint8_t(Op::Count)), payload);
    }
    finish(flags);
  }

 private:
  void call()
  {
    g_counters.calls++;
  }

  // Devices and entries ///////////////////////////////////////////////////

  int newDevice()
  {
    if (m_devices.size() >= size_t(kMaxDevices))
      return int(m_devices.size()) - 1;
    call();
    DeviceSlot slot;
    slot.handle = anariNewDevice(g_library, "default");
    if (!slot.handle)
      violated("anariNewDevice failed");
    m_devices.push_back(slot);
    return int(m_devices.size()) - 1;
  }
  int deviceOperand(uint8_t b) const
  {
    return b % int(m_devices.size());
  }
  ANARIDevice deviceOf(const Entry &e) const
  {
    return m_devices[e.device].handle;
  }
  // Any live device, for introspection (NULL if all were released).
  ANARIDevice liveDevice() const
  {
    for (const DeviceSlot &d : m_devices) {
      if (!d.released)
        return d.handle;
    }
    return nullptr;
  }
  bool isLive(const Entry &e) const
  {
    return e.handle && e.refs > 0 && !m_devices[e.device].released;
  }

  Entry *entry(uint8_t b)
  {
    return m_entries.empty() ? nullptr : &m_entries[b % m_entries.size()];
  }
  // Appends an entry for a created object (NULL handles too: the pool's
  // indices must not depend on what the device accepted).
  Entry &add(ANARIObject handle,
      ANARIDataType type,
      int device,
      const std::string &subtype = "")
  {
    // Callers hold references into the pool: it must never reallocate.
    if (m_entries.size() == m_entries.capacity())
      violated("fuzz_api: object pool overflow (an interpreter bug)");
    Entry e;
    e.handle = handle;
    e.type = type;
    e.device = device;
    e.subtype = subtype;
    e.refs = handle ? 1 : 0;
    m_entries.push_back(e);
    return m_entries.back();
  }
  bool full() const
  {
    return m_entries.size() >= kMaxObjects;
  }

  // A live object of `type` on `device` picked by `index`, or NULL.
  ANARIObject liveOf(ANARIDataType type, int device, uint8_t index)
  {
    std::vector<const Entry *> matches;
    for (const Entry &e : m_entries) {
      const bool typeMatches =
          int(type) == ANARI_OBJECT
          || (int(type) == ANARI_ARRAY && anari::isArray(e.type))
          || e.type == type;
      if (typeMatches && e.device == device && isLive(e))
        matches.push_back(&e);
    }
    return matches.empty() ? nullptr : matches[index % matches.size()]->handle;
  }
  ANARIObject staleHandle(uint8_t index)
  {
    std::vector<const Entry *> matches;
    for (const Entry &e : m_entries) {
      if (e.handle && !isLive(e))
        matches.push_back(&e);
    }
    return matches.empty() ? nullptr : matches[index % matches.size()]->handle;
  }
  ANARIObject foreignHandle(int device, uint8_t index)
  {
    std::vector<const Entry *> matches;
    for (const Entry &e : m_entries) {
      if (e.device != device && isLive(e))
        matches.push_back(&e);
    }
    return matches.empty() ? nullptr : matches[index % matches.size()]->handle;
  }
  ANARIObject anyLive(int device, uint8_t index)
  {
    return liveOf(ANARI_OBJECT, device, index);
  }
  // A handle for `type` on `device` per a handle selector (ApiProgram.h).
  ANARIObject handleOf(uint8_t s, ANARIDataType type, int device, Payload &p)
  {
    if (s < kHandleNull)
      return liveOf(type, device, s);
    if (s < kHandleStale)
      return nullptr;
    if (s < kHandleForeign)
      return staleHandle(p.value());
    if (s < kHandleWrongType)
      return foreignHandle(device, p.value());
    if (s < kHandleBogus)
      return anyLive(device, p.value());
    static const uintptr_t kBogus[] = {0x1,
        0xdeadbeef,
        0x7f00000000000001ull, // generation 0: never handed out
        0x7fffffff00000001ull,
        0x7f000001ffffffffull,
        uintptr_t(&g_userBuffer)};
    return (ANARIObject)kBogus[(s - kHandleBogus) % 6];
  }

  // Values ////////////////////////////////////////////////////////////////

  // Fills `count` elements of `type` at `out` from selectors in `p`. Object
  // elements become handles of `device`; `nested` allows arrays of arrays.
  void fill(void *out,
      ANARIDataType type,
      uint64_t count,
      int device,
      Payload &p,
      bool extremes)
  {
    auto *bytes = (unsigned char *)out;
    const size_t size = anari::sizeOf(type);
    if (anari::isObject(type)) {
      for (uint64_t i = 0; i < count; i++) {
        ANARIObject h = handleOf(p.value(), type, device, p);
        std::memcpy(bytes + i * size, &h, sizeof(h));
      }
      return;
    }
    const Shape shape = shapeOf(type);
    for (uint64_t i = 0; i < count; i++) {
      unsigned char *element = bytes + i * size;
      if (!shape.count) {
        for (size_t b = 0; b < size; b++)
          element[b] = p.value();
        continue;
      }
      const size_t step = scalarSize(shape.scalar);
      for (int c = 0; c < shape.count; c++)
        writeScalar(shape.scalar, p.value(), p, extremes, element + c * step);
    }
  }

  // A new array of `dimensions` of `elementType`, appended to the pool;
  // `sharing` % 3: managed, shared with a deleter, shared without one (the
  // memory is freed right after the last release). Arrays of arrays nest
  // once.
  ANARIObject newArray(int device,
      int dimensions,
      ANARIDataType elementType,
      const uint64_t size[3],
      int sharing,
      Payload &p,
      bool extremes,
      int depth = 0)
  {
    ANARIDevice dev = m_devices[device].handle;
    const uint64_t count = size[0] * size[1] * size[2];
    const size_t elementSize = anari::sizeOf(elementType);
    const bool valid =
        count > 0 && elementSize > 0
        && (int(elementType) >= 1000 || anari::isObject(elementType));
    void *memory = nullptr;
    void *borrowed = nullptr;
    if (sharing % 3 == 1 && valid)
      memory = newSharedMemory(count * elementSize);
    if (sharing % 3 == 2 && valid)
      borrowed = std::malloc(count * elementSize);
    std::vector<unsigned char> staging;
    void *target = memory ? memory : borrowed;
    if (!target && valid) {
      staging.resize(count * elementSize);
      target = staging.data();
    }
    if (target) {
      if (int(elementType) == ANARI_ARRAY1D && depth == 0
          && count <= kMaxNested) {
        // Arrays of arrays (motion.vertex.*): inner arrays of points.
        for (uint64_t i = 0; i < count; i++) {
          const uint64_t inner[3] = {size[0], 1, 1};
          ANARIObject a =
              newArray(device, 1, ANARI_FLOAT32_VEC3, inner, 0, p, extremes, 1);
          std::memcpy((unsigned char *)target + i * elementSize, &a, 8);
        }
      } else {
        fill(target, elementType, count, device, p, extremes);
      }
    }
    call();
    ANARIObject handle = nullptr;
    const void *deleterUser = &g_deleterToken;
    const void *application = memory ? memory : borrowed;
    if (dimensions == 1) {
      handle = anariNewArray1D(dev,
          application,
          memory ? sharedDeleter : nullptr,
          deleterUser,
          elementType,
          size[0]);
    } else if (dimensions == 2) {
      handle = anariNewArray2D(dev,
          application,
          memory ? sharedDeleter : nullptr,
          deleterUser,
          elementType,
          size[0],
          size[1]);
    } else {
      handle = anariNewArray3D(dev,
          application,
          memory ? sharedDeleter : nullptr,
          deleterUser,
          elementType,
          size[0],
          size[1],
          size[2]);
    }
    if (memory && !handle) {
      // Refused: the device never owned the memory.
      g_sharedLive--;
      std::free((SharedMemory *)memory - 1);
    }
    if (!handle) {
      std::free(borrowed);
      borrowed = nullptr;
    }
    if (handle && !memory && !borrowed && target) {
      call();
      if (void *mapped = anariMapArray(dev, (ANARIArray)handle)) {
        std::memcpy(mapped, target, count * elementSize);
      }
      call();
      anariUnmapArray(dev, (ANARIArray)handle);
    }
    const ANARIDataType type = dimensions == 1   ? ANARI_ARRAY1D
                               : dimensions == 2 ? ANARI_ARRAY2D
                                                 : ANARI_ARRAY3D;
    if (full()) {
      // No room to remember it: the parameter or array holding it keeps it.
      if (handle) {
        call();
        anariRelease(dev, handle);
      }
      std::free(borrowed);
      return handle;
    }
    Entry &e = add(handle, type, device);
    e.elementType = elementType;
    e.capacity = handle ? count : 0;
    e.borrowed = borrowed;
    return handle;
  }

  // Sets `name` of `e` to a value of `type` drawn from `p`; `twist` corrupts
  // it one way. `info` (optional) is the introspected parameter.
  void setValue(Entry &e,
      const std::string &name,
      ANARIDataType type,
      Twist twist,
      Payload &p,
      const ParameterInfo *info)
  {
    ANARIDevice dev = deviceOf(e);
    int device = e.device;
    if (twist == Twist::WrongType) {
      ANARIDataType other = kAnyTypes[p.operand() % kAnyTypeCount];
      if (info && int(other) == int(info->type))
        other = ANARI_FLOAT32_VEC2;
      type = other;
      info = nullptr;
    }
    const bool extremes = twist == Twist::Extreme;
    alignas(16) unsigned char buffer[256] = {};
    const void *mem = buffer;
    std::string text;
    const int t = int(type);
    if (anari::isObject(type)) {
      ANARIObject h = nullptr;
      const uint8_t s = p.value();
      switch (twist) {
      case Twist::NullHandle:
        break;
      case Twist::StaleHandle:
        h = staleHandle(s);
        break;
      case Twist::ForeignHandle:
        h = foreignHandle(device, s);
        break;
      case Twist::WrongObject:
        h = anyLive(device, s);
        break;
      case Twist::BogusHandle:
        h = handleOf(uint8_t(kHandleBogus + s % 6), type, device, p);
        break;
      default:
        if (anari::isArray(type) && s < 100 && !full()) {
          h = freshArrayFor(e, type, info, p, extremes);
        } else {
          h = liveOf(type, device, s);
        }
        break;
      }
      std::memcpy(buffer, &h, sizeof(h));
    } else if (t == ANARI_STRING) {
      const uint8_t s = p.value();
      if (info && !info->values.empty() && s < 128) {
        text = info->values[s % info->values.size()];
      } else {
        static const char *kStrings[] = {"",
            "color",
            "attribute0",
            "attribute3",
            "worldPosition",
            "primitiveId",
            "linear",
            "nearest",
            "repeat",
            "mirrorRepeat",
            "both",
            "none",
            "sideBySide",
            "equirectangular",
            "Ng",
            "Ns",
            "uv",
            "primitiveId",
            "backface",
            "opaque",
            "mask",
            "blend",
            "\xff\xfe not utf-8"};
        constexpr int n = sizeof(kStrings) / sizeof(kStrings[0]);
        if (s < 200) {
          text = kStrings[s % n];
        } else {
          for (int i = 0, length = s - 200; i < length; i++)
            text.push_back(char(1 + p.value() % 255));
        }
      }
      mem = text.c_str();
    } else if (t == ANARI_VOID_POINTER) {
      // By value: the pointer is the value (user data, never followed).
      const bool null = p.value() & 1;
      mem = null ? nullptr
            : name == "frameCompletionCallbackUserData"
                ? (const void *)&g_completionToken
                : (const void *)g_userBuffer;
    } else if (t == ANARI_FRAME_COMPLETION_CALLBACK) {
      const ANARIFrameCompletionCallback f = frameCompleted;
      std::memcpy(buffer, &f, sizeof(f));
    } else if (t == ANARI_STATUS_CALLBACK) {
      const ANARIStatusCallback f = checkStatus;
      std::memcpy(buffer, &f, sizeof(f));
    } else if (t == ANARI_FUNCTION_POINTER) {
      void (*f)() = noFunction;
      std::memcpy(buffer, &f, sizeof(f));
    } else if (t == ANARI_MEMORY_DELETER) {
      const ANARIMemoryDeleter f = noDeleter;
      std::memcpy(buffer, &f, sizeof(f));
    } else if (t == ANARI_STRING_LIST) {
      const void *list = g_stringList;
      std::memcpy(buffer, &list, sizeof(list));
    } else if (t == ANARI_DATA_TYPE_LIST) {
      const void *list = g_typeList;
      std::memcpy(buffer, &list, sizeof(list));
    } else if (t == ANARI_PARAMETER_LIST) {
      const void *list = g_parameterList;
      std::memcpy(buffer, &list, sizeof(list));
    } else if (t == ANARI_DATA_TYPE) {
      const uint8_t s = p.value();
      ANARIDataType value = kAnyTypes[s % kAnyTypeCount];
      if (info && !info->typeValues.empty() && s < 128)
        value = info->typeValues[s % info->typeValues.size()];
      else if (s >= 128 && s < 160)
        value = kElementTypes[s % kElementTypeCount];
      const int32_t v = int(value);
      std::memcpy(buffer, &v, 4);
    } else if (anari::sizeOf(type) <= sizeof(buffer)) {
      fill(buffer, type, 1, device, p, extremes || twist == Twist::Extreme);
      limitCost(e, name, type, twist, buffer);
    }
    if (twist == Twist::NullHandle && !anari::isObject(type))
      mem = nullptr;
    // Through the debug layer, a handle no live object of this device has
    // must be reported by the layer at this very call (on a released
    // device, libanari refuses the call before any layer sees it; a device
    // without a status callback reports nothing).
    ANARIObject value = nullptr;
    if (anari::isObject(type))
      std::memcpy(&value, buffer, sizeof(value));
    const bool corrupt =
        value && !m_devices[device].released && !m_devices[device].silenced
        && (twist == Twist::StaleHandle || twist == Twist::ForeignHandle
            || twist == Twist::BogusHandle);
    const uint64_t layerMessages = g_counters.layerMessages;
    call();
    anariSetParameter(dev, e.handle, name.c_str(), type, mem);
    if (g_throughDebugLayer && corrupt
        && g_counters.layerMessages == layerMessages)
      violated("the debug layer let a corrupted handle through:", name.c_str());
  }

  // Keeps frames tiny and sample counts small (one absurd size excepted).
  void limitCost(Entry &e,
      const std::string &name,
      ANARIDataType type,
      Twist twist,
      unsigned char *value)
  {
    if (e.type == ANARI_FRAME && name == "size"
        && int(type) == ANARI_UINT32_VEC2) {
      uint32_t size[2];
      std::memcpy(size, value, 8);
      if (twist == Twist::Extreme) {
        size[0] = size[1] = 100000;
        e.absurdSize = true;
      } else {
        size[0] %= kMaxFrameSide + 1;
        size[1] %= kMaxFrameSide + 1;
      }
      e.largestSide = std::max({e.largestSide, size[0], size[1]});
      std::memcpy(value, size, 8);
      return;
    }
    static const char *kCosts[] = {"aoSamples",
        "maxPathLength",
        "pixelSamples",
        "sampleLimit",
        "maxDepth"};
    for (const char *cost : kCosts) {
      if (name == cost
          && (int(type) == ANARI_INT32 || int(type) == ANARI_UINT32)) {
        int32_t v;
        std::memcpy(&v, value, 4);
        if (v > kMaxSamples)
          v = 1 + v % kMaxSamples;
        std::memcpy(value, &v, 4);
      }
    }
  }

  // A new valid-looking array for an array parameter of `e`.
  ANARIObject freshArrayFor(Entry &e,
      ANARIDataType arrayType,
      const ParameterInfo *info,
      Payload &p,
      bool extremes)
  {
    ANARIDataType elementType = ANARI_FLOAT32_VEC3;
    if (info && !info->elementTypes.empty())
      elementType = info->elementTypes[p.value() % info->elementTypes.size()];
    const int dimensions = int(arrayType) == ANARI_ARRAY2D   ? 2
                           : int(arrayType) == ANARI_ARRAY3D ? 3
                                                             : 1;
    uint64_t size[3] = {1, 1, 1};
    const uint64_t side = dimensions == 1 ? 16 : dimensions == 2 ? 8 : 4;
    for (int i = 0; i < 3; i++) {
      const uint64_t n = p.value() % (side + 1);
      if (i < dimensions)
        size[i] = n ? n : 1;
    }
    return newArray(
        e.device, dimensions, elementType, size, p.value(), p, extremes);
  }

  const std::vector<ParameterInfo> *parametersOf(const Entry &e)
  {
    ANARIDevice dev = liveDevice();
    if (!dev)
      return nullptr;
    return &g_introspection.parametersOf(dev, e.type, e.subtype);
  }

  // Operations ////////////////////////////////////////////////////////////

  void execute(Op op, Payload &p)
  {
    switch (op) {
    case Op::NewObject:
      return newObject(p);
    case Op::NewArray:
      return newArrayOp(p);
    case Op::SetParameter:
      return setParameter(p);
    case Op::SetNamedParameter:
      return setNamedParameter(p);
    case Op::UnsetParameter:
      return unsetParameter(p);
    case Op::CommitParameters:
      return commit(p);
    case Op::Release:
      return release(p);
    case Op::Retain:
      return retain(p);
    case Op::MapArray:
      return mapArray(p);
    case Op::UnmapArray:
      return unmapArray(p);
    case Op::MapParameterArray:
      return mapParameterArray(p);
    case Op::UnmapParameterArray:
      return unmapParameterArray(p);
    case Op::RenderFrame:
      return renderFrame(p);
    case Op::FrameReady:
      return frameReady(p);
    case Op::MapFrame:
      return mapFrameOp(p);
    case Op::DiscardFrame:
      return discardFrame(p);
    case Op::GetProperty:
      return getProperty(p);
    case Op::Introspect:
      return introspect(p);
    case Op::NewDevice:
      newDevice();
      return;
    case Op::ReleaseDevice:
      return releaseDevice(p);
    case Op::SetDeviceParameter:
      return setDeviceParameter(p);
    case Op::MakeCycle:
      return makeCycle(p);
    case Op::BuildScene:
      return buildScene(p);
    case Op::Churn:
      return churn(p);
    case Op::WaitAll:
      return waitAll();
    case Op::LibraryQuery:
      return libraryQuery(p);
    case Op::SharedThreads:
      return sharedThreads(p);
    case Op::Count:
      return;
    }
  }

  ANARIObject create(ANARIDevice dev,
      ANARIDataType type,
      const char *subtype,
      bool generic = false)
  {
    call();
    if (generic) {
      static const std::map<int, const char *> kNames = {
          {ANARI_GEOMETRY, "geometry"},
          {ANARI_MATERIAL, "material"},
          {ANARI_SAMPLER, "sampler"},
          {ANARI_LIGHT, "light"},
          {ANARI_CAMERA, "camera"},
          {ANARI_RENDERER, "renderer"},
          {ANARI_SURFACE, "surface"},
          {ANARI_GROUP, "group"},
          {ANARI_INSTANCE, "instance"},
          {ANARI_WORLD, "world"},
          {ANARI_FRAME, "frame"},
          {ANARI_SPATIAL_FIELD, "spatialField"},
          {ANARI_VOLUME, "volume"}};
      return anariNewObject(dev, kNames.at(type), subtype ? subtype : "");
    }
    switch (int(type)) {
    case ANARI_GEOMETRY:
      return anariNewGeometry(dev, subtype);
    case ANARI_MATERIAL:
      return anariNewMaterial(dev, subtype);
    case ANARI_SAMPLER:
      return anariNewSampler(dev, subtype);
    case ANARI_LIGHT:
      return anariNewLight(dev, subtype);
    case ANARI_CAMERA:
      return anariNewCamera(dev, subtype);
    case ANARI_RENDERER:
      return anariNewRenderer(dev, subtype);
    case ANARI_SURFACE:
      return anariNewSurface(dev);
    case ANARI_GROUP:
      return anariNewGroup(dev);
    case ANARI_INSTANCE:
      return anariNewInstance(dev, subtype);
    case ANARI_WORLD:
      return anariNewWorld(dev);
    case ANARI_FRAME:
      return anariNewFrame(dev);
    case ANARI_SPATIAL_FIELD:
      return anariNewSpatialField(dev, subtype);
    case ANARI_VOLUME:
      return anariNewVolume(dev, subtype);
    default:
      return nullptr;
    }
  }

  static bool hasSubtypes(ANARIDataType type)
  {
    const int t = int(type);
    return t != ANARI_SURFACE && t != ANARI_GROUP && t != ANARI_WORLD
           && t != ANARI_FRAME;
  }

  // The subtype named, or introspected subtype `index` (one past the end:
  // an unknown one).
  std::string subtypeFor(ANARIDataType type, uint8_t index, std::string name)
  {
    if (!name.empty() || !hasSubtypes(type))
      return name;
    ANARIDevice dev = liveDevice();
    const std::vector<std::string> none;
    const auto &list = dev ? g_introspection.subtypesOf(dev, type) : none;
    const size_t pick = index % (list.size() + 1);
    return pick < list.size() ? list[pick] : "fuzz-unknown";
  }

  void newObject(Payload &p)
  {
    const int device = deviceOperand(p.operand());
    const ANARIDataType type = kCategories[p.operand() % kCategoryCount];
    const uint8_t subtypeIndex = p.operand();
    const uint8_t twist = p.operand();
    const std::string subtype = subtypeFor(type, subtypeIndex, p.name());
    if (full())
      return;
    ANARIObject h = create(m_devices[device].handle,
        type,
        hasSubtypes(type) ? subtype.c_str() : nullptr,
        twist % 4 == 1);
    add(h, type, device, subtype);
  }

  void newArrayOp(Payload &p)
  {
    const int device = deviceOperand(p.operand());
    const int dimensions = 1 + p.operand() % 3;
    const ANARIDataType elementType = elementTypeOf(p.operand());
    uint64_t size[3] = {1, 1, 1};
    for (int i = 0; i < 3; i++) {
      const uint8_t n = p.operand();
      if (i < dimensions)
        size[i] = n % 17;
    }
    const uint8_t sharing = p.operand();
    if (full())
      return;
    newArray(device, dimensions, elementType, size, sharing, p, true);
  }

  void setParameter(Payload &p)
  {
    Entry *e = entry(p.operand());
    const uint8_t index = p.operand();
    const Twist twist = Twist(p.operand() % uint8_t(Twist::Count));
    if (!e)
      return;
    const auto *list = parametersOf(*e);
    if (!list || list->empty())
      return;
    const ParameterInfo &info = (*list)[index % list->size()];
    setValue(*e, info.name, info.type, twist, p, &info);
  }

  void setNamedParameter(Payload &p)
  {
    Entry *e = entry(p.operand());
    const ANARIDataType type = kAnyTypes[p.operand() % kAnyTypeCount];
    const Twist twist = Twist(p.operand() % uint8_t(Twist::Count));
    const std::string name = p.name();
    if (!e)
      return;
    // The introspected definition, when the name and type have one, so
    // strings and channel types come from their accepted values.
    const ParameterInfo *info = nullptr;
    if (const auto *list = parametersOf(*e)) {
      for (const ParameterInfo &candidate : *list) {
        if (candidate.name == name && int(candidate.type) == int(type))
          info = &candidate;
      }
    }
    setValue(*e, name, type, twist, p, info);
  }

  void unsetParameter(Payload &p)
  {
    Entry *e = entry(p.operand());
    const uint8_t index = p.operand();
    const bool all = p.operand() & 1;
    if (!e)
      return;
    call();
    if (all) {
      anariUnsetAllParameters(deviceOf(*e), e->handle);
      return;
    }
    const auto *list = parametersOf(*e);
    const std::string name =
        list && !list->empty() ? (*list)[index % list->size()].name : "none";
    anariUnsetParameter(deviceOf(*e), e->handle, name.c_str());
  }

  void commit(Payload &p)
  {
    Entry *e = entry(p.operand());
    if (!e)
      return;
    call();
    anariCommitParameters(deviceOf(*e), e->handle);
  }

  void release(Payload &p)
  {
    Entry *e = entry(p.operand());
    if (!e)
      return;
    if (isLive(*e)) {
      dropReference(*e);
    } else {
      call();
      anariRelease(deviceOf(*e), e->handle); // stale: must be reported
    }
  }

  // Releases one of the program's references; after the last, memory the
  // array borrowed is freed at once (the device must have let go of it or
  // copied it).
  void dropReference(Entry &e)
  {
    call();
    anariRelease(deviceOf(e), e.handle);
    if (--e.refs == 0) {
      std::free(e.borrowed);
      e.borrowed = nullptr;
    }
  }
  // After a device release: memory its arrays borrowed is the program's.
  void freeBorrowed(int device)
  {
    for (Entry &e : m_entries) {
      if (e.device == device) {
        std::free(e.borrowed);
        e.borrowed = nullptr;
      }
    }
  }

  void retain(Payload &p)
  {
    Entry *e = entry(p.operand());
    if (!e)
      return;
    call();
    anariRetain(deviceOf(*e), e->handle);
    if (isLive(*e))
      e->refs++;
  }

  void mapArray(Payload &p)
  {
    Entry *e = entry(p.operand());
    const uint8_t unmap = p.operand();
    if (!e)
      return;
    ANARIDevice dev = deviceOf(*e);
    call();
    void *mapped = anariMapArray(dev, (ANARIArray)e->handle);
    if (mapped && !isLive(*e))
      violated("anariMapArray mapped a released handle");
    if (mapped && e->capacity)
      fill(mapped, e->elementType, e->capacity, e->device, p, true);
    if (!(unmap & 1)) {
      call();
      anariUnmapArray(dev, (ANARIArray)e->handle);
    }
  }

  void unmapArray(Payload &p)
  {
    Entry *e = entry(p.operand());
    if (!e)
      return;
    call();
    anariUnmapArray(deviceOf(*e), (ANARIArray)e->handle);
  }

  std::string parameterName(const Entry &e, uint8_t index)
  {
    const auto *list = parametersOf(e);
    if (!list || list->empty() || index == 255)
      return "fuzz.unknown";
    return (*list)[index % list->size()].name;
  }

  void mapParameterArray(Payload &p)
  {
    Entry *e = entry(p.operand());
    const uint8_t index = p.operand();
    const uint8_t typeSelector = p.operand();
    const int dimensions = 1 + p.operand() % 3;
    uint64_t size[3];
    for (uint64_t &n : size)
      n = p.operand() % 9;
    const uint8_t unmap = p.operand();
    if (!e)
      return;
    const auto *list = parametersOf(*e);
    const ParameterInfo *info = list && !list->empty() && index != 255
                                    ? &(*list)[index % list->size()]
                                    : nullptr;
    ANARIDataType elementType = elementTypeOf(typeSelector);
    if (info && !info->elementTypes.empty() && typeSelector < 64)
      elementType =
          info->elementTypes[typeSelector % info->elementTypes.size()];
    if (int(elementType) == ANARI_ARRAY1D)
      elementType = ANARI_FLOAT32_VEC3; // nested arrays need handles we own
    const std::string name = info ? info->name : "fuzz.unknown";
    ANARIDevice dev = deviceOf(*e);
    uint64_t stride = 0;
    void *mapped = nullptr;
    call();
    if (dimensions == 1) {
      mapped = anariMapParameterArray1D(
          dev, e->handle, name.c_str(), elementType, size[0], &stride);
    } else if (dimensions == 2) {
      mapped = anariMapParameterArray2D(
          dev, e->handle, name.c_str(), elementType, size[0], size[1], &stride);
    } else {
      mapped = anariMapParameterArray3D(dev,
          e->handle,
          name.c_str(),
          elementType,
          size[0],
          size[1],
          size[2],
          &stride);
    }
    if (mapped) {
      if (stride != anari::sizeOf(elementType))
        violated("anariMapParameterArray: unexpected element stride");
      uint64_t count = size[0];
      if (dimensions > 1)
        count *= size[1];
      if (dimensions > 2)
        count *= size[2];
      fill(mapped, elementType, count, e->device, p, true);
    }
    if (!(unmap & 1)) {
      call();
      anariUnmapParameterArray(dev, e->handle, name.c_str());
    }
  }

  void unmapParameterArray(Payload &p)
  {
    Entry *e = entry(p.operand());
    const uint8_t index = p.operand();
    if (!e)
      return;
    call();
    anariUnmapParameterArray(
        deviceOf(*e), e->handle, parameterName(*e, index).c_str());
  }

  Entry *frameOperand(Payload &p)
  {
    // Prefer frames: an index among frames, so seeds and mutations hit them.
    const uint8_t s = p.operand();
    std::vector<Entry *> frames;
    for (Entry &e : m_entries) {
      if (e.type == ANARI_FRAME)
        frames.push_back(&e);
    }
    if (frames.empty() || s >= 240)
      return entry(s);
    return frames[s % frames.size()];
  }

  void renderFrame(Payload &p)
  {
    Entry *e = frameOperand(p);
    const uint8_t wait = p.operand();
    if (!e)
      return;
    call();
    anariRenderFrame(deviceOf(*e), (ANARIFrame)e->handle);
    if (wait & 1) {
      call();
      anariFrameReady(deviceOf(*e), (ANARIFrame)e->handle, ANARI_WAIT);
    }
    if (wait & 2)
      mapFrame(*e, "channel.color");
  }

  void frameReady(Payload &p)
  {
    Entry *e = frameOperand(p);
    const uint8_t wait = p.operand();
    if (!e)
      return;
    call();
    anariFrameReady(deviceOf(*e),
        (ANARIFrame)e->handle,
        (wait & 1) ? ANARI_WAIT : ANARI_NO_WAIT);
  }

  void mapFrame(Entry &e, const char *channel)
  {
    ANARIDevice dev = deviceOf(e);
    uint32_t width = 1234, height = 5678;
    ANARIDataType type = ANARI_FLOAT64_BOX4;
    call();
    auto *pixels = (const unsigned char *)anariMapFrame(
        dev, (ANARIFrame)e.handle, channel, &width, &height, &type);
    if (!pixels) {
      // (libanari leaves the outputs alone when the device is not live.)
      const bool cleared = width == 0 && height == 0 && type == ANARI_UNKNOWN;
      if (!m_devices[e.device].released && !cleared)
        violated("anariMapFrame: no pixels but a size or type:", channel);
      return;
    }
    if (!isLive(e))
      violated("anariMapFrame mapped a released handle");
    if (e.type != ANARI_FRAME)
      violated("anariMapFrame mapped an object that is not a frame");
    if (e.absurdSize && (width > kMaxFrameSide || height > kMaxFrameSide))
      violated("anariMapFrame: an absurd frame size was allocated");
    if (width == 0 || height == 0 || width > e.largestSide
        || height > e.largestSide)
      violated("anariMapFrame: frame size is not one that was set:", channel);
    const size_t pixelSize = anari::sizeOf(type);
    if (pixelSize == 0 || pixelSize > 16)
      violated("anariMapFrame: invalid pixel type:", channel);
    // Every byte must be readable (ASan checks the buffer's extent).
    unsigned sum = 0;
    const size_t bytes = size_t(width) * height * pixelSize;
    for (size_t i = 0; i < bytes; i++)
      sum += pixels[i];
    m_sink += sum;
    g_counters.framesMapped++;
    if (std::getenv("PRISM_FUZZ_API_VERBOSE")) {
      size_t distinct = 0; // pixels unlike the first: is anything in view?
      for (size_t i = 1; i < size_t(width) * height; i++) {
        distinct += std::memcmp(pixels, pixels + i * pixelSize, pixelSize) != 0;
      }
      std::fprintf(stderr,
          "  frame %s %ux%u %s: %zu pixels unlike the first\n",
          channel,
          width,
          height,
          anari::toString(type),
          distinct);
    }
    call();
    anariUnmapFrame(dev, (ANARIFrame)e.handle, channel);
  }

  void mapFrameOp(Payload &p)
  {
    Entry *e = frameOperand(p);
    static const char *kChannels[] = {"channel.color",
        "channel.depth",
        "channel.normal",
        "channel.albedo",
        "channel.primitiveId",
        "channel.objectId",
        "channel.instanceId",
        "color",
        ""};
    const char *channel = kChannels[p.operand() % 9];
    if (e)
      mapFrame(*e, channel);
  }

  void discardFrame(Payload &p)
  {
    Entry *e = frameOperand(p);
    if (!e)
      return;
    call();
    anariDiscardFrame(deviceOf(*e), (ANARIFrame)e->handle);
  }

  void getProperty(Payload &p)
  {
    const uint8_t objectSelector = p.operand();
    static const char *kNames[] = {"bounds",
        "duration",
        "version",
        "version.name",
        "version.name.size",
        "geometryMaxIndex",
        "extension",
        "raysTraced",
        "refinementProgress",
        "renderProgress",
        "valid",
        "fuzz"};
    static const ANARIDataType kTypes[] = {ANARI_FLOAT32_BOX3,
        ANARI_FLOAT32,
        ANARI_INT32,
        ANARI_STRING,
        ANARI_UINT64,
        ANARI_UINT64,
        ANARI_STRING_LIST,
        ANARI_UINT64,
        ANARI_FLOAT32,
        ANARI_FLOAT32,
        ANARI_BOOL,
        ANARI_UINT32};
    const uint8_t nameIndex = p.operand() % 12;
    const uint8_t typeSelector = p.operand();
    const ANARIDataType type = typeSelector < 128
                                   ? kTypes[nameIndex]
                                   : kAnyTypes[typeSelector % kAnyTypeCount];
    const ANARIWaitMask wait = (p.operand() & 1) ? ANARI_WAIT : ANARI_NO_WAIT;
    const uint8_t sizeSelector = p.operand() % 4;
    ANARIDevice dev;
    ANARIObject object;
    if (objectSelector == 255 || m_entries.empty()) {
      dev = m_devices[0].handle;
      object = (ANARIObject)dev;
    } else {
      Entry *e = entry(objectSelector);
      dev = deviceOf(*e);
      object = e->handle;
    }
    alignas(16) unsigned char buffer[128] = {};
    const uint64_t sizes[] = {sizeof(buffer), 0, 1, sizeof(buffer)};
    void *mem = sizeSelector == 3 ? nullptr : buffer;
    call();
    const int written = anariGetProperty(
        dev, object, kNames[nameIndex], type, mem, sizes[sizeSelector], wait);
    if (written && mem && int(type) == ANARI_STRING_LIST) {
      const char **list;
      std::memcpy(&list, buffer, sizeof(list));
      for (int i = 0; list && list[i] && i < 10000; i++)
        m_sink += std::strlen(list[i]);
    }
  }

  // Reads an introspection answer as the type asked for.
  void consume(const void *answer, ANARIDataType type)
  {
    if (!answer)
      return;
    switch (int(type)) {
    case ANARI_STRING:
      m_sink += std::strlen((const char *)answer);
      break;
    case ANARI_STRING_LIST:
      for (auto *s = (const char *const *)answer; *s; ++s)
        m_sink += std::strlen(*s);
      break;
    case ANARI_DATA_TYPE_LIST:
      for (auto *t = (const ANARIDataType *)answer; *t != ANARI_UNKNOWN; ++t)
        m_sink += int(*t);
      break;
    case ANARI_PARAMETER_LIST:
      for (auto *q = (const ANARIParameter *)answer; q->name; ++q)
        m_sink += std::strlen(q->name) + int(q->type);
      break;
    default: {
      const size_t size = anari::sizeOf(type);
      for (size_t i = 0; i < size; i++)
        m_sink += ((const unsigned char *)answer)[i];
      break;
    }
    }
  }

  void introspect(Payload &p)
  {
    ANARIDevice dev = m_devices[deviceOperand(p.operand())].handle;
    const uint8_t category = p.operand();
    const uint8_t subtypeIndex = p.operand();
    const uint8_t parameterIndex = p.operand();
    const uint8_t info = p.operand();
    const uint8_t infoType = p.operand();
    static const ANARIDataType kExtraTypes[] = {ANARI_DEVICE,
        ANARI_ARRAY1D,
        ANARI_OBJECT,
        ANARI_UNKNOWN,
        ANARI_FLOAT32};
    const ANARIDataType type = category < 240
                                   ? kCategories[category % kCategoryCount]
                                   : kExtraTypes[category % 5];
    call();
    consume(anariGetObjectSubtypes(dev, type), ANARI_STRING_LIST);
    const std::string subtype = subtypeFor(type, subtypeIndex, "");
    const char *s = hasSubtypes(type) ? subtype.c_str() : nullptr;
    static const ANARIDataType kInfoTypes[] = {ANARI_STRING,
        ANARI_PARAMETER_LIST,
        ANARI_STRING_LIST,
        ANARI_DATA_TYPE_LIST,
        ANARI_BOOL,
        ANARI_INT32,
        ANARI_FLOAT32};
    if (parameterIndex < 128) {
      static const char *kInfos[] = {
          "description", "parameter", "channel", "extension", "fuzz", ""};
      // Ask with the type the info has, or (infoType) another.
      static const ANARIDataType kNatural[] = {ANARI_STRING,
          ANARI_PARAMETER_LIST,
          ANARI_STRING_LIST,
          ANARI_STRING_LIST,
          ANARI_STRING,
          ANARI_STRING};
      const int i = info % 6;
      const ANARIDataType asked =
          infoType < 128 ? kNatural[i] : kInfoTypes[infoType % 7];
      call();
      consume(anariGetObjectInfo(dev, type, s, kInfos[i], asked), asked);
      return;
    }
    ParameterInfo fallback;
    fallback.name = "fuzz";
    fallback.type = ANARI_FLOAT32;
    const ParameterInfo *parameter = &fallback;
    if (ANARIDevice live = liveDevice()) {
      const auto &list = g_introspection.parametersOf(
          live, type, hasSubtypes(type) ? subtype : "");
      if (!list.empty())
        parameter = &list[parameterIndex % list.size()];
    }
    static const char *kInfos[] = {"description",
        "required",
        "default",
        "minimum",
        "maximum",
        "elementType",
        "value",
        "extension",
        "fuzz"};
    const int i = info % 9;
    ANARIDataType natural = ANARI_STRING;
    if (i == 1)
      natural = ANARI_BOOL;
    else if (i >= 2 && i <= 4)
      natural = parameter->type;
    else if (i == 5)
      natural = ANARI_DATA_TYPE_LIST;
    else if (i == 6)
      natural = int(parameter->type) == ANARI_DATA_TYPE ? ANARI_DATA_TYPE_LIST
                                                        : ANARI_STRING_LIST;
    const ANARIDataType asked =
        infoType < 128 ? natural : kInfoTypes[infoType % 7];
    call();
    const void *answer = anariGetParameterInfo(dev,
        type,
        s,
        parameter->name.c_str(),
        parameter->type,
        kInfos[i],
        asked);
    // A STRING default points at the characters.
    consume(answer, asked);
  }

  void releaseDevice(Payload &p)
  {
    const int device = deviceOperand(p.operand());
    DeviceSlot &d = m_devices[device];
    call();
    anariRelease(d.handle, (ANARIObject)d.handle);
    d.released = true;
    freeBorrowed(device);
  }

  void setDeviceParameter(Payload &p)
  {
    DeviceSlot &slot = m_devices[deviceOperand(p.operand())];
    ANARIDevice dev = slot.handle;
    call();
    switch (p.operand() % 5) {
    case 0: {
      const ANARIStatusCallback f = checkStatus;
      anariSetParameter(dev, dev, "statusCallback", ANARI_STATUS_CALLBACK, &f);
      slot.silenced = false;
      break;
    }
    case 1: {
      const ANARIStatusCallback f = nullptr;
      anariSetParameter(dev, dev, "statusCallback", ANARI_STATUS_CALLBACK, &f);
      slot.silenced = true;
      break;
    }
    case 2:
      anariSetParameter(
          dev, dev, "statusCallbackUserData", ANARI_VOID_POINTER, &g_counters);
      break;
    case 3: {
      const float f = 1.f;
      anariSetParameter(dev, dev, "fuzz", ANARI_FLOAT32, &f);
      break;
    }
    default:
      anariSetParameter(dev, dev, "name", ANARI_STRING, "fuzz device");
      break;
    }
    call();
    anariCommitParameters(dev, dev);
  }

  // An object array of one element holding `element` (written through a map,
  // so the array exists before its element does when they are the same).
  ANARIObject holderArray(int device, ANARIDataType elementType)
  {
    const uint64_t size[3] = {1, 1, 1};
    ANARIDevice dev = m_devices[device].handle;
    call();
    ANARIObject a =
        anariNewArray1D(dev, nullptr, nullptr, nullptr, elementType, 1);
    Entry &e = add(a, ANARI_ARRAY1D, device);
    e.elementType = elementType;
    e.capacity = a ? size[0] : 0;
    return a;
  }
  void store(int device, ANARIObject array, ANARIObject element)
  {
    ANARIDevice dev = m_devices[device].handle;
    call();
    if (auto *mapped = (ANARIObject *)anariMapArray(dev, (ANARIArray)array))
      mapped[0] = element;
    call();
    anariUnmapArray(dev, (ANARIArray)array);
  }

  void makeCycle(Payload &p)
  {
    const Cycle kind = Cycle(p.operand() % uint8_t(Cycle::Count));
    const uint8_t objectSelector = p.operand();
    if (m_entries.size() + 2 > kMaxObjects)
      return;
    const int device = 0;
    ANARIDevice dev = m_devices[device].handle;
    switch (kind) {
    case Cycle::ArrayHoldsItself: {
      ANARIObject a = holderArray(device, ANARI_ARRAY1D);
      store(device, a, a);
      break;
    }
    case Cycle::ArraysHoldEachOther: {
      ANARIObject a = holderArray(device, ANARI_ARRAY1D);
      ANARIObject b = holderArray(device, ANARI_ARRAY1D);
      store(device, a, b);
      store(device, b, a);
      break;
    }
    case Cycle::GeometryHoldsItsArray: {
      ANARIObject g = create(dev, ANARI_GEOMETRY, "sphere");
      add(g, ANARI_GEOMETRY, device, "sphere");
      ANARIObject a = holderArray(device, ANARI_GEOMETRY);
      store(device, a, g);
      call();
      anariSetParameter(dev, g, "primitive.attribute0", ANARI_ARRAY1D, &a);
      call();
      anariCommitParameters(dev, g);
      break;
    }
    case Cycle::MappedParameterHoldsObject: {
      Entry *e = entry(objectSelector);
      if (!e)
        break;
      ANARIDevice own = deviceOf(*e);
      const ANARIDataType type =
          anari::isObject(e->type) ? e->type : ANARI_OBJECT;
      uint64_t stride = 0;
      call();
      auto *mapped = (ANARIObject *)anariMapParameterArray1D(
          own, e->handle, "fuzz.cycle", type, 1, &stride);
      if (mapped)
        mapped[0] = e->handle;
      call();
      anariUnmapParameterArray(own, e->handle, "fuzz.cycle");
      call();
      anariCommitParameters(own, e->handle);
      break;
    }
    case Cycle::Count:
      break;
    }
  }

  bool hasParameter(const Entry &e, const char *name, ANARIDataType type)
  {
    if (const auto *list = parametersOf(e)) {
      for (const ParameterInfo &info : *list) {
        if (info.name == name && int(info.type) == int(type))
          return true;
      }
    }
    return false;
  }

  void setFloat(Entry &e, const char *name, float v)
  {
    call();
    anariSetParameter(deviceOf(e), e.handle, name, ANARI_FLOAT32, &v);
  }
  void setVec3(Entry &e, const char *name, float x, float y, float z)
  {
    const float v[3] = {x, y, z};
    call();
    anariSetParameter(deviceOf(e), e.handle, name, ANARI_FLOAT32_VEC3, v);
  }
  void setObject(Entry &e, const char *name, ANARIDataType type, ANARIObject h)
  {
    call();
    anariSetParameter(deviceOf(e), e.handle, name, type, &h);
  }
  void commitEntry(Entry &e)
  {
    call();
    anariCommitParameters(deviceOf(e), e.handle);
  }
  size_t addObject(int device, ANARIDataType type, const std::string &subtype)
  {
    ANARIObject h = create(m_devices[device].handle,
        type,
        hasSubtypes(type) ? subtype.c_str() : nullptr);
    add(h, type, device, subtype);
    return m_entries.size() - 1;
  }
  size_t addArray(int device,
      ANARIDataType elementType,
      uint64_t n1,
      uint64_t n2,
      Payload &p)
  {
    const uint64_t size[3] = {n1, n2, 1};
    newArray(device, n2 > 1 ? 2 : 1, elementType, size, p.value(), p, false);
    return m_entries.size() - 1;
  }
  size_t addHolder(int device, ANARIDataType elementType, ANARIObject element)
  {
    const uint64_t size[3] = {1, 1, 1};
    ANARIDevice dev = m_devices[device].handle;
    call();
    ANARIObject a =
        anariNewArray1D(dev, nullptr, nullptr, nullptr, elementType, 1);
    if (a) {
      call();
      if (auto *mapped = (ANARIObject *)anariMapArray(dev, (ANARIArray)a))
        mapped[0] = element;
      call();
      anariUnmapArray(dev, (ANARIArray)a);
    }
    Entry &e = add(a, ANARI_ARRAY1D, device);
    e.elementType = elementType;
    e.capacity = a ? size[0] : 0;
    return m_entries.size() - 1;
  }

  void buildScene(Payload &p)
  {
    const int device = deviceOperand(p.operand());
    ANARIDevice live = liveDevice();
    if (!live || m_entries.size() + kSceneObjects > kMaxObjects)
      return;
    auto pick = [&](ANARIDataType type, uint8_t index) {
      const auto &list = g_introspection.subtypesOf(live, type);
      return list.empty() ? std::string() : list[index % list.size()];
    };
    const std::string geometryType = pick(ANARI_GEOMETRY, p.operand());
    const std::string materialType = pick(ANARI_MATERIAL, p.operand());
    const std::string lightType = pick(ANARI_LIGHT, p.operand());
    const std::string cameraType = pick(ANARI_CAMERA, p.operand());
    const std::string rendererType = pick(ANARI_RENDERER, p.operand());
    const uint8_t flags = p.operand();
    const size_t first = m_entries.size();

    // 12 points: whole triangles, quads, segments and cone pieces.
    const size_t positions = addArray(device, ANARI_FLOAT32_VEC3, 12, 1, p);
    const size_t geometry = addObject(device, ANARI_GEOMETRY, geometryType);
    setObject(m_entries[geometry],
        "vertex.position",
        ANARI_ARRAY1D,
        m_entries[positions].handle);
    if (hasParameter(m_entries[geometry], "radius", ANARI_FLOAT32))
      setFloat(m_entries[geometry], "radius", 0.25f);
    commitEntry(m_entries[geometry]);

    const size_t image = addArray(device, ANARI_UFIXED8_VEC4, 4, 4, p);
    const size_t sampler = addObject(device, ANARI_SAMPLER, "image2D");
    setObject(
        m_entries[sampler], "image", ANARI_ARRAY2D, m_entries[image].handle);
    commitEntry(m_entries[sampler]);

    const size_t material = addObject(device, ANARI_MATERIAL, materialType);
    const char *colorName =
        materialType == "physicallyBased" ? "baseColor" : "color";
    if (flags & kSceneSampler) {
      setObject(m_entries[material],
          colorName,
          ANARI_SAMPLER,
          m_entries[sampler].handle);
    } else {
      setVec3(m_entries[material], colorName, 0.8f, 0.5f, 0.25f);
    }
    commitEntry(m_entries[material]);

    const size_t surface = addObject(device, ANARI_SURFACE, "");
    setObject(m_entries[surface],
        "geometry",
        ANARI_GEOMETRY,
        m_entries[geometry].handle);
    setObject(m_entries[surface],
        "material",
        ANARI_MATERIAL,
        m_entries[material].handle);
    commitEntry(m_entries[surface]);
    const size_t surfaces =
        addHolder(device, ANARI_SURFACE, m_entries[surface].handle);

    const size_t group = addObject(device, ANARI_GROUP, "");
    setObject(
        m_entries[group], "surface", ANARI_ARRAY1D, m_entries[surfaces].handle);
    commitEntry(m_entries[group]);
    const size_t instance = addObject(device, ANARI_INSTANCE, "transform");
    setObject(
        m_entries[instance], "group", ANARI_GROUP, m_entries[group].handle);
    commitEntry(m_entries[instance]);
    const size_t instances =
        addHolder(device, ANARI_INSTANCE, m_entries[instance].handle);

    const size_t light = addObject(device, ANARI_LIGHT, lightType);
    if (hasParameter(m_entries[light], "radiance", ANARI_ARRAY2D)) {
      const uint64_t size[3] = {4, 2, 1};
      ANARIObject radiance =
          newArray(device, 2, ANARI_FLOAT32_VEC3, size, 0, p, false);
      setObject(m_entries[light], "radiance", ANARI_ARRAY2D, radiance);
      // The light holds it; the pool keeps an entry, so the count is fixed.
      m_entries.pop_back();
      call();
      anariRelease(m_devices[device].handle, radiance);
    }
    if (hasParameter(m_entries[light], "position", ANARI_FLOAT32_VEC3))
      setVec3(m_entries[light], "position", 0.5f, 2.f, 3.f);
    commitEntry(m_entries[light]);
    const size_t lights =
        addHolder(device, ANARI_LIGHT, m_entries[light].handle);

    const size_t world = addObject(device, ANARI_WORLD, "");
    if (flags & kSceneInstanced) {
      setObject(m_entries[world],
          "instance",
          ANARI_ARRAY1D,
          m_entries[instances].handle);
    } else {
      setObject(m_entries[world],
          "surface",
          ANARI_ARRAY1D,
          m_entries[surfaces].handle);
    }
    if (!(flags & kSceneNoLight)) {
      setObject(
          m_entries[world], "light", ANARI_ARRAY1D, m_entries[lights].handle);
    }
    commitEntry(m_entries[world]);

    const size_t camera = addObject(device, ANARI_CAMERA, cameraType);
    // Fresh values lie in [0, 1]: the camera looks at that cube.
    setVec3(m_entries[camera], "position", 0.5f, 0.5f, 2.5f);
    commitEntry(m_entries[camera]);
    const size_t renderer = addObject(device, ANARI_RENDERER, rendererType);
    commitEntry(m_entries[renderer]);

    const size_t frame = addObject(device, ANARI_FRAME, "");
    Entry &f = m_entries[frame];
    setObject(f, "world", ANARI_WORLD, m_entries[world].handle);
    setObject(f, "camera", ANARI_CAMERA, m_entries[camera].handle);
    setObject(f, "renderer", ANARI_RENDERER, m_entries[renderer].handle);
    const uint32_t size[2] = {
        1 + p.value() % kMaxFrameSide, 1 + p.value() % kMaxFrameSide};
    f.largestSide = std::max({f.largestSide, size[0], size[1]});
    call();
    anariSetParameter(deviceOf(f), f.handle, "size", ANARI_UINT32_VEC2, size);
    const ANARIDataType color =
        (p.value() & 1) ? ANARI_FLOAT32_VEC4 : ANARI_UFIXED8_RGBA_SRGB;
    const ANARIDataType depth = ANARI_FLOAT32;
    call();
    anariSetParameter(
        deviceOf(f), f.handle, "channel.color", ANARI_DATA_TYPE, &color);
    call();
    anariSetParameter(
        deviceOf(f), f.handle, "channel.depth", ANARI_DATA_TYPE, &depth);
    if (flags & kSceneAccumulate) {
      const bool on = true;
      call();
      anariSetParameter(deviceOf(f), f.handle, "accumulation", ANARI_BOOL, &on);
    }
    commitEntry(f);
    if (m_entries.size() - first != size_t(kSceneObjects))
      violated("BuildScene made the wrong number of pool entries");
    if (flags & kSceneRender) {
      call();
      anariRenderFrame(deviceOf(f), (ANARIFrame)f.handle);
      call();
      anariFrameReady(deviceOf(f), (ANARIFrame)f.handle, ANARI_WAIT);
      mapFrame(f, "channel.color");
    }
  }

  void churn(Payload &p)
  {
    const ANARIDataType type = kCategories[p.operand() % kCategoryCount];
    const int count = p.operand() % 64;
    ANARIDevice dev = m_devices[0].handle;
    const std::string subtype = subtypeFor(type, 0, "");
    for (int i = 0; i < count; i++) {
      ANARIObject h =
          create(dev, type, hasSubtypes(type) ? subtype.c_str() : nullptr);
      call();
      anariRelease(dev, h);
    }
  }

  // The library's entry points: device subtypes and extensions, modules,
  // initialized devices, extension functions.
  void libraryQuery(Payload &p)
  {
    const uint8_t which = p.operand();
    ANARIDevice dev = m_devices[deviceOperand(p.operand())].handle;
    static const char *kNames[] = {"default", "prism", "", "fuzz"};
    const char *name = kNames[p.operand() % 4];
    call();
    switch (which % 5) {
    case 0:
      consume(anariGetDeviceSubtypes(g_library), ANARI_STRING_LIST);
      break;
    case 1:
      consume(anariGetDeviceExtensions(g_library, name), ANARI_STRING_LIST);
      break;
    case 2:
      anariLoadModule(g_library, name);
      call();
      anariUnloadModule(g_library, name);
      break;
    case 3: {
      if (m_devices.size() >= size_t(kMaxDevices))
        break;
      const ANARIStatusCallback callback = checkStatus;
      ANARIParameterValue initializers[] = {
          {"statusCallback", ANARI_STATUS_CALLBACK, &callback},
          {"statusCallbackUserData", ANARI_VOID_POINTER, &g_counters},
          {"fuzz", ANARI_FLOAT32, &kOne},
          {nullptr, ANARI_UNKNOWN, nullptr}};
      ANARIDevice made =
          anariNewInitializedDevice(g_library, name, initializers);
      if (made)
        m_devices.push_back({made, false});
      break;
    }
    default:
      // Prism has no extension functions: every name answers NULL.
      if (anariDeviceGetProcAddress(dev, name))
        violated("anariDeviceGetProcAddress found a function:", name);
      break;
    }
  }

  void sharedThreads(Payload &p)
  {
    Entry *world = entry(p.operand());
    Entry *camera = entry(p.operand());
    Entry *renderer = entry(p.operand());
    const int frames = p.operand() % 4 + 1;
    if (!world || !camera || !renderer || m_devices[world->device].released)
      return;
    ANARIDevice dev = deviceOf(*world);
    const bool holdWorld = isLive(*world);
    std::mutex sharedCalls; // calls naming world, camera or renderer
    std::atomic<uint64_t> sum{0};
    auto work = [&] {
      if (holdWorld) {
        std::lock_guard lock(sharedCalls);
        call();
        anariRetain(dev, world->handle);
      }
      for (int i = 0; i < frames; i++) {
        call();
        ANARIFrame frame = anariNewFrame(dev);
        const uint32_t size[2] = {8, 8};
        const ANARIDataType color = ANARI_FLOAT32_VEC4;
        anariSetParameter(dev, frame, "size", ANARI_UINT32_VEC2, size);
        anariSetParameter(dev, frame, "channel.color", ANARI_DATA_TYPE, &color);
        {
          std::lock_guard lock(sharedCalls);
          anariSetParameter(dev, frame, "world", ANARI_WORLD, &world->handle);
          anariSetParameter(
              dev, frame, "camera", ANARI_CAMERA, &camera->handle);
          anariSetParameter(
              dev, frame, "renderer", ANARI_RENDERER, &renderer->handle);
        }
        anariCommitParameters(dev, frame);
        anariRenderFrame(dev, frame);
        anariFrameReady(dev, frame, ANARI_WAIT);
        uint32_t width = 0, height = 0;
        ANARIDataType type = ANARI_UNKNOWN;
        auto *pixels = (const unsigned char *)anariMapFrame(
            dev, frame, "channel.color", &width, &height, &type);
        if (pixels) {
          if (width > 8 || height > 8 || anari::sizeOf(type) != 16)
            violated("anariMapFrame (SharedThreads): not the frame set up");
          uint64_t frameSum = 0; // every byte readable (ASan)
          for (size_t b = 0; b < size_t(width) * height * 16; b++)
            frameSum += pixels[b];
          sum += frameSum;
          g_counters.framesMapped++;
        }
        anariUnmapFrame(dev, frame, "channel.color");
        anariRelease(dev, frame);
      }
      if (holdWorld) {
        std::lock_guard lock(sharedCalls);
        call();
        anariRelease(dev, world->handle);
      }
    };
    std::thread other(work);
    work();
    other.join();
    m_sink += sum;
  }

  void waitAll()
  {
    for (Entry &e : m_entries) {
      if (e.type == ANARI_FRAME && isLive(e)) {
        call();
        anariFrameReady(deviceOf(e), (ANARIFrame)e.handle, ANARI_WAIT);
      }
    }
  }

  void finish(uint8_t flags)
  {
    if (!(flags & kNoFinalWait))
      waitAll();
    if (!(flags & kLeaveObjectsToDevice)) {
      for (auto it = m_entries.rbegin(); it != m_entries.rend(); ++it) {
        while (isLive(*it))
          dropReference(*it);
      }
    }
    for (size_t i = 0; i < m_devices.size(); i++) {
      DeviceSlot &d = m_devices[i];
      if (!d.released) {
        call();
        anariRelease(d.handle, (ANARIObject)d.handle);
        d.released = true;
      }
      freeBorrowed(int(i));
    }
    // Every device is gone: every deleter must have run, exactly once.
    if (g_sharedLive != 0)
      violated("a shared array's deleter did not run by device release");
  }

  std::vector<DeviceSlot> m_devices;
  std::vector<Entry> m_entries;
  uint64_t m_sink = 0; // keeps reads of returned data from being optimised out
};

} // namespace

void loadDeviceLibrary()
{
  if (g_library)
    return;
  // Messages of libanari and of every device go to checkStatus.
  g_library = anariLoadLibrary("prism", checkStatus, &g_counters);
  if (!g_library)
    violated("anariLoadLibrary(\"prism\") failed");
}

void runProgram(const uint8_t *data, size_t size)
{
  loadDeviceLibrary();
  g_counters.programs++;
  Interpreter interpreter;
  interpreter.run(data, size);
}

RunStatistics statistics()
{
  RunStatistics s;
  s.programs = g_counters.programs;
  s.calls = g_counters.calls;
  s.messages = g_counters.messages;
  s.errors = g_counters.errors;
  s.framesCompleted = g_counters.framesCompleted;
  s.framesMapped = g_counters.framesMapped;
  return s;
}

} // namespace prism::fuzz
