#include "Replayer.h"

#include "ImageIO.h"
#include "MachineLimits.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

namespace prism::replay {
namespace {

// No property is larger than a few values: a trace asking more is not one
// the layer wrote.
constexpr uint64_t kMaxPropertyBytes = 1 << 20;

// `userPtr`: the replay's Options.
void printStatus(const void *userPtr,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  const auto *options = (const Options *)userPtr;
  if (options->printMessages && severity <= ANARI_SEVERITY_WARNING)
    std::fprintf(stderr, "anari-replay: device: %s\n", message);
}

// The layer's own messages name the call: "anariSetParameter(...): ...";
// the wrapped device's are left aside.
bool fromLayer(const char *text)
{
  if (std::strncmp(text, "anari", 5) != 0)
    return false;
  size_t i = 5;
  while (std::isalnum((unsigned char)text[i]))
    ++i;
  return i > 5 && text[i] == '(';
}

// Warnings and errors are compared; performance warnings (a frame mapped
// while it may still render) depend on timing.
bool isProblem(const std::string &severity)
{
  return severity == "FATAL_ERROR" || severity == "ERROR"
         || severity == "WARNING";
}

// A message less its ", trace line N": where the recording's trace had an
// object created, which the replay (writing no trace) does not say.
std::string withoutTraceLine(std::string text)
{
  const std::string mark = ", trace line ";
  for (size_t at = text.find(mark); at != std::string::npos;
       at = text.find(mark, at)) {
    size_t end = at + mark.size();
    while (end < text.size() && std::isdigit((unsigned char)text[end]))
      ++end;
    text.erase(at, end - at);
  }
  return text;
}

bool isWord(const trace::Token &t, const char *text = nullptr)
{
  return t.kind == trace::Token::kWord && (!text || t.text == text);
}

} // namespace

void Replayer::collectStatus(const void *userPtr,
    ANARIDevice device,
    ANARIObject source,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message)
{
  auto *self = (Replayer *)userPtr;
  if (message && fromLayer(message)) {
    if (severity > ANARI_SEVERITY_WARNING)
      return; // not a problem (isProblem)
    std::lock_guard lock(self->m_reportsMutex);
    self->m_replayedReports.push_back(
        trace::reportLine(severity, code, message));
  } else {
    printStatus(
        &self->m_options, device, source, sourceType, severity, code, message);
  }
}

void Replayer::compareReports()
{
  std::lock_guard lock(m_reportsMutex);
  m_summary.reportsRecorded = m_recordedReports.size();
  m_summary.reportsReplayed = m_replayedReports.size();
  const size_t n = std::max(m_recordedReports.size(), m_replayedReports.size());
  for (size_t i = 0; i < n; ++i) {
    const char *recorded =
        i < m_recordedReports.size() ? m_recordedReports[i].c_str() : "none";
    const char *replayed =
        i < m_replayedReports.size() ? m_replayedReports[i].c_str() : "none";
    if (std::strcmp(recorded, replayed) != 0) {
      m_summary.reportsDifference = "report " + std::to_string(i + 1)
                                    + ": recorded " + recorded + "\n  replayed "
                                    + replayed;
      return;
    }
  }
}

Replayer::Replayer(Options options) : m_options(std::move(options)) {}

Replayer::~Replayer()
{
  if (m_device)
    anariRelease(m_device, m_device);
  if (m_library)
    anariUnloadLibrary(m_library);
}

bool Replayer::fail(const std::string &message)
{
  m_error = message;
  return false;
}

bool Replayer::run()
{
  std::ifstream text(m_options.tracePath);
  if (!text)
    return fail("cannot read " + m_options.tracePath);
  std::ifstream data(m_options.tracePath + ".bin", std::ios::binary);
  if (data) {
    m_data.assign(
        std::istreambuf_iterator<char>(data), std::istreambuf_iterator<char>());
  }
  std::string line;
  Tokens tokens;
  for (int number = 1; std::getline(text, line); ++number) {
    std::string error;
    if (!trace::tokenize(line, tokens, error))
      return fail("line " + std::to_string(number) + ": " + error);
    if (tokens.empty())
      continue;
    if (!call(tokens)) {
      m_error = "line " + std::to_string(number) + ": " + m_error;
      return false;
    }
    // Reports are not calls, nor refused calls left out.
    if (tokens[0].text != "Report"
        && (tokens[0].text != "Refused" || m_options.checkReports))
      ++m_summary.calls;
  }
  if (m_options.checkReports)
    compareReports();
  return true;
}

bool Replayer::call(const Tokens &t)
{
  if (!isWord(t[0]))
    return fail("a line starts with a keyword");
  const std::string &keyword = t[0].text;
  if (keyword == "Report") {
    // Kept as the layer would write it again, to compare.
    if (t.size() != 4 || !isWord(t[1]) || !isWord(t[2])
        || t[3].kind != trace::Token::kString)
      return fail("Report: severity, code, message expected");
    if (m_options.checkReports && isProblem(t[1].text)) {
      m_recordedReports.push_back("Report " + t[1].text + " " + t[2].text + " "
                                  + trace::quote(withoutTraceLine(t[3].text)));
    }
    return true;
  }
  if (keyword == "Refused") {
    // A call the layer did not forward: only the layer can take it again.
    if (t.size() < 2)
      return fail("Refused: a call expected");
    return !m_options.checkReports || call(Tokens(t.begin() + 1, t.end()));
  }
  if (keyword == "Device")
    return startDevice(t);
  if (!m_device)
    return fail("'" + keyword + "' before 'Device'");
  if (keyword == "New" || keyword == "NewObject")
    return newObject(t);
  if (keyword == "Array")
    return newArray(t);
  if (keyword == "MapArray")
    return mapArray(t);
  if (keyword == "ArrayData")
    return arrayData(t);
  if (keyword == "Set")
    return setParameter(t);
  if (keyword == "MapParameterArray" || keyword == "ParameterArray")
    return parameterArray(t);
  if (keyword == "Map")
    return mapFrame(t);
  if (keyword == "Property")
    return property(t);

  ANARIObject o = nullptr;
  if (t.size() < 2 || !object(t[1], o))
    return fail(m_error.empty() ? keyword + ": an object expected" : m_error);
  if (keyword == "Release" && o == (ANARIObject)m_device) {
    anariRelease(m_device, m_device);
    m_device = nullptr;
    return true;
  }
  if (keyword == "Release" || keyword == "Retain")
    referenced(t[1].text, keyword == "Release" ? -1 : 1);
  if (keyword == "Commit") {
    anariCommitParameters(m_device, o);
  } else if (keyword == "Release") {
    anariRelease(m_device, o);
  } else if (keyword == "Retain") {
    anariRetain(m_device, o);
  } else if (keyword == "UnsetAll") {
    anariUnsetAllParameters(m_device, o);
  } else if (keyword == "Unset" && t.size() == 3) {
    anariUnsetParameter(m_device, o, t[2].text.c_str());
  } else if (keyword == "Render") {
    if (m_options.renderFrames)
      anariRenderFrame(m_device, (ANARIFrame)o);
  } else if (keyword == "Ready" && t.size() == 3) {
    anariFrameReady(m_device,
        (ANARIFrame)o,
        t[2].text == "WAIT" ? ANARI_WAIT : ANARI_NO_WAIT);
  } else if (keyword == "Discard") {
    anariDiscardFrame(m_device, (ANARIFrame)o);
  } else if (keyword == "UnmapArray") {
    anariUnmapArray(m_device, (ANARIArray)o);
  } else if (keyword == "Unmap" && t.size() == 3) {
    anariUnmapFrame(m_device, (ANARIFrame)o, t[2].text.c_str());
  } else if (keyword == "UnmapParameterArray" && t.size() == 3) {
    anariUnmapParameterArray(m_device, o, t[2].text.c_str());
  } else {
    return fail("unknown call '" + keyword + "'");
  }
  return true;
}

bool Replayer::startDevice(const Tokens &t)
{
  if (m_deviceStarted)
    return fail("a second 'Device'");
  if (t.size() < 2 || t[1].kind != trace::Token::kString)
    return fail("Device: a subtype expected");
  std::string library = m_options.library;
  if (library.empty())
    library = t.size() > 2 ? t[2].text : "prism";
  if (m_options.checkReports) {
    // The layer around the library, reporting as when it was recorded.
    setenv("ANARI_DEBUG_WRAPPED_LIBRARY", library.c_str(), 1);
    library = "debug";
    m_library = anariLoadLibrary(library.c_str(), collectStatus, this);
  } else {
    m_library = anariLoadLibrary(library.c_str(), printStatus, &m_options);
  }
  if (!m_library)
    return fail("cannot load library '" + library + "'");
  m_device = anariNewDevice(m_library, t[1].text.c_str());
  if (!m_device)
    return fail("library '" + library + "' made no device");
  m_deviceStarted = true;
  m_objects["device"] = (ANARIObject)m_device;
  m_objects["null"] = nullptr;
  // A handle the layer never made; NULL for a library without the layer
  // (which the layer would have given NULL too, as an object array's
  // element).
  m_objects["foreign"] =
      m_options.checkReports ? (ANARIObject)uintptr_t(0xf0f0f0f0) : nullptr;
  return true;
}

bool Replayer::object(const trace::Token &token, ANARIObject &out, bool inArray)
{
  auto it = m_objects.find(token.text);
  if (!isWord(token) || it == m_objects.end())
    return fail("unknown object '" + token.text + "'");
  // The layer checks handles (and reports a released one); a library
  // without it would use freed memory.
  if (!m_options.checkReports && !inArray && m_released.count(token.text))
    return fail("'" + token.text + "' used after its release");
  out = it->second;
  return true;
}

void Replayer::referenced(const std::string &name, int change)
{
  auto count = m_references.find(name);
  if (count == m_references.end())
    return; // the device, null, foreign or a refused creation
  count->second += change;
  if (count->second > 0)
    return;
  m_released[name] = true;
  m_mappedArrays.erase(name);
  const std::string prefix = name + " ";
  for (auto it = m_mappedParameters.begin(); it != m_mappedParameters.end();) {
    if (it->first.compare(0, prefix.size(), prefix) == 0)
      it = m_mappedParameters.erase(it);
    else
      ++it;
  }
}

bool Replayer::type(const trace::Token &token, ANARIDataType &out)
{
  if (isWord(token) && trace::typeFromName(token.text, out))
    return true;
  return fail("unknown data type '" + token.text + "'");
}

bool Replayer::number(const trace::Token &token, uint64_t &out)
{
  const bool digits = isWord(token) && !token.text.empty()
                      && std::all_of(token.text.begin(),
                          token.text.end(),
                          [](char c) { return c >= '0' && c <= '9'; });
  errno = 0;
  out = digits ? std::strtoull(token.text.c_str(), nullptr, 10) : 0;
  if (digits && errno != ERANGE)
    return true;
  return fail("a number expected, not '" + token.text + "'");
}

bool Replayer::dimensions(const Tokens &t, size_t at, uint64_t items[3])
{
  if (t.size() < at + 5 || t[at].kind != trace::Token::kOpen
      || t[at + 4].kind != trace::Token::kClose)
    return fail("[n1 n2 n3] expected");
  for (int i = 0; i < 3; ++i) {
    if (!number(t[at + 1 + i], items[i]))
      return false;
  }
  return true;
}

bool Replayer::arrayBytes(ANARIDataType arrayType,
    ANARIDataType elementType,
    const uint64_t items[3],
    uint64_t &bytes)
{
  const int dimensions = arrayType == ANARI_ARRAY1D   ? 1
                         : arrayType == ANARI_ARRAY2D ? 2
                         : arrayType == ANARI_ARRAY3D ? 3
                                                      : 0;
  if (!dimensions)
    return fail("an ARRAY1D, ARRAY2D or ARRAY3D expected, not "
                + trace::typeName(arrayType));
  if (!limits::checkedBytes(
          items, dimensions, anari::sizeOf(elementType), bytes))
    return fail("the array's size overflows 64 bits");
  if (m_options.maxArrayBytes && bytes > m_options.maxArrayBytes) {
    return fail("an array of " + limits::byteSize(bytes) + ", more than the "
                + limits::byteSize(m_options.maxArrayBytes) + " allowed");
  }
  return true;
}

bool Replayer::keepArrayMemory(
    std::vector<unsigned char> &bytes, const void *&memory)
{
  // Each line may name the same block of the side file again: what the
  // replay holds must still fit the machine.
  if (!limits::fitsInMemory(m_arrayMemoryBytes + bytes.size()))
    return fail("the trace's shared arrays need more than "
                + limits::memoryLimitText());
  m_arrayMemoryBytes += bytes.size();
  m_arrayMemory.push_back(std::move(bytes));
  memory = m_arrayMemory.back().data();
  return true;
}

bool Replayer::contents(const Tokens &t,
    size_t at,
    ANARIDataType elementType,
    std::vector<unsigned char> &bytes,
    bool &none)
{
  none = false;
  bytes.clear();
  if (at >= t.size())
    return fail("array contents expected");
  if (isWord(t[at], "-")) {
    none = true;
    return true;
  }
  if (t[at].kind == trace::Token::kOpen) {
    for (size_t i = at + 1; i < t.size() && t[i].kind != trace::Token::kClose;
         ++i) {
      ANARIObject handle = nullptr;
      if (!object(t[i], handle, true))
        return false;
      auto *p = (const unsigned char *)&handle;
      bytes.insert(bytes.end(), p, p + sizeof(handle));
    }
    return true;
  }
  uint64_t offset = 0, size = 0;
  if (!isWord(t[at]) || t[at].text[0] != '@'
      || std::sscanf(t[at].text.c_str(),
             "@%llu:%llu",
             (unsigned long long *)&offset,
             (unsigned long long *)&size)
             != 2)
    return fail("'@offset:size' expected, not '" + t[at].text + "'");
  if (offset > m_data.size() || size > m_data.size() - offset)
    return fail(t[at].text + " lies past the end of the side file");
  (void)elementType;
  bytes.assign(m_data.begin() + offset, m_data.begin() + offset + size);
  return true;
}

bool Replayer::newObject(const Tokens &t)
{
  if (t.size() < 3 || !isWord(t[1]))
    return fail("New: a name and a type expected");
  const char *subtype = t.size() > 3 ? t[3].text.c_str() : nullptr;
  ANARIObject o = nullptr;
  if (t[0].text == "NewObject") {
    o = anariNewObject(m_device, t[2].text.c_str(), subtype ? subtype : "");
    name(t[1], o);
    return true;
  }
  ANARIDataType objectType;
  if (!type(t[2], objectType))
    return false;
  switch (int(objectType)) {
  case ANARI_GEOMETRY:
    o = anariNewGeometry(m_device, subtype);
    break;
  case ANARI_MATERIAL:
    o = anariNewMaterial(m_device, subtype);
    break;
  case ANARI_SAMPLER:
    o = anariNewSampler(m_device, subtype);
    break;
  case ANARI_SURFACE:
    o = anariNewSurface(m_device);
    break;
  case ANARI_SPATIAL_FIELD:
    o = anariNewSpatialField(m_device, subtype);
    break;
  case ANARI_VOLUME:
    o = anariNewVolume(m_device, subtype);
    break;
  case ANARI_LIGHT:
    o = anariNewLight(m_device, subtype);
    break;
  case ANARI_GROUP:
    o = anariNewGroup(m_device);
    break;
  case ANARI_INSTANCE:
    o = anariNewInstance(m_device, subtype);
    break;
  case ANARI_WORLD:
    o = anariNewWorld(m_device);
    break;
  case ANARI_CAMERA:
    o = anariNewCamera(m_device, subtype);
    break;
  case ANARI_RENDERER:
    o = anariNewRenderer(m_device, subtype);
    break;
  case ANARI_FRAME:
    o = anariNewFrame(m_device);
    break;
  default:
    return fail("New: no object of type " + t[2].text);
  }
  name(t[1], o);
  return true;
}

bool Replayer::newArray(const Tokens &t)
{
  ANARIDataType arrayType, elementType;
  uint64_t items[3];
  if (t.size() < 9 || !isWord(t[1]))
    return fail("Array: name, type, element type, [n1 n2 n3], data expected");
  std::vector<unsigned char> bytes;
  bool none = false;
  uint64_t needed = 0;
  if (!type(t[2], arrayType) || !type(t[3], elementType)
      || !dimensions(t, 4, items)
      || !arrayBytes(arrayType, elementType, items, needed)
      || !contents(t, 9, elementType, bytes, none))
    return false;
  // The device (and the layer) read the whole array from this memory.
  if (!none && bytes.size() < needed) {
    return fail("Array " + t[1].text + ": its " + std::to_string(needed)
                + " bytes of items are more than its data's "
                + std::to_string(bytes.size()));
  }
  const void *memory = nullptr;
  if (!none && !keepArrayMemory(bytes, memory))
    return false;
  ANARIObject o = nullptr;
  if (arrayType == ANARI_ARRAY1D) {
    o = anariNewArray1D(
        m_device, memory, nullptr, nullptr, elementType, items[0]);
  } else if (arrayType == ANARI_ARRAY2D) {
    o = anariNewArray2D(
        m_device, memory, nullptr, nullptr, elementType, items[0], items[1]);
  } else {
    o = anariNewArray3D(m_device,
        memory,
        nullptr,
        nullptr,
        elementType,
        items[0],
        items[1],
        items[2]);
  }
  name(t[1], o);
  if (o)
    m_arrayBytes[t[1].text] = needed;
  return true;
}

void Replayer::name(const trace::Token &token, ANARIObject o)
{
  // `-`: a creation the layer refused, which made no object to name.
  if (token.text == "-")
    return;
  m_objects[token.text] = o;
  m_released.erase(token.text);
  if (o)
    m_references[token.text] = 1;
  else
    m_references.erase(token.text);
}

bool Replayer::mapArray(const Tokens &t)
{
  ANARIObject array = nullptr;
  if (t.size() != 2 || !object(t[1], array))
    return fail(m_error.empty() ? "MapArray: an array expected" : m_error);
  void *memory = anariMapArray(m_device, (ANARIArray)array);
  if (memory)
    m_mappedArrays.emplace(t[1].text, memory); // a second map keeps the first
  return true;
}

bool Replayer::arrayData(const Tokens &t)
{
  ANARIObject array = nullptr;
  std::vector<unsigned char> bytes;
  bool none = false;
  if (t.size() < 3 || !object(t[1], array)
      || !contents(t, 2, ANARI_UNKNOWN, bytes, none))
    return false;
  auto shape = m_arrayBytes.find(t[1].text);
  if (shape == m_arrayBytes.end() && !m_options.checkReports)
    return fail("ArrayData: '" + t[1].text + "' is no array");
  const uint64_t capacity = shape == m_arrayBytes.end() ? 0 : shape->second;
  if (!none && bytes.size() > capacity) {
    return fail("ArrayData " + t[1].text + ": " + std::to_string(bytes.size())
                + " bytes of data for an array of " + std::to_string(capacity));
  }
  // Mapped by its `MapArray` line, or (traces without one) now.
  void *memory = nullptr;
  auto mapped = m_mappedArrays.find(t[1].text);
  if (mapped != m_mappedArrays.end()) {
    memory = mapped->second;
    m_mappedArrays.erase(mapped);
  } else {
    memory = anariMapArray(m_device, (ANARIArray)array);
  }
  if (memory && !bytes.empty()) // an empty vector's data() may be null
    std::memcpy(memory, bytes.data(), bytes.size());
  anariUnmapArray(m_device, (ANARIArray)array);
  return true;
}

bool Replayer::setParameter(const Tokens &t)
{
  ANARIObject o = nullptr;
  ANARIDataType valueType;
  if (t.size() < 5 || !object(t[1], o) || t[2].kind != trace::Token::kString
      || !type(t[3], valueType))
    return fail(
        m_error.empty() ? "Set: object, name, type, value expected" : m_error);
  const char *name = t[2].text.c_str();
  if (valueType == ANARI_STRING) {
    anariSetParameter(m_device, o, name, valueType, t[4].text.c_str());
    return true;
  }
  if (anari::isObject(valueType)) {
    ANARIObject value = nullptr;
    if (!object(t[4], value))
      return false;
    anariSetParameter(m_device, o, name, valueType, &value);
    return true;
  }
  if (valueType == ANARI_DATA_TYPE) {
    ANARIDataType value;
    if (!type(t[4], value))
      return false;
    anariSetParameter(m_device, o, name, valueType, &value);
    return true;
  }
  std::vector<std::string> components;
  if (t[4].kind != trace::Token::kOpen)
    return fail("Set: a value list expected");
  for (size_t i = 5; i < t.size() && t[i].kind != trace::Token::kClose; ++i)
    components.push_back(t[i].text);
  std::vector<unsigned char> bytes;
  if (!trace::decodeValue(valueType, components, bytes))
    return fail("Set: the value does not fit " + t[3].text);
  anariSetParameter(m_device, o, name, valueType, bytes.data());
  return true;
}

bool Replayer::parameterArray(const Tokens &t)
{
  ANARIObject o = nullptr;
  ANARIDataType arrayType, elementType;
  uint64_t items[3];
  std::vector<unsigned char> bytes;
  bool none = false;
  // `MapParameterArray` maps (a later `ParameterArray` writes and unmaps);
  // `ParameterArray` alone (traces without the map's line) does both.
  const bool mapOnly = t[0].text == "MapParameterArray";
  if (t.size() < (mapOnly ? 10 : 11) || !object(t[1], o)
      || !type(t[3], arrayType) || !type(t[4], elementType)
      || !dimensions(t, 5, items)
      || (!mapOnly && !contents(t, 10, elementType, bytes, none)))
    return fail(m_error.empty() ? t[0].text + ": operands expected" : m_error);
  uint64_t needed = 0;
  if (!arrayBytes(arrayType, elementType, items, needed))
    return false;
  const uint64_t size = anari::sizeOf(elementType);
  uint64_t mappedItems = size ? needed / size : 0;
  const char *name = t[2].text.c_str();
  const std::string key = t[1].text + " " + trace::quote(t[2].text);
  uint64_t stride = 0;
  void *memory = nullptr;
  auto mapped = m_mappedParameters.find(key);
  if (!mapOnly && mapped != m_mappedParameters.end()) {
    memory = mapped->second.memory;
    stride = mapped->second.stride;
    mappedItems = mapped->second.items; // what the device made room for
    m_mappedParameters.erase(mapped);
  } else if (arrayType == ANARI_ARRAY1D) {
    memory = anariMapParameterArray1D(
        m_device, o, name, elementType, items[0], &stride);
  } else if (arrayType == ANARI_ARRAY2D) {
    memory = anariMapParameterArray2D(
        m_device, o, name, elementType, items[0], items[1], &stride);
  } else {
    memory = anariMapParameterArray3D(
        m_device, o, name, elementType, items[0], items[1], items[2], &stride);
  }
  if (!memory)
    return true; // the device refused, as it did (or not) when recorded
  if (mapOnly) {
    m_mappedParameters.emplace(
        key, MappedParameter{memory, stride, mappedItems});
    return true;
  }
  if (size && bytes.size() / size > mappedItems) {
    anariUnmapParameterArray(m_device, o, name);
    return fail(t[0].text + ": " + std::to_string(bytes.size() / size)
                + " items of data for " + std::to_string(mappedItems)
                + " mapped");
  }
  const uint64_t step = stride ? stride : size;
  for (uint64_t i = 0; size && (i + 1) * size <= bytes.size(); ++i)
    std::memcpy((char *)memory + i * step, bytes.data() + i * size, size);
  anariUnmapParameterArray(m_device, o, name);
  return true;
}

bool Replayer::mapFrame(const Tokens &t)
{
  ANARIObject frame = nullptr;
  uint64_t width = 0, height = 0;
  ANARIDataType recordedType;
  if (t.size() == 3 && object(t[1], frame)) {
    // A map the layer refused: no image to compare.
    uint32_t w = 0, h = 0;
    ANARIDataType pixelType = ANARI_UNKNOWN;
    anariMapFrame(
        m_device, (ANARIFrame)frame, t[2].text.c_str(), &w, &h, &pixelType);
    return true;
  }
  if (t.size() < 7 || !object(t[1], frame) || !number(t[3], width)
      || !number(t[4], height) || !type(t[5], recordedType))
    return fail(
        m_error.empty() ? "Map: frame, channel, size, type, hash" : m_error);
  uint32_t w = 0, h = 0;
  ANARIDataType pixelType = ANARI_UNKNOWN;
  const void *pixels = anariMapFrame(
      m_device, (ANARIFrame)frame, t[2].text.c_str(), &w, &h, &pixelType);
  bool same = pixels && w == width && h == height && pixelType == recordedType;
  if (same) {
    const uint64_t bytes = uint64_t(w) * h * anari::sizeOf(pixelType);
    same = trace::hashName(trace::hashBytes(pixels, bytes)) == t[6].text;
  }
  if (same) {
    ++m_summary.framesSame;
  } else {
    ++m_summary.framesDifferent;
    if (m_options.printMessages)
      std::fprintf(stderr,
          "anari-replay: %s '%s' differs from the recorded image\n",
          t[1].text.c_str(),
          t[2].text.c_str());
  }
  if (pixels && !m_options.frameDirectory.empty())
    return writeFrame(t[1].text, t[2].text, pixels, w, h, pixelType);
  // The trace unmaps it on its own line.
  return true;
}

bool Replayer::writeFrame(const std::string &frame,
    const std::string &channel,
    const void *pixels,
    uint32_t width,
    uint32_t height,
    ANARIDataType type)
{
  char prefix[32];
  std::snprintf(prefix, sizeof(prefix), "%04d-", ++m_framesWritten);
  const std::string base =
      m_options.frameDirectory + "/" + prefix + frame + "-" + channel;
  // The channel's bytes as the device gave them, and colors as an image.
  const uint64_t bytes = uint64_t(width) * height * anari::sizeOf(type);
  FILE *raw = std::fopen((base + ".raw").c_str(), "wb");
  const bool wrote = raw && std::fwrite(pixels, 1, bytes, raw) == bytes;
  if (raw && std::fclose(raw) != 0)
    return fail("--write-frames: cannot write '" + base + ".raw'");
  if (!wrote)
    return fail("--write-frames: cannot write '" + base + ".raw'");
  if (type == ANARI_FLOAT32_VEC4) {
    image::Image out(width, height);
    std::memcpy(out.pixels.data(), pixels, bytes);
    auto written = image::write(base + ".exr", out);
    if (!written.ok())
      return fail("--write-frames: " + written.error);
  }
  return true;
}

bool Replayer::property(const Tokens &t)
{
  ANARIObject o = nullptr;
  ANARIDataType valueType;
  uint64_t size = 0;
  if (t.size() < 6 || !object(t[1], o) || !type(t[3], valueType)
      || !number(t[4], size))
    return fail(
        m_error.empty() ? "Property: object, name, type, size" : m_error);
  if (size > kMaxPropertyBytes) {
    return fail("Property: a size of " + std::to_string(size)
                + " bytes is more than any property's ("
                + limits::byteSize(kMaxPropertyBytes) + ")");
  }
  std::vector<unsigned char> memory(size_t(size) + 1);
  anariGetProperty(m_device,
      o,
      t[2].text.c_str(),
      valueType,
      memory.data(),
      size,
      t[5].text == "WAIT" ? ANARI_WAIT : ANARI_NO_WAIT);
  return true;
}

} // namespace prism::replay
