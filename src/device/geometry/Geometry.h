// ANARIGeometry: the shape of a surface (spec 5.9). The base reads the
// attribute arrays every subtype shares and resolves attributes at a hit
// with the spec's precedence: faceVarying > vertex > primitive > uniform.
#pragma once

#include "../object/Object.h"
#include "../rt/Hit.h"
#include "Attributes.h"
#include "EmitterShape.h"
#include "SharedElements.h"
#include "VertexMotion.h"

#include <vector>

namespace prism {

class Array;
namespace rt {
class Scene;
}

class Geometry : public Object
{
 public:
  Geometry(DeviceState &device, const std::string &subtype);

  bool isValid() const override
  {
    return m_valid;
  }
  uint32_t primitiveCount() const
  {
    return m_primitiveCount;
  }
  // Adds the geometry to `scene` as Embree geometry `id`.
  virtual void addTo(rt::Scene &scene, uint32_t id) const = 0;

  // Fills the geometry's attributes at `hit` (object space), leaving those
  // the geometry does not define untouched; skips color and attribute0..3
  // unless `interpolate`. Returns the object-space shading normal
  // (normalised, facing as the geometry defines it) at the ray's `time`.
  float3 attributesAt(const rt::Hit &hit,
      const float3 &objectPosition,
      AttributeValues &attributes,
      bool interpolate = true,
      float time = 0.5f) const;

  // The object-space tangent at `hit` (xyz along increasing u, w = +-1 the
  // handedness of the bitangent) from vertex.tangent / faceVarying.tangent
  // or, without them, from how attribute0 (texture coordinates) varies
  // over the primitive; false when neither defines one.
  bool tangentAt(const rt::Hit &hit, float4 &tangent) const;

  // Appends the surface, in object space, for sampling it as a light;
  // nothing for shapes that cannot be sampled (or move while the shutter
  // is open).
  virtual void appendEmitterShape(EmitterShape &) const {}
  // Whether the normal attributesAt() returns is just the normalised
  // hit.geometricNormal (no vertex or corner normals, no analytic normal):
  // renderers that need nothing else may then skip attributesAt().
  bool getProperty(const std::string &name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;
  bool flatShaded() const
  {
    return m_vertexNormals.empty() && m_cornerNormals.empty()
           && !m_vertexMotion.hasNormals() && !hasAnalyticNormal();
  }

 protected:
  // Which vertices a hit interpolates, and how; `slot` is each vertex's
  // corner number within its primitive (for faceVarying.* arrays).
  struct Corners
  {
    uint32_t count{0};
    uint32_t vertex[4]{};
    uint32_t slot[4]{};
    float weight[4]{};
  };

  void commitParameters() final;
  // Reads the subtype's own parameters; calls invalidate() on bad input.
  virtual void readShape() = 0;
  virtual Corners cornersAt(uint32_t primitive, float u, float v) const = 0;
  // Corners per primitive of faceVarying.* arrays (0: not supported).
  virtual uint32_t faceVaryingCorners() const
  {
    return 0;
  }
  // The shading normal before vertex normals apply (default: Ng).
  virtual float3 surfaceNormal(
      const rt::Hit &hit, const float3 &objectPosition) const;
  // True in subtypes whose surfaceNormal() is not Ng (see flatShaded()).
  virtual bool hasAnalyticNormal() const
  {
    return false;
  }

  // Marks the geometry invalid with an error naming the problem.
  void invalidate(const char *format, ...)
      __attribute__((format(printf, 2, 3)));
  // An ARRAY1D parameter with one of `elementTypes`, or NULL (reported).
  const Array *readArray(const char *name,
      std::initializer_list<ANARIDataType> elementTypes,
      bool required = false);
  // The primitive index array as `components` uint32 per primitive (read
  // in place when it holds exactly that); false if unset. Out-of-range or
  // over-wide indices invalidate the geometry.
  bool readIndices(int components, SharedElements<uint32_t> &indices);
  // Positions (FLOAT32_VEC3) with Embree's read padding, read in place
  // when the array's memory allows it; false if missing.
  bool readPositions(size_t minimumCount);
  // Embree loads FLOAT4 vertices 16 bytes at a time, aligned: a shared
  // array elsewhere is copied (malloc's 8-byte-aligned blocks crash its
  // curve builder).
  static constexpr uintptr_t kEmbreeFloat4Alignment = 16;
  // PRISM_GEOMETRY_POSITION_RADIUS (spheres, curves): 'vertex.positionRadius'
  // (FLOAT32_VEC4, the radius in w), Embree's own layout, which replaces
  // vertex.position and the radii (ignored, with a warning, if also set);
  // NULL if unset or unusable (then reported). Sets m_vertexCount.
  const Array *readPositionRadius(size_t minimumCount);
  // Meshes: motion.vertex.* keys (deformation motion blur) if set, else
  // vertex.position as readPositions(); false if neither is usable.
  bool readDeformablePositions(size_t minimumCount);
  void setPrimitiveCount(uint32_t count)
  {
    m_primitiveCount = count;
  }
  // Every vertex index used must be below this (checked after readShape).
  void requireVertexIndicesBelow(
      size_t vertexCount, const SharedElements<uint32_t> &indices);
  // 0, 1, ... count - 1 into `indices` (a soup's implied indices).
  static void generateIndices(SharedElements<uint32_t> &indices, size_t count);
  // Bytes of array data this geometry holds as its own copies and
  // conversions (positions and indices; subtypes add theirs).
  virtual size_t copiedBytes() const;
  // Radii per vertex (FLOAT32), or empty if unset.
  std::vector<float> readFloats(const char *name);

  // Embree reads one float beyond the last: the array has it to read.
  SharedElements<float3> m_positions;
  // The primitive index array as read by readIndices (subtypes' own).
  SharedElements<uint32_t> m_indices;
  size_t m_vertexCount{0};
  // Set when motion.vertex.position is: the vertices over time (then
  // m_positions holds its first key).
  VertexMotion m_vertexMotion;

 private:
  struct AttributeData
  {
    bool hasUniform{false};
    float4 uniform{0, 0, 0, 1};
    std::vector<float4> perPrimitive, perVertex, perCorner;
  };
  void readAttributes();
  std::vector<float4> readAttributeArray(const std::string &name);
  void checkAttributeSizes();
  bool uvTangent(
      uint32_t primitive, const Corners &corners, float4 &tangent) const;

  bool m_valid{false};
  uint32_t m_primitiveCount{0};
  AttributeData m_attributes[5]; // color, attribute0..3
  std::vector<float3> m_vertexNormals;
  std::vector<float3> m_cornerNormals;
  std::vector<float4> m_vertexTangents;
  std::vector<float4> m_cornerTangents;
};

// The geometry of `subtype`, or NULL if the device does not implement it.
Geometry *createGeometry(DeviceState &device, const std::string &subtype);

} // namespace prism
