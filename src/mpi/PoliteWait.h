// Waiting on MPI without spinning: MPI implementations busy-poll inside
// blocking calls, which on a shared or oversubscribed machine takes the core
// from the slower processes being waited for. These poll and sleep instead.
#pragma once

#include <mpi.h>

#include <chrono>

namespace prism::mpi {

using Clock = std::chrono::steady_clock;

// Polls `request` until it completes (true) or `deadline` passes (false;
// never when `forever`).
bool waitUntil(MPI_Request &request, Clock::time_point deadline, bool forever);

// A barrier over `communicator` that sleeps while it waits, so the
// collectives after it start together and nobody spins in them.
void politeBarrier(MPI_Comm communicator);

} // namespace prism::mpi
