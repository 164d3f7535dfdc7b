#include "PoliteWait.h"

#include <thread>

namespace prism::mpi {

bool waitUntil(MPI_Request &request, Clock::time_point deadline, bool forever)
{
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done)
      return true;
    if (!forever && Clock::now() >= deadline)
      return false;
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

void politeBarrier(MPI_Comm communicator)
{
  MPI_Request request;
  MPI_Ibarrier(communicator, &request);
  waitUntil(request, Clock::time_point{}, true);
}

} // namespace prism::mpi
