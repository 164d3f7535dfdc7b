// Replays a trace written by the debug layer (docs/debug-layer.md) on any
// ANARI library through libanari: each line becomes the call it records.
#pragma once

#include "trace/TraceFormat.h"

#include <anari/anari.h>

#include <list>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace prism::replay {

struct Options
{
  std::string tracePath;
  std::string library;        // empty: the library the trace recorded
  std::string frameDirectory; // empty: frames are not written
  // Replays through the debug layer wrapped around the library, with the
  // calls it refused, and compares its reports with the recorded ones.
  bool checkReports = false;
  // What a fuzzer needs to keep each input cheap: `Render` lines skipped
  // (frames map empty and count as different), arrays larger than
  // `maxArrayBytes` refused (0: the machine's memory), nothing printed
  // (device messages, frames that differ).
  bool renderFrames = true;
  uint64_t maxArrayBytes = 0;
  bool printMessages = true;
};

struct Summary
{
  uint64_t calls = 0;
  int framesSame = 0;
  int framesDifferent = 0;
  // With checkReports: the layer's reports, recorded and replayed, and the
  // first difference ("" if the same, in the same order).
  uint64_t reportsRecorded = 0;
  uint64_t reportsReplayed = 0;
  std::string reportsDifference;
};

class Replayer
{
 public:
  explicit Replayer(Options options);
  ~Replayer();
  // Replays the whole trace; false (and error()) if it cannot be read or a
  // line makes no sense. Frames that differ are counted, not errors.
  bool run();
  const std::string &error() const
  {
    return m_error;
  }
  const Summary &summary() const
  {
    return m_summary;
  }

 private:
  using Tokens = std::vector<trace::Token>;
  bool call(const Tokens &tokens);
  bool startDevice(const Tokens &t);
  bool newObject(const Tokens &t);
  bool newArray(const Tokens &t);
  bool setParameter(const Tokens &t);
  bool parameterArray(const Tokens &t);
  bool mapArray(const Tokens &t);
  bool arrayData(const Tokens &t);
  bool mapFrame(const Tokens &t);
  bool property(const Tokens &t);
  // False (and the replay fails) when the files cannot be written.
  bool writeFrame(const std::string &frame,
      const std::string &channel,
      const void *pixels,
      uint32_t width,
      uint32_t height,
      ANARIDataType type);

  // Operand helpers; each sets m_error and returns false on a bad operand.
  // `inArray`: an object array's element, which may name an object the
  // application released (the array still holds it; the device checks).
  bool object(
      const trace::Token &token, ANARIObject &out, bool inArray = false);
  bool type(const trace::Token &token, ANARIDataType &out);
  bool number(const trace::Token &token, uint64_t &out);
  bool dimensions(const Tokens &t, size_t at, uint64_t items[3]);
  // The bytes of an array of `arrayType` (ARRAY1D..3D) with `items` of
  // `elementType`, checked for overflow.
  bool arrayBytes(ANARIDataType arrayType,
      ANARIDataType elementType,
      const uint64_t items[3],
      uint64_t &bytes);
  // Keeps `bytes` as the memory of a shared array, within the machine's
  // memory for all of them.
  bool keepArrayMemory(std::vector<unsigned char> &bytes, const void *&memory);
  // Counts the application's references to the object named `name`; at
  // zero, its mappings are forgotten and (without checkReports, where the
  // layer checks handles) the name is no longer usable.
  void referenced(const std::string &name, int change);
  // Bytes of an operand at t[at] ("@offset:size", "-" or a list of object
  // names); `next` receives the index after it.
  bool contents(const Tokens &t,
      size_t at,
      ANARIDataType elementType,
      std::vector<unsigned char> &bytes,
      bool &none);
  bool fail(const std::string &message);
  // Names the object a creation line made (`-`: none).
  void name(const trace::Token &token, ANARIObject o);
  static void collectStatus(const void *userPtr,
      ANARIDevice device,
      ANARIObject source,
      ANARIDataType sourceType,
      ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const char *message);
  void compareReports();

  Options m_options;
  std::string m_error;
  Summary m_summary;
  std::vector<unsigned char> m_data; // the side file
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  std::unordered_map<std::string, ANARIObject> m_objects;
  bool m_deviceStarted{false};
  // The application's references to each named object, and the names
  // released (a handle the device has freed).
  std::unordered_map<std::string, int64_t> m_references;
  std::unordered_map<std::string, bool> m_released;
  // Each array's size in bytes, by name: no data line writes past it.
  std::unordered_map<std::string, uint64_t> m_arrayBytes;
  uint64_t m_arrayMemoryBytes{0};
  // Memory of shared arrays, alive as long as the replay (the device may
  // read it until the array is gone).
  std::list<std::vector<unsigned char>> m_arrayMemory;
  // Arrays and parameter arrays ("o1 \"name\"") mapped by their own line,
  // until the line that writes their data and unmaps them; parameter
  // arrays with the device's stride.
  std::unordered_map<std::string, void *> m_mappedArrays;
  struct MappedParameter
  {
    void *memory;
    uint64_t stride;
    uint64_t items; // elements the device mapped
  };
  std::unordered_map<std::string, MappedParameter> m_mappedParameters;
  int m_framesWritten = 0;
  std::vector<std::string> m_recordedReports;
  std::mutex m_reportsMutex; // NOTE: status may come from any thread
  std::vector<std::string> m_replayedReports;
};

} // namespace prism::replay
