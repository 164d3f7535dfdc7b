// Elements a geometry reads: the application's array memory in place when
// its layout is already the one Embree and the renderers read, else the
// geometry's own converted copy. Shared arrays are then never copied:
// Embree builds over the application's memory (the array outlives the
// pointer until the next commit, and a release or an edit re-commits).
#pragma once

#include <cstddef>
#include <vector>

namespace prism {

template <typename T>
class SharedElements
{
 public:
  void clear()
  {
    std::vector<T>().swap(m_copy);
    m_data = nullptr;
    m_size = 0;
  }
  // Reads `size` elements at `data` in place (no copy).
  void share(const T *data, size_t size)
  {
    std::vector<T>().swap(m_copy);
    m_data = data;
    m_size = size;
  }
  // The geometry's own `size` elements (plus `spare` after them that
  // readers may touch) for the caller to fill: a conversion.
  T *own(size_t size, size_t spare = 0)
  {
    m_copy.resize(size + spare);
    m_data = m_copy.data();
    m_size = size;
    return m_copy.data();
  }

  const T *data() const
  {
    return m_data;
  }
  size_t size() const
  {
    return m_size;
  }
  bool empty() const
  {
    return m_size == 0;
  }
  const T &operator[](size_t i) const
  {
    return m_data[i];
  }
  const T *begin() const
  {
    return m_data;
  }
  const T *end() const
  {
    return m_data + m_size;
  }
  // The bytes of the geometry's own copy (0 when read in place).
  size_t copiedBytes() const
  {
    return m_copy.capacity() * sizeof(T);
  }

 private:
  const T *m_data{nullptr};
  size_t m_size{0};
  std::vector<T> m_copy;
};

} // namespace prism
