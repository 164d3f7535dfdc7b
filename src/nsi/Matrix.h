// 4x4 matrices as NSI passes them, composed in double.
#pragma once

#include <array>
#include <vector>

namespace prism::nsi {

// NSI's convention: row vectors, translation in elements 12-14. ANARI's
// column-major FLOAT32_MAT4 holds the same 16 numbers in the same order.
using Matrix = std::array<double, 16>;
constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
// One placement's matrix at each motion time (one entry when still).
using Placement = std::vector<Matrix>;

// p * m for a row vector p = (x, y, z, w).
std::array<double, 3> transformPoint(
    const Matrix &m, const std::array<double, 3> &p);
std::array<double, 3> transformVector(
    const Matrix &m, const std::array<double, 3> &v);
// The placement of `local` inside `parent`: local first, then parent.
Matrix compose(const Matrix &local, const Matrix &parent);

} // namespace prism::nsi
