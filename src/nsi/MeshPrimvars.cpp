#include "MeshPrimvars.h"

#include <cmath>

namespace prism::nsi {

std::vector<float> faceVertexValues(const std::string &handle,
    const Node &mesh,
    const std::string &name,
    size_t components,
    const MeshLayout &layout,
    const std::function<void(int, const std::string &)> &report)
{
  const Value *value = mesh.attribute(name);
  if (!value)
    return {};
  auto ignored = [&](const std::string &why) {
    report(NSIErrWarning,
        "mesh '" + handle + "': '" + name + "' " + why + "; ignored");
    return std::vector<float>{};
  };
  const std::vector<double> values = value->numbers();
  if (values.empty() || values.size() % components)
    return ignored(
        "is not " + std::to_string(components) + " numbers per value");
  const size_t count = values.size() / components;
  const size_t faceVertices = layout.faceOfVertex.size();

  // Which value each face vertex takes.
  std::vector<size_t> source(faceVertices);
  if (const Value *indices = mesh.attribute(name + ".indices")) {
    const std::vector<double> numbers = indices->numbers();
    if (numbers.size() != faceVertices)
      return ignored("has " + std::to_string(numbers.size()) + " indices for "
                     + std::to_string(faceVertices) + " face vertices");
    for (size_t k = 0; k < faceVertices; ++k) {
      const double i = numbers[k];
      if (!(i >= 0 && i < double(count)) || i != std::floor(i))
        return ignored("has index " + shortNumber(i) + ", outside its "
                       + std::to_string(count) + " values");
      source[k] = size_t(i);
    }
  } else if ((value->flags & NSIParamPerFace) && count == layout.faceCount) {
    for (size_t k = 0; k < faceVertices; ++k)
      source[k] = layout.faceOfVertex[k];
  } else if (count == layout.pointCount) {
    for (size_t k = 0; k < faceVertices; ++k)
      source[k] =
          layout.pointIndices.empty() ? k : size_t(layout.pointIndices[k]);
  } else if (count == faceVertices) {
    for (size_t k = 0; k < faceVertices; ++k)
      source[k] = k;
  } else if (count == layout.faceCount) {
    for (size_t k = 0; k < faceVertices; ++k)
      source[k] = layout.faceOfVertex[k];
  } else if (count != 1) {
    return ignored("has " + std::to_string(count)
                   + " values, matching no point, face vertex or face count");
  }

  std::vector<float> out;
  out.reserve(faceVertices * components);
  for (size_t s : source) {
    for (size_t c = 0; c < components; ++c)
      out.push_back(float(values[s * components + c]));
  }
  return out;
}

} // namespace prism::nsi
