#pragma once
// What lacrima-import does to itself before it reads a file: the limits the parent asked for
// and what a parser never needs. Each step that the system does not offer is skipped; the
// limits on memory and time, which the parent relies on, are not (a failure there is an error).
#include <cstdint>
#include <string>

namespace lacrima::importer {

struct ConfinementLimits {
  std::uint64_t memoryBytes = 0;  // RLIMIT_AS; 0: none
  long long cpuSeconds = 0;       // RLIMIT_CPU (SIGXCPU, SIGKILL a second later); 0: none
};

// Keeps descriptors 0-2 and `answerFd`, closes every other; dies with the parent
// (PR_SET_PDEATHSIG); no new privileges; no core dumps; no file may grow when the answer goes to
// a pipe (RLIMIT_FSIZE 0); the limits; and, where an unprivileged user namespace can be made, a
// network namespace of its own with nothing in it. Returns "" or what failed.
std::string confine(int answerFd, const ConfinementLimits& limits);

}  // namespace lacrima::importer
