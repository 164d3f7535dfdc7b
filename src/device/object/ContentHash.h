// A cheap 64-bit hash of what objects hold (not cryptographic), fed words,
// bytes and strings in order: equal inputs give equal values in every
// process, so processes can compare what they committed. Linear in the
// bytes, one multiply per 8 of them, no allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace prism {

class ContentHash
{
 public:
  void add(uint64_t word)
  {
    // One round of a multiply-rotate-multiply mix (as in xxHash64): every
    // input bit reaches the high bits, the rotation brings them back down.
    m_state ^= word * kPrime2;
    m_state = ((m_state << 31) | (m_state >> 33)) * kPrime1;
  }

  void add(const void *bytes, size_t size)
  {
    auto *p = static_cast<const unsigned char *>(bytes);
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
      uint64_t word;
      std::memcpy(&word, p + i, 8);
      add(word);
    }
    uint64_t tail = 0;
    std::memcpy(&tail, p + i, size - i);
    add(tail);
    add(uint64_t(size)); // so a zero tail differs from a shorter input
  }

  void add(const std::string &text)
  {
    add(text.data(), text.size());
  }

  // The state with a final avalanche (MurmurHash3's fmix64).
  uint64_t value() const
  {
    uint64_t h = m_state;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
    return h;
  }

 private:
  static constexpr uint64_t kPrime1 = 0x9e3779b185ebca87ull;
  static constexpr uint64_t kPrime2 = 0xc2b2ae3d27d4eb4full;
  uint64_t m_state{0x27d4eb2f165667c5ull};
};

} // namespace prism
