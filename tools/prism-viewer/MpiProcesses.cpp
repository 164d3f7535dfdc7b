#include "MpiProcesses.h"

#ifdef PRISM_VIEWER_HAS_MPI
#include <mpi.h>
#endif

#include <cstdlib>

namespace prism::viewer {

#ifdef PRISM_VIEWER_HAS_MPI

namespace {

// Open MPI's and MPICH's (PMI) launchers say how many processes they ran.
bool launchedByMpirun()
{
  for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name))
      return true;
  return false;
}

} // namespace

MpiProcesses::MpiProcesses()
{
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    if (!launchedByMpirun())
      return;
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided)
        != MPI_SUCCESS)
      return;
    m_started = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &m_size);
}

MpiProcesses::~MpiProcesses()
{
  if (m_started)
    MPI_Finalize();
}

void MpiProcesses::send(const std::string &line) const
{
  if (m_size < 2)
    return;
  unsigned long long length = line.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  MPI_Bcast((void *)line.data(), int(length), MPI_CHAR, 0, MPI_COMM_WORLD);
}

std::string MpiProcesses::receive() const
{
  unsigned long long length = 0;
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  std::string line(length, '\0');
  MPI_Bcast(line.data(), int(length), MPI_CHAR, 0, MPI_COMM_WORLD);
  return line;
}

#else

MpiProcesses::MpiProcesses() = default;
MpiProcesses::~MpiProcesses() = default;
void MpiProcesses::send(const std::string &) const {}
std::string MpiProcesses::receive() const
{
  return "quit";
}

#endif

} // namespace prism::viewer
