// A cloud of soft blobs over a ground plane: a 128^3 structuredRegular
// field (a few Gaussian blobs, their density rippled by a sum of sines so
// the transfer function has structure to show) rendered by a
// transferFunction1D volume with the inferno map. Devices without
// structured-regular fields or transfer-function volumes get the plane and
// a note.
#include "ColorMaps.h"
#include "DemoScenes.h"
#include "Meshes.h"
#include "Objects.h"
#include "TransferFunction.h"

#include <algorithm>
#include <cmath>

namespace prism::scenes {
namespace {

constexpr int kVoxels = 128; // per side
// The field spans [-1, 1]^3 in world space, resting on the ground at -1.
constexpr float kHalfSize = 1.f;

struct Blob
{
  Vec3 centre;
  float radius; // standard deviation of the Gaussian
  float weight;
};

// Density in [0, 1] at `p` (world space).
float blobDensity(const Vec3 &p)
{
  static const Blob kBlobs[] = {
      {{-0.3f, -0.45f, 0.1f}, 0.3f, 1.f},
      {{0.35f, -0.5f, -0.2f}, 0.26f, 0.9f},
      {{0.f, 0.05f, 0.f}, 0.3f, 0.85f},
      {{0.4f, 0.2f, 0.35f}, 0.18f, 0.7f},
      {{-0.4f, 0.35f, -0.3f}, 0.17f, 0.65f},
  };
  float density = 0.f;
  for (const Blob &b : kBlobs) {
    const Vec3 d = p - b.centre;
    density += b.weight * std::exp(-dot(d, d) / (2.f * b.radius * b.radius));
  }
  // Three octaves of products of sines at incommensurate frequencies along
  // skewed axes: cheap, deterministic, and it reads as turbulence.
  float turbulence = 0.f, amplitude = 0.5f;
  Vec3 q = p;
  for (int octave = 0; octave < 3; octave++) {
    turbulence += amplitude * std::sin(5.1f * q[0] + 2.3f * q[1])
                  * std::sin(4.7f * q[1] - 1.9f * q[2])
                  * std::sin(5.3f * q[2] + 2.1f * q[0]);
    q = Vec3{1.9f * q[1] + 0.3f, 2.1f * q[2] - 0.7f, 2.f * q[0] + 1.1f};
    amplitude *= 0.55f;
  }
  density *= 0.75f + 1.2f * turbulence;
  // Fade to zero at the field's faces so the box never shows.
  for (float c : p)
    density *= std::min(1.f, 8.f * (kHalfSize - std::abs(c)));
  return std::clamp(density, 0.f, 1.f);
}

ANARIVolume newBlobVolume(ANARIDevice device, const TransferFunction &style)
{
  std::vector<float> voxels(size_t(kVoxels) * kVoxels * kVoxels);
  const float spacing = 2.f * kHalfSize / float(kVoxels - 1);
  size_t index = 0;
  for (int k = 0; k < kVoxels; k++)
    for (int j = 0; j < kVoxels; j++)
      for (int i = 0; i < kVoxels; i++) // x fastest, as ARRAY3D is laid out
        voxels[index++] = blobDensity({-kHalfSize + float(i) * spacing,
            -kHalfSize + float(j) * spacing,
            -kHalfSize + float(k) * spacing});
  ANARIArray3D data = newArray3D(device,
      ANARI_FLOAT32,
      voxels.data(),
      kVoxels,
      kVoxels,
      kVoxels,
      sizeof(float));
  ANARISpatialField field = anariNewSpatialField(device, "structuredRegular");
  setObject(device, field, "data", ANARI_ARRAY3D, data);
  anariRelease(device, data);
  setVec3(device, field, "origin", {-kHalfSize, -kHalfSize, -kHalfSize});
  setVec3(device, field, "spacing", {spacing, spacing, spacing});
  anariCommitParameters(device, field);

  ANARIVolume volume = newTransferFunctionVolume(device, field, style);
  anariRelease(device, field);
  return volume;
}

} // namespace

TransferFunction volumeBlobsStyle()
{
  TransferFunction tf;
  tf.colors = linearColors(*findColorMap("inferno"));
  // Thin haze below 0.2, dense cores above 0.6.
  tf.opacities = {0.f, 0.f, 0.05f, 0.25f, 0.6f, 0.9f, 1.f};
  tf.valueRange = {0.f, 1.f};
  tf.unitDistance = 0.15f;
  return tf;
}

Scene buildVolumeBlobs(ANARIDevice device)
{
  return buildVolumeBlobsWithStyle(device, volumeBlobsStyle());
}

Scene buildVolumeBlobsWithStyle(
    ANARIDevice device, const TransferFunction &style)
{
  Scene scene;
  scene.name = "volume";
  scene.description = "soft blobs in a structuredRegular field";
  scene.camera.valid = true;
  scene.camera.eye = {1.9f, 0.8f, 2.7f};
  scene.camera.at = {0.f, -0.1f, 0.f};
  scene.camera.up = {0.f, 1.f, 0.f};
  scene.camera.fovyDegrees = 36.f;
  scene.hasBackground = true;
  scene.background = {0.08f, 0.09f, 0.12f, 1.f};

  TriangleMesh ground;
  ground.addQuad({-4.f, -kHalfSize, 4.f}, {8.f, 0.f, 0.f}, {0.f, 0.f, -8.f});
  scene.bounds = ground.bounds();
  scene.bounds.extend(Vec3{kHalfSize, kHalfSize, kHalfSize});
  ANARIMaterial groundMaterial = newMatte(device, {0.45f, 0.45f, 0.45f});
  ANARIGeometry groundGeometry = newTriangleGeometry(device, ground);
  std::vector<ANARIObject> surfaces = {
      newSurface(device, groundGeometry, groundMaterial)};
  anariRelease(device, groundGeometry);
  anariRelease(device, groundMaterial);

  std::vector<ANARIObject> lights;
  if (ANARILight sun =
          newLightIfSupported(device, "directional", scene, lights)) {
    setVec3(device, sun, "direction", normalize({-0.6f, -1.f, -0.4f}));
    setFloat(device, sun, "irradiance", 2.5f);
    anariCommitParameters(device, sun);
  }
  // A weak fill from the other side keeps the shadowed side readable.
  if (ANARILight fill =
          newLightIfSupported(device, "directional", scene, lights)) {
    setVec3(device, fill, "direction", normalize({0.7f, -0.3f, -0.6f}));
    setFloat(device, fill, "irradiance", 0.6f);
    anariCommitParameters(device, fill);
  }
  finishWorld(device, scene, surfaces, {}, lights);

  if (!hasSubtype(device, ANARI_SPATIAL_FIELD, "structuredRegular")
      || !hasSubtype(device, ANARI_VOLUME, "transferFunction1D")) {
    scene.notes.push_back(
        "the device does not implement structuredRegular fields with "
        "transferFunction1D volumes (KHR_SPATIAL_FIELD_STRUCTURED_REGULAR, "
        "KHR_VOLUME_TRANSFER_FUNCTION1D); only the ground is shown");
    return scene;
  }
  ANARIVolume volume = newBlobVolume(device, style);
  setObjectArray(device, scene.world, "volume", ANARI_VOLUME, {volume});
  anariCommitParameters(device, scene.world);
  anariRelease(device, volume);
  return scene;
}

} // namespace prism::scenes
