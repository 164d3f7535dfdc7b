// Unstructured meshes as an application hands them over, and a fixture
// that commits them to unstructured fields.
#pragma once

#include "../ObjectTestFixture.h"
#include "volume/UnstructuredField.h"

#include <functional>
#include <random>

namespace prism::testing {

constexpr uint8_t kTetra = 10, kHexahedron = 12, kWedge = 13, kPyramid = 14;

// A mesh as the application hands it over.
struct Mesh
{
  std::vector<float3> positions;
  std::vector<uint32_t> index;
  std::vector<uint32_t> cellIndex;
  std::vector<uint8_t> cellType;
  std::vector<float> vertexData;
  std::vector<float> cellData;

  void addCell(uint8_t type, std::initializer_list<uint32_t> vertices)
  {
    cellType.push_back(type);
    cellIndex.push_back(uint32_t(index.size()));
    index.insert(index.end(), vertices);
  }
  void setVertexData(const std::function<float(float3)> &f)
  {
    vertexData.clear();
    for (const float3 &p : positions)
      vertexData.push_back(f(p));
  }
};

// A jittered n x n x n grid of hexahedra over [0, n]^3.
inline Mesh hexahedronGrid(int n, float jitter, std::mt19937 &rng)
{
  Mesh mesh;
  std::uniform_real_distribution<float> offset(-jitter, jitter);
  const int m = n + 1;
  for (int z = 0; z < m; z++)
    for (int y = 0; y < m; y++)
      for (int x = 0; x < m; x++)
        mesh.positions.push_back(
            {x + offset(rng), y + offset(rng), z + offset(rng)});
  auto at = [m](int x, int y, int z) {
    return uint32_t((z * m + y) * m + x);
  };
  for (int z = 0; z < n; z++)
    for (int y = 0; y < n; y++)
      for (int x = 0; x < n; x++)
        mesh.addCell(kHexahedron,
            {at(x, y, z),
                at(x + 1, y, z),
                at(x + 1, y + 1, z),
                at(x, y + 1, z),
                at(x, y, z + 1),
                at(x + 1, y, z + 1),
                at(x + 1, y + 1, z + 1),
                at(x, y + 1, z + 1)});
  return mesh;
}

class MeshTestFixture : public ObjectTestFixture
{
 protected:
  // Sets every array of `mesh` that is non-empty on `field` and commits.
  void commitMesh(UnstructuredField *field, const Mesh &mesh)
  {
    auto setArray = [&](const char *name, ANARIDataType type, auto &values) {
      if (!values.empty())
        set(field, name, ANARI_ARRAY1D, array(type, values));
      else
        field->unstageParameter(name);
    };
    setArray("vertex.position", ANARI_FLOAT32_VEC3, mesh.positions);
    setArray("index", ANARI_UINT32, mesh.index);
    setArray("cell.index", ANARI_UINT32, mesh.cellIndex);
    setArray("cell.type", ANARI_UINT8, mesh.cellType);
    setArray("vertex.data", ANARI_FLOAT32, mesh.vertexData);
    setArray("cell.data", ANARI_FLOAT32, mesh.cellData);
    commit(field);
  }
  UnstructuredField *field(const Mesh &mesh)
  {
    auto *result = make<UnstructuredField>();
    commitMesh(result, mesh);
    return result;
  }
};

} // namespace prism::testing
