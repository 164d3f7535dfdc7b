// Where the processes of a communicator meet at anariRenderFrame: rank 0
// collects every process's frame descriptor and answers each with one
// verdict (render, disagree, or a process is missing). Point-to-point rather
// than a collective, so that rank 0 can tell which processes never came and
// every process can give up after a timeout instead of hanging.
#pragma once

#include "FrameAgreement.h"

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace prism::mpi {

struct RendezvousResult
{
  bool render{false};   // every process came and agrees
  bool allValid{false}; // every process's frame is valid
  std::string problem;  // why not, naming the ranks
};

class Rendezvous
{
 public:
  Rendezvous() = default;
  ~Rendezvous();
  Rendezvous(const Rendezvous &) = delete;
  Rendezvous &operator=(const Rendezvous &) = delete;

  // Called by every process of `communicator`. `timeoutSeconds` <= 0 waits
  // for the others as long as it takes; otherwise rank 0 waits that long for
  // the others, and they wait twice as long (plus a second) for its answer,
  // so only a rank 0 that never comes is blamed by them.
  RendezvousResult meet(const FrameDescriptor &local,
      MPI_Comm communicator,
      double timeoutSeconds);

 private:
  // A message whose buffer must live until MPI has sent it (a process that
  // gave up waiting may leave one behind).
  struct PendingSend
  {
    MPI_Request request{MPI_REQUEST_NULL};
    std::unique_ptr<std::vector<unsigned char>> bytes;
  };
  void send(const void *bytes, size_t size, int to, int tag, MPI_Comm comm);
  void forgetSentMessages();

  std::vector<PendingSend> m_pendingSends;
  uint64_t m_attempts{0};
};

} // namespace prism::mpi
