#include "Confinement.h"

#include <dirent.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <vector>

namespace lacrima::importer {
namespace {

void closeOtherDescriptors(int keep) {
  // /proc/self/fd lists exactly what is open; collect first, close after (closing while the
  // directory is read would change it).
  std::vector<int> open;
  if (DIR* dir = ::opendir("/proc/self/fd")) {
    const int own = ::dirfd(dir);
    while (const dirent* entry = ::readdir(dir)) {
      char* end = nullptr;
      const long fd = std::strtol(entry->d_name, &end, 10);
      if (*end == '\0' && end != entry->d_name && fd > 2 && fd != keep && fd != own)
        open.push_back(static_cast<int>(fd));
    }
    ::closedir(dir);
  }
  for (int fd : open) ::close(fd);
}

bool limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit value{soft, hard};
  return ::setrlimit(resource, &value) == 0;
}

// AddressSanitizer reserves terabytes of shadow memory at start: an address-space limit would
// fail every allocation after it. Sanitizer builds rely on the time limits alone.
constexpr bool kAddressSanitizer =
#if defined(__SANITIZE_ADDRESS__)
    true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    true;
#else
    false;
#endif
#else
    false;
#endif

}  // namespace

std::string confine(int answerFd, const ConfinementLimits& limits) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  ::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
  closeOtherDescriptors(answerFd);
  limit(RLIMIT_CORE, 0, 0);
  // The answer goes to a pipe, which no file-size limit concerns; a user who sends it to a file
  // by hand keeps the right to.
  struct stat answer;
  if (::fstat(answerFd, &answer) == 0 && S_ISFIFO(answer.st_mode)) limit(RLIMIT_FSIZE, 0, 0);
  if (limits.memoryBytes > 0 && !kAddressSanitizer &&
      !limit(RLIMIT_AS, limits.memoryBytes, limits.memoryBytes))
    return "cannot limit its memory (setrlimit RLIMIT_AS)";
  if (limits.cpuSeconds > 0 && !limit(RLIMIT_CPU, static_cast<rlim_t>(limits.cpuSeconds),
                                      static_cast<rlim_t>(limits.cpuSeconds + 1)))
    return "cannot limit its processor time (setrlimit RLIMIT_CPU)";
  // No network: a reader needs none. Without unprivileged user namespaces this is skipped.
  ::unshare(CLONE_NEWUSER | CLONE_NEWNET);
  return {};
}

}  // namespace lacrima::importer
