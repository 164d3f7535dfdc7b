// What the layer reads out of array data: the largest index an index array
// holds (read once when the data is handed over: at creation of a shared
// array and at each unmap, the only times the application may change it).
#pragma once

#include "anari/anari.h"

#include <cstdint>

namespace prism::debug {

// Bytes of one component of an unsigned/signed integer element type (1, 2,
// 4, 8), 0 for every other type.
int integerComponentBytes(ANARIDataType type);

// The largest component of `count` elements of `type` laid out `stride`
// bytes apart (0: packed). Negative values count as the largest possible
// index (they are out of range for any vertex array). False if `type` is
// not an integer type.
bool largestComponent(const void *memory,
    ANARIDataType type,
    uint64_t count,
    uint64_t stride,
    uint64_t &largest);

} // namespace prism::debug
