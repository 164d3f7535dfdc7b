// Pathtracer mode's lights: each process places the emitters and declared
// lights of its own part of the scene, but any process may shade any
// path, so every process must sample every process's lights in next-event
// estimation, with the same light list and the same selection
// probabilities as one process holding the whole scene. The processes send
// one another their placed emitters (world-space triangles and spheres and
// their radiance), bounds and, where they differ, declared lights once per
// change of any of their worlds.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>

namespace prism {
class World;
}

namespace prism::mpi {

struct EmitterExchangeResult
{
  bool exchanged{false};    // the emitters were sent this time
  bool lightsShared{false}; // and the declared lights, which differed
  uint64_t bytesSent{0};    // by this process, to all the others
  std::string problem;      // why the world keeps its own emitters only
};

// Collective over `communicator` (every process calls it with the world of
// the frame they render together). When any process's world placed its
// lights anew since the last exchange (World::sharesEmitters() false on
// it), every process sends the others its own emitters and bounds, and
// each world then holds, after its declared lights, every process's
// emitters in rank order (rank 0's first), each process's in its
// placement order, with light selection weighed by the bounds of all the
// worlds together. When the processes' declared lights differ (count or
// World::declaredLightsHash()), each also sends its declared lights
// (LightExchange.h) and every world declares every process's, a light
// declared alike on several processes once, in rank order
// (World::shareLights()). Otherwise nothing but one flag is reduced. On
// one process the world is left as it is and nothing is called. Without
// `withEmitters` (composite mode) only the declared lights are shared
// (World::shareDeclaredLights()), and each world keeps its own emitters.
EmitterExchangeResult shareLights(
    World &world, MPI_Comm communicator, bool withEmitters = true);

} // namespace prism::mpi
