#include "Rendezvous.h"
#include "PoliteWait.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

namespace prism::mpi {
namespace {

// Tags of the device's own point-to-point messages on the application's
// communicator (collectives never match point-to-point messages); below the
// 32767 every MPI accepts.
constexpr int kDescriptorTag = 32080;
constexpr int kVerdictTag = 32081;

enum class Outcome : uint32_t {
  Render,
  Disagree,
  Missing,
};

struct Verdict
{
  uint32_t outcome{0};
  uint32_t allValid{0};
  // The attempt this verdict answers, so a verdict meant for an attempt its
  // receiver gave up on is never taken for a later one.
  uint64_t attempt{0};
  char problem[2048]{};
};

// Cancels a receive that timed out; false when its message had arrived
// meanwhile (the receive then completed and its buffer holds the message).
bool cancelReceive(MPI_Request &request)
{
  MPI_Cancel(&request);
  MPI_Status status;
  MPI_Wait(&request, &status);
  int cancelled = 0;
  MPI_Test_cancelled(&status, &cancelled);
  return cancelled != 0;
}

std::string secondsText(double seconds)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", seconds);
  return text;
}

} // namespace

Rendezvous::~Rendezvous()
{
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized)
    return;
  forgetSentMessages();
  for (PendingSend &pending : m_pendingSends) {
    // Never received (its receiver gave up): MPI may still read the buffer.
    MPI_Request_free(&pending.request);
    (void)pending.bytes.release();
  }
}

void Rendezvous::forgetSentMessages()
{
  std::erase_if(m_pendingSends, [](PendingSend &pending) {
    int done = 0;
    MPI_Test(&pending.request, &done, MPI_STATUS_IGNORE);
    return done != 0;
  });
}

void Rendezvous::send(
    const void *bytes, size_t size, int to, int tag, MPI_Comm communicator)
{
  PendingSend pending;
  pending.bytes = std::make_unique<std::vector<unsigned char>>(
      (const unsigned char *)bytes, (const unsigned char *)bytes + size);
  MPI_Isend(pending.bytes->data(),
      int(size),
      MPI_BYTE,
      to,
      tag,
      communicator,
      &pending.request);
  m_pendingSends.push_back(std::move(pending));
}

RendezvousResult Rendezvous::meet(const FrameDescriptor &descriptor,
    MPI_Comm communicator,
    double timeoutSeconds)
{
  forgetSentMessages();
  FrameDescriptor local = descriptor;
  local.attempt = m_attempts++;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  const bool forever = !(timeoutSeconds > 0.0);
  const double waitSeconds =
      forever ? 0.0 : (rank == 0 ? timeoutSeconds : 2.0 * timeoutSeconds + 1.0);
  const Clock::time_point deadline =
      Clock::now()
      + std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(waitSeconds));
  const std::string waited = secondsText(timeoutSeconds);

  if (rank != 0) {
    send(&local, sizeof(local), 0, kDescriptorTag, communicator);
    for (;;) {
      Verdict verdict;
      MPI_Request request;
      MPI_Irecv(&verdict,
          sizeof(verdict),
          MPI_BYTE,
          0,
          kVerdictTag,
          communicator,
          &request);
      if (!waitUntil(request, deadline, forever) && cancelReceive(request)) {
        return {false,
            false,
            "rank 0 did not answer within " + secondsText(waitSeconds)
                + " s (twice the device's mpiTimeout, plus a second)"};
      }
      if (verdict.attempt != local.attempt)
        continue; // the answer to an attempt this process gave up on
      verdict.problem[sizeof(verdict.problem) - 1] = '\0';
      return {Outcome(verdict.outcome) == Outcome::Render,
          verdict.allValid != 0,
          verdict.problem};
    }
  }

  std::vector<FrameDescriptor> all(ranks);
  all[0] = local;
  std::vector<MPI_Request> receives(ranks, MPI_REQUEST_NULL);
  for (int r = 1; r < ranks; r++) {
    MPI_Irecv(&all[r],
        sizeof(FrameDescriptor),
        MPI_BYTE,
        r,
        kDescriptorTag,
        communicator,
        &receives[r]);
  }
  std::vector<int> missing;
  for (int r = 1; r < ranks; r++) {
    if (!waitUntil(receives[r], deadline, forever)
        && cancelReceive(receives[r]))
      missing.push_back(r);
  }

  Verdict verdict;
  std::string problem;
  if (!missing.empty()) {
    verdict.outcome = uint32_t(Outcome::Missing);
    problem = missing.size() > 1 ? "ranks " : "rank ";
    for (size_t i = 0; i < missing.size(); i++) {
      problem += i ? "," : "";
      problem += std::to_string(missing[i]);
    }
    problem += " did not call anariRenderFrame within " + waited
               + " s (the device's mpiTimeout)";
  } else {
    problem = describeDisagreement(all);
    verdict.outcome =
        uint32_t(problem.empty() ? Outcome::Render : Outcome::Disagree);
    if (!problem.empty())
      problem =
          "the processes of the frame's communicator disagree: " + problem;
    verdict.allValid = 1;
    for (const FrameDescriptor &d : all)
      verdict.allValid = verdict.allValid && d.valid;
  }
  std::strncpy(verdict.problem, problem.c_str(), sizeof(verdict.problem) - 1);
  for (int r = 1; r < ranks; r++) {
    if (std::find(missing.begin(), missing.end(), r) != missing.end())
      continue;
    verdict.attempt = all[r].attempt;
    send(&verdict, sizeof(verdict), r, kVerdictTag, communicator);
  }
  return {Outcome(verdict.outcome) == Outcome::Render,
      verdict.allValid != 0,
      problem};
}

} // namespace prism::mpi
