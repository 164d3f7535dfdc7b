// MPI's lifetime as the device sees it: initialised by the device only when
// the application has not done so, and then finalized by the device alone.
#pragma once

#include <string>

namespace prism::mpi {

class MpiSession
{
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession &) = delete;
  MpiSession &operator=(const MpiSession &) = delete;

  // False when MPI was finalized before the device was created (MPI cannot
  // start twice in a process); the device then renders alone.
  bool usable() const
  {
    return m_usable;
  }
  // Why the session is not usable, for the status callback.
  const std::string &problem() const
  {
    return m_problem;
  }

 private:
  bool m_usable{false};
  bool m_ownsMpi{false};
  std::string m_problem;
};

} // namespace prism::mpi
