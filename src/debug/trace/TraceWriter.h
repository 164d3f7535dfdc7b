// Writes a trace: the text stream at `path` and its bulk data at
// `path`.bin, each distinct block of bytes stored once.
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <utility>

namespace prism::trace {

class TraceWriter
{
 public:
  // Opens both files; check ok().
  explicit TraceWriter(const std::string &path);
  ~TraceWriter();
  TraceWriter(const TraceWriter &) = delete;
  TraceWriter &operator=(const TraceWriter &) = delete;

  bool ok() const
  {
    return m_text && m_data;
  }
  // Appends one line (a call), flushed so a crash keeps what came before;
  // returns its line number in the file (from 1).
  uint64_t line(const std::string &text);
  // "@offset:size" naming `size` bytes in the side file (written once).
  std::string blob(const void *data, uint64_t size);

 private:
  bool sameAsStored(uint64_t offset, const void *data, uint64_t size);

  std::mutex m_mutex; // NOTE: calls may come from any thread
  FILE *m_text{nullptr};
  FILE *m_data{nullptr};
  uint64_t m_dataSize{0};
  uint64_t m_lines{0};
  // (hash, size) -> offset of blocks already written.
  std::map<std::pair<uint64_t, uint64_t>, uint64_t> m_blobs;
};

} // namespace prism::trace
