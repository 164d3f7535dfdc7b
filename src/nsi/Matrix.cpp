#include "Matrix.h"

namespace prism::nsi {

std::array<double, 3> transformPoint(
    const Matrix &m, const std::array<double, 3> &p)
{
  std::array<double, 3> out;
  for (int j = 0; j < 3; ++j)
    out[j] = p[0] * m[j] + p[1] * m[4 + j] + p[2] * m[8 + j] + m[12 + j];
  return out;
}

std::array<double, 3> transformVector(
    const Matrix &m, const std::array<double, 3> &v)
{
  std::array<double, 3> out;
  for (int j = 0; j < 3; ++j)
    out[j] = v[0] * m[j] + v[1] * m[4 + j] + v[2] * m[8 + j];
  return out;
}

Matrix compose(const Matrix &local, const Matrix &parent)
{
  Matrix out{};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      double sum = 0;
      for (int k = 0; k < 4; ++k)
        sum += local[4 * i + k] * parent[4 * k + j];
      out[4 * i + j] = sum;
    }
  }
  return out;
}

} // namespace prism::nsi
