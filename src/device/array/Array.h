// ANARIArray1D/2D/3D: shared (application memory, deleter called once when
// the device lets go), managed (device memory written through map), and
// arrays of object handles, which hold internal references (spec 3.9).
#pragma once

#include "../object/Object.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace prism {

class Array : public Object
{
 public:
  struct Shape
  {
    ANARIDataType elementType{ANARI_UNKNOWN};
    uint64_t size[3]{1, 1, 1};
    int dimensions{1};
  };

  // `appMemory` NULL makes a managed array. Validate with isCreatable first.
  Array(DeviceState &device,
      const void *appMemory,
      ANARIMemoryDeleter deleter,
      const void *deleterUserPtr,
      const Shape &shape);
  ~Array() override;

  // Why an array of `shape` cannot be created, or NULL if it can.
  static const char *whyNotCreatable(const Shape &shape);
  // The device's memory for a managed array of `shape` (UINT64_MAX when
  // that overflows).
  static uint64_t bytesNeeded(const Shape &shape);

  ANARIDataType elementType() const
  {
    return m_shape.elementType;
  }
  int dimensions() const
  {
    return m_shape.dimensions;
  }
  uint64_t size(int dimension) const
  {
    return m_shape.size[dimension];
  }
  uint64_t capacity() const
  {
    return m_shape.size[0] * m_shape.size[1] * m_shape.size[2];
  }
  size_t elementSize() const
  {
    return m_elementSize;
  }
  // First element in use and how many are in use (KHR_ARRAY1D_REGION).
  const void *begin() const;
  uint64_t count() const
  {
    return m_regionEnd - m_regionBegin;
  }
  // Whether the application gets its memory back when it releases this
  // array (shared, no deleter: spec 3.9), so objects still using the array
  // need a copy of their own.
  bool borrowsApplicationMemory() const
  {
    return m_appMemory && !m_deleter;
  }
  // Whether `bytes` beyond the last element in use can be read without a
  // fault (Embree reads 16 bytes for each 12-byte vertex): the device's
  // own memory carries kReadableSlack spare bytes; the application's
  // memory is checked against the end of its page.
  bool readableAfterEnd(size_t bytes) const;
  static constexpr size_t kReadableSlack = 16;
  // Copies the application's memory into the device's and uses the copy
  // from now on (objects reading the array re-commit). Throws bad_alloc.
  void takePrivateCopy();
  bool isObjectArray() const
  {
    return m_isObjectArray;
  }
  // The objects in use of an object array (entries may be NULL).
  std::vector<Object *> objects() const;

  void *map();
  void unmap();
  bool isMapped() const
  {
    return m_mapped;
  }

  void dropReferences() override;

 protected:
  void commitParameters() override;
  // The shape and the elements in use: bytes, or each object's hash.
  void hashContent(ContentHash &hash) const override;
  // An object array's elements may be recommitted while it is not.
  bool keepsContentHash() const override
  {
    return !m_isObjectArray;
  }

 private:
  void *storage();
  const void *storage() const
  {
    return const_cast<Array *>(this)->storage();
  }
  void refreshObjectReferences();
  void releaseObjectReferences();

  Shape m_shape;
  size_t m_elementSize{0};
  const void *m_appMemory{nullptr};
  ANARIMemoryDeleter m_deleter{nullptr};
  const void *m_deleterUserPtr{nullptr};
  // From calloc: the system hands out zeroed pages as they are first
  // touched, so a large managed array costs nothing until it is written.
  struct FreeMemory
  {
    void operator()(unsigned char *p) const;
  };
  std::unique_ptr<unsigned char[], FreeMemory> m_managed;
  bool m_mapped{false};
  bool m_isObjectArray{false};
  uint64_t m_regionBegin{0};
  uint64_t m_regionEnd{0};
  std::vector<Object *> m_heldObjects; // internal references, per element
};

} // namespace prism
