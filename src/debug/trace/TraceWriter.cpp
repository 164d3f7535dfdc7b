#include "TraceWriter.h"

#include "TraceFormat.h"

#include <cstring>
#include <vector>

namespace prism::trace {

TraceWriter::TraceWriter(const std::string &path)
{
  m_text = std::fopen(path.c_str(), "w");
  m_data = std::fopen((path + ".bin").c_str(), "w+b");
  if (m_text) {
    std::fprintf(m_text,
        "# ANARI API trace written by the prism debug layer; bulk data in "
        "%s.bin\n# replay: anari-replay %s [--library NAME]\n",
        path.c_str(),
        path.c_str());
    m_lines = 2;
  }
}

TraceWriter::~TraceWriter()
{
  if (m_text)
    std::fclose(m_text);
  if (m_data)
    std::fclose(m_data);
}

uint64_t TraceWriter::line(const std::string &text)
{
  std::lock_guard lock(m_mutex);
  if (!m_text)
    return 0;
  std::fputs(text.c_str(), m_text);
  std::fputc('\n', m_text);
  std::fflush(m_text);
  return ++m_lines;
}

std::string TraceWriter::blob(const void *data, uint64_t size)
{
  // Identical blocks (an array set on many objects, unchanged unmaps) are
  // stored once: found by hash, confirmed byte for byte.
  const uint64_t hash = hashBytes(data, size);
  std::lock_guard lock(m_mutex);
  auto key = std::make_pair(hash, size);
  auto it = m_blobs.find(key);
  uint64_t offset = 0;
  if (it != m_blobs.end() && sameAsStored(it->second, data, size)) {
    offset = it->second;
  } else {
    offset = m_dataSize;
    if (m_data && size) {
      std::fseek(m_data, 0, SEEK_END);
      std::fwrite(data, 1, size, m_data);
      std::fflush(m_data);
    }
    m_dataSize += size;
    m_blobs[key] = offset;
  }
  std::string name = "@"; // appended: GCC 12 raises a false -Wrestrict
  return name.append(std::to_string(offset))
      .append(":")
      .append(std::to_string(size));
}

bool TraceWriter::sameAsStored(uint64_t offset, const void *data, uint64_t size)
{
  if (!m_data || std::fseek(m_data, long(offset), SEEK_SET) != 0)
    return false;
  std::vector<unsigned char> stored(size);
  const bool read = std::fread(stored.data(), 1, size, m_data) == size;
  std::fseek(m_data, 0, SEEK_END);
  return read && std::memcmp(stored.data(), data, size) == 0;
}

} // namespace prism::trace
