// How rays meet the world's volumes (emission-absorption media, see
// volume/Volume.h): the spec's reference ray marcher (Appendix C) with
// empty-space skipping for the raycast renderer, and unbiased delta and
// ratio tracking against majorant grids for the path tracer. Distances
// are along world-space rays; a volume's steps are a fraction of its data
// cells (in its object space).
#pragma once

#include "../math/Vec.h"
#include "SampleHash.h"

#include <cstdint>
#include <limits>

namespace prism {

class World;

// Whether the ray can meet any volume within [tMin, tMax].
bool mayMeetVolumes(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax);

// What marching a ray segment gives: the colour emitted towards the ray's
// origin (already attenuated) and the fraction of light from behind the
// segment that passes it, plus the first sample with opacity.
struct VolumeMarch
{
  float3 color{0.f, 0.f, 0.f};
  float transmittance{1.f};
  float firstDepth{std::numeric_limits<float>::infinity()};
  uint32_t objectId{~0u};
  uint32_t instanceId{~0u};
  float3 firstColor{0.f, 0.f, 0.f};
};

struct MarchSettings
{
  // Samples per data cell of each volume.
  float samplingRate{1.f};
  // Where in each step the sample lies, in [0, 1) (0.5: the middle;
  // jittered per frame, accumulation converges to the exact integral).
  float offset{0.5f};
  // Cross majorant cells where nothing can absorb without sampling them
  // (false, with stopTransmittance 0: the reference marcher exactly).
  bool skipEmpty{true};
  // Stop once this little light from behind passes (0: never stop).
  float stopTransmittance{1e-3f};
};

// Appendix C over [tMin, tMax]: per step, the sampled opacity absorbs the
// light behind and adds the sampled colour in front. Overlapping volumes
// are sampled together (extinctions add, colours weighted by them).
VolumeMarch marchVolumes(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    const MarchSettings &settings);

// Where light along a ray first interacts with a volume, drawn by delta
// tracking (the first real collision of every volume's, the nearest).
struct VolumeCollision
{
  float t{std::numeric_limits<float>::infinity()};
  float3 color{0.f, 0.f, 0.f};
  uint32_t objectId{~0u};
  uint32_t instanceId{~0u};
};
// False if the ray crosses [tMin, tMax] without a collision: the
// probability of that is the transmittance, so no weight is needed.
// Without `majorantGrid`, each volume's largest bound serves everywhere
// (the same result, more tentative collisions: for comparisons).
bool trackCollision(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    HashedStream &random,
    VolumeCollision &collision,
    bool majorantGrid = true);

// An unbiased estimate of the transmittance of [tMin, tMax] (ratio
// tracking with Russian roulette once it is small).
float trackTransmittance(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    HashedStream &random);

} // namespace prism
