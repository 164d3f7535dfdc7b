// Replays a trace written by the debug layer (docs/debug-layer.md) on any
// ANARI library through libanari: each line becomes the call it records.
#pragma once

#include "trace/TraceFormat.h"

#include <anari/anari.h>

#include <list>
#include <string>
#include <unordered_map>
#include <vector>

namespace prism::replay {

struct Options
{
  std::string tracePath;
  std::string library;        // empty: the library the trace recorded
  std::string frameDirectory; // empty: frames are not written
};

struct Summary
{
  uint64_t calls = 0;
  int framesSame = 0;
  int framesDifferent = 0;
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
  bool arrayData(const Tokens &t);
  bool mapFrame(const Tokens &t);
  bool property(const Tokens &t);
  void writeFrame(const std::string &frame,
      const std::string &channel,
      const void *pixels,
      uint32_t width,
      uint32_t height,
      ANARIDataType type);

  // Operand helpers; each sets m_error and returns false on a bad operand.
  bool object(const trace::Token &token, ANARIObject &out);
  bool type(const trace::Token &token, ANARIDataType &out);
  bool number(const trace::Token &token, uint64_t &out);
  bool dimensions(const Tokens &t, size_t at, uint64_t items[3]);
  // Bytes of an operand at t[at] ("@offset:size", "-" or a list of object
  // names); `next` receives the index after it.
  bool contents(const Tokens &t,
      size_t at,
      ANARIDataType elementType,
      std::vector<unsigned char> &bytes,
      bool &none);
  bool fail(const std::string &message);

  Options m_options;
  std::string m_error;
  Summary m_summary;
  std::vector<unsigned char> m_data; // the side file
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  std::unordered_map<std::string, ANARIObject> m_objects;
  // Memory of shared arrays, alive as long as the replay (the device may
  // read it until the array is gone).
  std::list<std::vector<unsigned char>> m_arrayMemory;
  int m_framesWritten = 0;
};

} // namespace prism::replay
