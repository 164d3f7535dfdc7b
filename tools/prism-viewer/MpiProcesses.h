// prism-viewer under mpirun: rank 0 shows the window and sends every
// change to the other processes as one line (ViewerSession::mirrorTo);
// they make the same changes on their own device (prism_mpi's collective
// calls then match) and render when rank 0 renders. Without MPI (or
// outside mpirun) this is one process and nothing is sent.
#pragma once

#include <string>

namespace prism::viewer {

class MpiProcesses
{
 public:
  // Starts MPI when the program runs under mpirun (MPI_THREAD_SERIALIZED,
  // as prism_mpi asks); finalizes it on destruction.
  MpiProcesses();
  ~MpiProcesses();
  MpiProcesses(const MpiProcesses &) = delete;
  MpiProcesses &operator=(const MpiProcesses &) = delete;

  int rank() const
  {
    return m_rank;
  }
  int size() const
  {
    return m_size;
  }
  // Rank 0: sends `line` to every other process.
  void send(const std::string &line) const;
  // The other ranks: the next line rank 0 sent.
  std::string receive() const;

 private:
  int m_rank{0};
  int m_size{1};
  bool m_started{false};
};

} // namespace prism::viewer
