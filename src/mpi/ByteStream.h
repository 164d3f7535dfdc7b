// What the processes send one another about their worlds (emitters,
// declared lights): values appended to bytes and read back. Floats travel
// as their bits, so every process rebuilds exactly what the sender had.
#pragma once

#include "math/Vec.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace prism::mpi {

class ByteWriter
{
 public:
  void add(float value)
  {
    append(&value, sizeof(value));
  }
  void add(uint32_t value)
  {
    append(&value, sizeof(value));
  }
  void add(uint64_t value)
  {
    append(&value, sizeof(value));
  }
  void add(const float3 &v)
  {
    add(v.x);
    add(v.y);
    add(v.z);
  }
  // Its length, then its characters.
  void add(const std::string &text)
  {
    add(uint32_t(text.size()));
    append(text.data(), text.size());
  }
  void append(const void *data, size_t size)
  {
    const auto *p = static_cast<const unsigned char *>(data);
    bytes.insert(bytes.end(), p, p + size);
  }
  std::vector<unsigned char> bytes;
};

class ByteReader
{
 public:
  ByteReader(const unsigned char *data, size_t size)
      : m_data(data), m_size(size)
  {}
  // False once a read went past the end (then values read are 0).
  bool ok() const
  {
    return m_ok;
  }
  size_t left() const
  {
    return m_size - m_offset;
  }
  float readFloat()
  {
    float value = 0.f;
    take(&value, sizeof(value));
    return value;
  }
  uint32_t readCount()
  {
    uint32_t value = 0;
    take(&value, sizeof(value));
    return value;
  }
  uint64_t readWord()
  {
    uint64_t value = 0;
    take(&value, sizeof(value));
    return value;
  }
  float3 readFloat3()
  {
    float3 v;
    v.x = readFloat();
    v.y = readFloat();
    v.z = readFloat();
    return v;
  }
  std::string readString()
  {
    const uint32_t size = readCount();
    if (!m_ok || size > left()) {
      m_ok = false;
      return {};
    }
    std::string text(reinterpret_cast<const char *>(m_data + m_offset), size);
    m_offset += size;
    return text;
  }
  // `size` bytes, or NULL (and not ok) when fewer are left.
  const unsigned char *readBytes(size_t size)
  {
    if (!m_ok || size > left()) {
      m_ok = false;
      return nullptr;
    }
    const unsigned char *bytes = m_data + m_offset;
    m_offset += size;
    return bytes;
  }

 private:
  void take(void *out, size_t size)
  {
    if (!m_ok || left() < size) {
      m_ok = false;
      return;
    }
    std::memcpy(out, m_data + m_offset, size);
    m_offset += size;
  }
  const unsigned char *m_data;
  size_t m_size;
  size_t m_offset{0};
  bool m_ok{true};
};

} // namespace prism::mpi
