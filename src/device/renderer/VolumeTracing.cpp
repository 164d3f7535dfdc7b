#include "VolumeTracing.h"

#include "../math/RayBox.h"
#include "../world/World.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

constexpr int kMaxSegments = 16;
// Steps of one volume along one ray for the marcher, and tentative
// collisions for delta and ratio tracking, at most: beyond that many a
// volume counts as opaque (pathological inputs only: a huge volume of
// tiny cells, or a majorant far above the extinction it bounds).
constexpr float kMaxSteps = float(1 << 20);
constexpr int kMaxTentativeCollisions = 1 << 16;

// One volume's part of a ray: [t0, t1] and the ray in its object space.
struct Segment
{
  const PlacedVolume *placed;
  float t0, t1;
  float3 origin, direction;
  // Step along the world ray that moves one sample in object space.
  float step;
};

// The volumes the ray crosses within [tMin, tMax], by entry distance; at
// most kMaxSegments (the nearest).
int segmentsAlong(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    float samplingRate,
    Segment out[kMaxSegments])
{
  int count = 0;
  for (const PlacedVolume &placed : world.volumes()) {
    Segment s{&placed, 0.f, 0.f, {}, {}, 0.f};
    if (!placed.clip(
            origin, direction, tMin, tMax, s.t0, s.t1, s.origin, s.direction))
      continue;
    const float speed = length(s.direction);
    if (!(speed > 0.f) || !std::isfinite(speed))
      continue;
    s.step = placed.volume->cellSize() / (samplingRate * speed);
    if (!(s.step > 0.f) || !std::isfinite(s.step) || !std::isfinite(s.t0)
        || !std::isfinite(s.t1))
      continue;
    // However large a volume is next to its cells, a segment takes at most
    // kMaxSteps steps (longer ones where it is larger).
    s.step = std::max(s.step, (s.t1 - s.t0) / kMaxSteps);
    if (count == kMaxSegments) {
      if (s.t0 >= out[count - 1].t0)
        continue;
      count--;
    }
    int i = count++;
    for (; i > 0 && out[i - 1].t0 > s.t0; i--)
      out[i] = out[i - 1];
    out[i] = s;
  }
  return count;
}

// Adds one step beginning at distance `begin`, of length `length`, with
// extinction `sigma` and colour `color` (Appendix C); records the first
// step with opacity, where it begins (the depth a slab entered at t
// reports is t, whichever point of the step was sampled).
void accumulate(VolumeMarch &march,
    float begin,
    float length,
    float sigma,
    const float3 &color,
    const PlacedVolume &placed)
{
  if (!(sigma > 0.f))
    return;
  const float stepTransmittance = std::exp(-sigma * length);
  if (march.firstDepth == std::numeric_limits<float>::infinity()) {
    march.firstDepth = begin;
    march.objectId = placed.volume->id();
    march.instanceId = placed.instanceId;
    march.firstColor = color;
  }
  march.color =
      march.color + color * (march.transmittance * (1.f - stepTransmittance));
  march.transmittance *= stepTransmittance;
}

// One volume alone over its segment: fixed steps from the segment's
// entry. With skipping, empty majorant cells are crossed without sampling
// (the samples there would add nothing: the majorant bounds every
// extinction in the cell) and the steps of the others are sampled in runs
// through the volume's line sampler; without, every step is sampled
// through sample() one by one: the reference marcher.
void marchSegment(
    const Segment &s, const MarchSettings &settings, VolumeMarch &march)
{
  const Volume &volume = *s.placed->volume;
  const float span = s.t1 - s.t0;
  const auto steps = int64_t(std::ceil(span / s.step));
  // Steps before this one are whole; the last may be shorter.
  const auto wholeSteps = int64_t(std::floor(span / s.step));
  int64_t nextStep = 0;
  // Step k: its sample's distance and the step's length.
  auto stepAt = [&](int64_t k, float &t, float &length) {
    const float a = s.t0 + float(k) * s.step;
    const float b = std::min(a + s.step, s.t1);
    t = a + settings.offset * (b - a);
    length = b - a;
  };
  auto one = [&](int64_t k) {
    float t, length, sigma = 0.f;
    float3 color;
    stepAt(k, t, length);
    if (volume.sample(s.origin + s.direction * t, sigma, color))
      accumulate(
          march, s.t0 + float(k) * s.step, length, sigma, color, *s.placed);
    return march.transmittance >= settings.stopTransmittance;
  };
  if (!settings.skipEmpty) {
    for (int64_t k = 0; k < steps; k++) {
      if (!one(k))
        return;
    }
    return;
  }
  constexpr int kRun = 64;
  float sigmas[kRun];
  float3 colors[kRun];
  auto sampleSteps = [&](int64_t first, int64_t end) {
    first = std::max(first, nextStep);
    nextStep = std::max(nextStep, end);
    for (int64_t k = first; k < end;) {
      if (k >= wholeSteps) {
        if (!one(k++))
          return false;
        continue;
      }
      const int n = int(std::min<int64_t>(kRun, std::min(end, wholeSteps) - k));
      float t, length;
      stepAt(k, t, length);
      volume.sampleLine(
          s.origin + s.direction * t, s.direction * s.step, n, sigmas, colors);
      for (int i = 0; i < n; i++) {
        accumulate(march,
            s.t0 + float(k + i) * s.step,
            s.step,
            sigmas[i],
            colors[i],
            *s.placed);
        if (march.transmittance < settings.stopTransmittance)
          return false;
      }
      k += n;
    }
    return true;
  };
  // Steps of consecutive cells that hold something are sampled as one run.
  int64_t runFirst = 0, runEnd = 0;
  const bool stopped = !volume.majorants().traverse(s.origin,
      s.direction,
      s.t0,
      s.t1,
      [&](float enter, float exit, float majorant) {
        if (majorant <= 0.f) {
          const bool go = runEnd <= runFirst || sampleSteps(runFirst, runEnd);
          runFirst = runEnd = 0;
          return go;
        }
        const auto first = int64_t(std::floor((enter - s.t0) / s.step));
        const auto end =
            std::min(steps, int64_t(std::ceil((exit - s.t0) / s.step)));
        if (runEnd <= runFirst)
          runFirst = first;
        runEnd = std::max(runEnd, end);
        return true;
      });
  if (!stopped && runEnd > runFirst)
    sampleSteps(runFirst, runEnd);
}

// Overlapping volumes over [t0, t1]: every volume sampled at the finest
// of their steps, extinctions added and colours weighted by them.
void marchOverlap(const Segment *segments,
    int count,
    float t0,
    float t1,
    const MarchSettings &settings,
    VolumeMarch &march)
{
  float step = segments[0].step;
  for (int i = 1; i < count; i++)
    step = std::min(step, segments[i].step);
  const auto steps = int64_t(std::ceil((t1 - t0) / step));
  for (int64_t k = 0; k < steps; k++) {
    const float a = t0 + float(k) * step;
    const float b = std::min(a + step, t1);
    const float t = a + settings.offset * (b - a);
    float sigmaSum = 0.f;
    float3 weighted{0.f, 0.f, 0.f};
    const PlacedVolume *densest = nullptr;
    float densestSigma = 0.f;
    for (int i = 0; i < count; i++) {
      const Segment &s = segments[i];
      float sigma = 0.f;
      float3 color;
      if (t < s.t0 || t > s.t1
          || !s.placed->volume->sample(s.origin + s.direction * t, sigma, color)
          || !(sigma > 0.f))
        continue;
      sigmaSum += sigma;
      weighted = weighted + color * sigma;
      if (sigma > densestSigma) {
        densestSigma = sigma;
        densest = s.placed;
      }
    }
    if (densest)
      accumulate(march, a, b - a, sigmaSum, weighted / sigmaSum, *densest);
    if (march.transmittance < settings.stopTransmittance)
      return;
  }
}

// Tentative collisions along the segment up to `end`, drawn at the rate of
// each majorant cell's bound, as visit(t, majorant, extinction, colour)
// (extinction 0 where the volume has no value); stops when visit returns
// false.
template <typename Visit>
void forEachTentativeCollision(const Segment &s,
    float end,
    bool majorantGrid,
    HashedStream &random,
    Visit &&visit)
{
  const Volume &volume = *s.placed->volume;
  int tentative = 0;
  auto inCell = [&](float enter, float exit, float majorant) {
    if (majorant <= 0.f)
      return true;
    for (float t = enter;;) {
      t -= std::log1p(-random.next()) / majorant;
      if (t >= exit)
        return true;
      float sigma = 0.f;
      float3 color{0.f, 0.f, 0.f};
      volume.sample(s.origin + s.direction * t, sigma, color);
      // Too many: this one is real (the extinction as large as can be).
      if (++tentative >= kMaxTentativeCollisions)
        sigma = majorant;
      if (!visit(t, majorant, sigma, color)
          || tentative >= kMaxTentativeCollisions)
        return false;
    }
  };
  // Without the grid: one bound, the largest, for the whole segment.
  if (!majorantGrid)
    inCell(s.t0, end, volume.majorants().maximum());
  else
    volume.majorants().traverse(s.origin, s.direction, s.t0, end, inCell);
}

} // namespace

bool mayMeetVolumes(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax)
{
  for (const PlacedVolume &placed : world.volumes()) {
    float t0 = tMin, t1 = tMax;
    if (clipRayToBox(placed.worldBounds, origin, direction, t0, t1))
      return true;
  }
  return false;
}

VolumeMarch marchVolumes(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    const MarchSettings &settings)
{
  VolumeMarch march;
  Segment segments[kMaxSegments];
  const int count = segmentsAlong(world,
      origin,
      direction,
      tMin,
      tMax,
      std::max(settings.samplingRate, 1e-3f),
      segments);
  // Segments by entry; runs of overlapping ones are marched together.
  for (int i = 0; i < count;) {
    float end = segments[i].t1;
    int j = i + 1;
    for (; j < count && segments[j].t0 < end; j++)
      end = std::max(end, segments[j].t1);
    if (j == i + 1)
      marchSegment(segments[i], settings, march);
    else
      marchOverlap(segments + i, j - i, segments[i].t0, end, settings, march);
    if (march.transmittance < settings.stopTransmittance)
      break;
    i = j;
  }
  return march;
}

bool trackCollision(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    HashedStream &random,
    VolumeCollision &collision,
    bool majorantGrid)
{
  Segment segments[kMaxSegments];
  const int count =
      segmentsAlong(world, origin, direction, tMin, tMax, 1.f, segments);
  collision = VolumeCollision{};
  // A later volume can only win with a nearer collision.
  for (int i = 0; i < count && segments[i].t0 < collision.t; i++) {
    const Segment &s = segments[i];
    // Real with probability extinction / majorant.
    forEachTentativeCollision(s,
        std::min(s.t1, collision.t),
        majorantGrid,
        random,
        [&](float t, float majorant, float sigma, const float3 &color) {
          if (random.next() * majorant >= sigma)
            return true;
          collision.t = t;
          collision.color = color;
          collision.objectId = s.placed->volume->id();
          collision.instanceId = s.placed->instanceId;
          return false;
        });
  }
  return collision.t < std::numeric_limits<float>::infinity();
}

float trackTransmittance(const World &world,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    HashedStream &random)
{
  Segment segments[kMaxSegments];
  const int count =
      segmentsAlong(world, origin, direction, tMin, tMax, 1.f, segments);
  float transmittance = 1.f;
  for (int i = 0; i < count && transmittance > 0.f; i++) {
    forEachTentativeCollision(segments[i],
        segments[i].t1,
        true,
        random,
        [&](float, float majorant, float sigma, const float3 &) {
          transmittance *= std::max(0.f, 1.f - sigma / majorant);
          // Small weights end by roulette instead of many more steps.
          if (transmittance < 0.1f) {
            if (random.next() >= transmittance * 10.f) {
              transmittance = 0.f;
              return false;
            }
            transmittance = 0.1f;
          }
          return true;
        });
  }
  return transmittance;
}

} // namespace prism
