#include "MpiSession.h"

#include <mpi.h>

namespace prism::mpi {

MpiSession::MpiSession()
{
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (finalized) {
    m_problem =
        "MPI was already finalized in this process; the device renders"
        " on this process alone";
    return;
  }
  if (!initialized) {
    // The device's MPI calls come one at a time: from the thread calling
    // the ANARI API, or (pathtracer mode) its render thread while that
    // thread waits.
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided)
        != MPI_SUCCESS) {
      m_problem =
          "MPI_Init_thread failed; the device renders on this process"
          " alone";
      return;
    }
    m_ownsMpi = true;
  }
  m_usable = true;
}

MpiSession::~MpiSession()
{
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (m_ownsMpi && !finalized)
    MPI_Finalize();
}

} // namespace prism::mpi
