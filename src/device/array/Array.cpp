#include "Array.h"

#include "../object/DeviceState.h"

#include "MachineLimits.h"
#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>

#include <unistd.h>

namespace prism {
namespace {

ANARIDataType arrayTypeOf(int dimensions)
{
  return dimensions == 1   ? ANARI_ARRAY1D
         : dimensions == 2 ? ANARI_ARRAY2D
                           : ANARI_ARRAY3D;
}

// Element types an array may hold: data of fixed size and object handles.
bool isArrayElementType(ANARIDataType type)
{
  const int t = int(type);
  if (anari::isObject(type))
    return t != ANARI_DEVICE && t != ANARI_OBJECT;
  return t >= 1000 && anari::sizeOf(type) > 0;
}

} // namespace

const char *Array::whyNotCreatable(const Shape &shape)
{
  if (!isArrayElementType(shape.elementType))
    return "element type is not a valid array element type";
  uint64_t elements = 1;
  for (int i = 0; i < shape.dimensions; i++) {
    if (shape.size[i] == 0)
      return "array size is zero (arrays must have at least one element)";
    if (elements > std::numeric_limits<uint64_t>::max() / shape.size[i])
      return "array size overflows";
    elements *= shape.size[i];
  }
  if (elements > (std::numeric_limits<uint64_t>::max() >> 8)
                     / anari::sizeOf(shape.elementType))
    return "array size overflows";
  return nullptr;
}

Array::Array(DeviceState &device,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *deleterUserPtr,
    const Shape &shape)
    : Object(device, arrayTypeOf(shape.dimensions), ""),
      m_shape(shape),
      m_elementSize(anari::sizeOf(shape.elementType)),
      m_appMemory(appMemory),
      m_deleter(deleter),
      m_deleterUserPtr(deleterUserPtr),
      m_isObjectArray(anari::isObject(shape.elementType))
{
  if (!m_appMemory) {
    // Zeroed so object arrays start as NULL handles, never garbage.
    // kReadableSlack more: Embree reads past a vertex array's last element.
    m_managed.reset((unsigned char *)std::calloc(
        capacity() * m_elementSize + kReadableSlack, 1));
    if (!m_managed)
      throw std::bad_alloc();
  }
  m_regionEnd = capacity();
  if (m_isObjectArray)
    refreshObjectReferences();
}

void Array::FreeMemory::operator()(unsigned char *p) const
{
  std::free(p);
}

uint64_t Array::bytesNeeded(const Shape &shape)
{
  uint64_t bytes = 0;
  // Object arrays also hold a reference and a staging slot per element.
  const uint64_t perElement =
      anari::sizeOf(shape.elementType)
      + (anari::isObject(shape.elementType) ? 2 * sizeof(Object *) : 0);
  if (!limits::checkedBytes(shape.size, shape.dimensions, perElement, bytes))
    return std::numeric_limits<uint64_t>::max();
  return bytes;
}

Array::~Array()
{
  releaseObjectReferences();
  // NOTE: the deleter runs exactly once, when no object uses the memory.
  if (m_appMemory && m_deleter)
    m_deleter(m_deleterUserPtr, m_appMemory);
}

void *Array::storage()
{
  return m_appMemory ? const_cast<void *>(m_appMemory) : m_managed.get();
}

const void *Array::begin() const
{
  auto *base =
      (const unsigned char *)(m_appMemory ? m_appMemory : m_managed.get());
  return base + m_regionBegin * m_elementSize;
}

bool Array::readableAfterEnd(size_t bytes) const
{
  if (bytes <= kReadableSlack && !m_appMemory)
    return true; // the device's memory carries the slack
  const auto *base = (const unsigned char *)storage();
  const uintptr_t end = uintptr_t(base + m_regionEnd * m_elementSize);
  const uintptr_t allocationEnd = uintptr_t(base + capacity() * m_elementSize);
  if (end + bytes <= allocationEnd)
    return true; // elements beyond the region in use
  // The application's allocation: readable memory comes in whole pages,
  // so bytes in the page of the last element's last byte can be read
  // (their values are never used).
  if (m_regionEnd == m_regionBegin || !m_appMemory)
    return false;
  const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
  return (end - 1) / page == (end + bytes - 1) / page;
}

void *Array::map()
{
  m_mapped = true;
  return storage();
}

void Array::unmap()
{
  m_mapped = false;
  if (m_isObjectArray)
    refreshObjectReferences();
  markChanged();
}

void Array::takePrivateCopy()
{
  if (!borrowsApplicationMemory())
    return;
  const size_t bytes = capacity() * m_elementSize;
  std::unique_ptr<unsigned char[], FreeMemory> copy(
      (unsigned char *)std::malloc(bytes + kReadableSlack));
  if (!copy)
    throw std::bad_alloc();
  std::memcpy(copy.get(), m_appMemory, bytes);
  m_managed = std::move(copy);
  m_appMemory = nullptr;
  // Users that kept pointers into the application's memory re-read.
  markChanged();
}

std::vector<Object *> Array::objects() const
{
  if (!m_isObjectArray)
    return {};
  return std::vector<Object *>(m_heldObjects.begin() + m_regionBegin,
      m_heldObjects.begin() + m_regionEnd);
}

void Array::refreshObjectReferences()
{
  // Take the new references before dropping the old ones, so an object in
  // both sets never reaches a count of zero in between.
  std::vector<Object *> fresh(capacity(), nullptr);
  auto *handles = (const ANARIObject *)storage();
  uint64_t dead = 0, firstDead = 0;
  for (uint64_t i = 0; i < capacity(); i++) {
    const ANARIObject handle = handles[i];
    Object *object = nullptr;
    if (i < m_heldObjects.size() && m_heldObjects[i]
        && m_heldObjects[i]->handle() == handle) {
      // Still the object this element held, even if the application has
      // released its handle since (handles are never reused).
      object = m_heldObjects[i];
    } else if (handle) {
      object = device().lookup(handle);
      if (!object && dead++ == 0)
        firstDead = i;
    }
    if (object) {
      object->retainInternal();
      fresh[i] = object;
    }
  }
  releaseObjectReferences();
  m_heldObjects = std::move(fresh);
  if (dead > 0) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "element %llu%s: %s; the element is NULL",
        (unsigned long long)firstDead,
        dead > 1 ? (" (and " + std::to_string(dead - 1) + " more)").c_str()
                 : "",
        device().whyNotLive(handles[firstDead]));
  }
}

void Array::releaseObjectReferences()
{
  auto held = std::move(m_heldObjects);
  m_heldObjects.clear();
  for (Object *object : held) {
    if (object)
      object->releaseInternal();
  }
}

void Array::dropReferences()
{
  Object::dropReferences();
  releaseObjectReferences();
  m_heldObjects.assign(capacity(), nullptr);
}

void Array::hashContent(ContentHash &hash) const
{
  hash.add(uint64_t(m_shape.elementType));
  for (uint64_t size : m_shape.size)
    hash.add(size);
  hash.add(count());
  if (!m_isObjectArray) {
    hash.add(begin(), count() * m_elementSize);
    return;
  }
  for (uint64_t i = m_regionBegin; i < m_regionEnd; i++) {
    const Object *object = m_heldObjects[i];
    hash.add(object ? object->contentHash() : 0);
  }
}

void Array::commitParameters()
{
  m_regionBegin = 0;
  m_regionEnd = capacity();
  if (m_shape.dimensions != 1)
    return;
  struct Region
  {
    uint64_t lower, upper;
  };
  if (!isSet("region")) {
    readAny("region");
    return;
  }
  auto region = read<Region>("region", ANARI_UINT64_REGION1, {0, capacity()});
  // The spec's clamping: always a valid range of at least one element.
  region.upper = std::max(region.upper, region.lower + 1);
  region.upper = std::min(region.upper, capacity());
  region.lower = std::min(region.lower, region.upper - 1);
  m_regionBegin = region.lower;
  m_regionEnd = region.upper;
}

} // namespace prism
