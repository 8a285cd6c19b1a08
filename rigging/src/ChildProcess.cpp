#include "ChildProcess.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

extern char** environ;

namespace lacrima::rigging {
namespace {

// stderr kept: enough for assimp's last message, bounded whatever the child prints.
constexpr std::size_t kErrorTailBytes = 4096;

[[noreturn]] void throwErrno(const char* what, int error = errno) {
  throw std::system_error(error, std::generic_category(), what);
}

// A pipe whose ends sit at fd 10 or above (so that the child's dup2 onto 2 and 3 never meets
// them) and close on exec; the child gets its end through the spawn's dup2, which clears that.
struct Pipe {
  UniqueFd read, write;
};
Pipe makePipe() {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throwErrno("pipe2");
  UniqueFd low[2] = {UniqueFd(fds[0]), UniqueFd(fds[1])};
  Pipe pipe;
  for (int i = 0; i < 2; ++i) {
    const int fd = ::fcntl(low[i].get(), F_DUPFD_CLOEXEC, 10);
    if (fd < 0) throwErrno("fcntl(F_DUPFD_CLOEXEC)");
    (i == 0 ? pipe.read : pipe.write) = UniqueFd(fd);
  }
  return pipe;
}

class SpawnActions {
 public:
  SpawnActions() { ::posix_spawn_file_actions_init(&actions_); }
  ~SpawnActions() { ::posix_spawn_file_actions_destroy(&actions_); }
  SpawnActions(const SpawnActions&) = delete;
  SpawnActions& operator=(const SpawnActions&) = delete;
  posix_spawn_file_actions_t* get() { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

class SpawnAttributes {
 public:
  SpawnAttributes() { ::posix_spawnattr_init(&attributes_); }
  ~SpawnAttributes() { ::posix_spawnattr_destroy(&attributes_); }
  SpawnAttributes(const SpawnAttributes&) = delete;
  SpawnAttributes& operator=(const SpawnAttributes&) = delete;
  posix_spawnattr_t* get() { return &attributes_; }

 private:
  posix_spawnattr_t attributes_;
};

// Appends what is readable on `fd` to `out`; false at end of file (or a read error).
bool drain(int fd, std::string& out) {
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      out.append(buffer, static_cast<std::size_t>(n));
      return true;
    }
    if (n < 0 && errno == EINTR) continue;
    return n < 0 && errno == EAGAIN;
  }
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv) {
  Pipe answer = makePipe(), errors = makePipe();
  // A larger pipe lets a big head through in fewer wake-ups; the default works too.
  ::fcntl(answer.write.get(), F_SETPIPE_SZ, 1 << 20);

  SpawnActions actions;
  ::posix_spawn_file_actions_addopen(actions.get(), 0, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_addopen(actions.get(), 1, "/dev/null", O_WRONLY, 0);
  ::posix_spawn_file_actions_adddup2(actions.get(), errors.write.get(), 2);
  ::posix_spawn_file_actions_adddup2(actions.get(), answer.write.get(), 3);
  ::posix_spawn_file_actions_addclosefrom_np(actions.get(), 4);

  SpawnAttributes attributes;
  sigset_t none, all;
  sigemptyset(&none);
  sigfillset(&all);
  ::posix_spawnattr_setsigmask(attributes.get(), &none);
  ::posix_spawnattr_setsigdefault(attributes.get(), &all);
  ::posix_spawnattr_setflags(attributes.get(), POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int error =
      ::posix_spawn(&pid_, args[0], actions.get(), attributes.get(), args.data(), environ);
  if (error != 0) throwErrno("posix_spawn", error);

  answerPipe_ = std::move(answer.read);
  errorPipe_ = std::move(errors.read);
  for (int fd : {answerPipe_.get(), errorPipe_.get()})
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
}

ChildProcess::~ChildProcess() {
  if (!reaped_) {
    kill();
    reapBlocking();
  }
}

void ChildProcess::kill() {
  if (!reaped_) ::kill(pid_, SIGKILL);
}

void ChildProcess::reapBlocking() {
  while (!reaped_) {
    if (::waitpid(pid_, &status_, 0) == pid_ || errno != EINTR) reaped_ = true;
  }
}

ChildProcess::Stop ChildProcess::wait(Clock::time_point deadline,
                                      const std::function<bool()>& cancelled,
                                      std::size_t maxAnswerBytes,
                                      std::chrono::milliseconds pollInterval) {
  using std::chrono::duration_cast;
  using std::chrono::milliseconds;
  const auto stop = [&](Stop why) {
    kill();
    reapBlocking();
    return why;
  };
  for (;;) {
    if (cancelled && cancelled()) return stop(Stop::Cancelled);
    const auto now = Clock::now();
    if (now >= deadline) return stop(Stop::Deadline);
    const int timeout = static_cast<int>(
        std::min(duration_cast<milliseconds>(deadline - now) + milliseconds(1), pollInterval)
            .count());
    pollfd fds[2];
    nfds_t count = 0;
    for (const UniqueFd* fd : {&answerPipe_, &errorPipe_})
      if (fd->valid()) fds[count++] = {fd->get(), POLLIN, 0};
    if (count == 0) {
      // Both pipes are closed: the child is exiting, or closed them and goes on (it must not
      // escape the deadline that way).
      if (::waitpid(pid_, &status_, WNOHANG) == pid_) {
        reaped_ = true;
        return Stop::Exited;
      }
      ::poll(nullptr, 0, 1);
      continue;
    }
    if (::poll(fds, count, timeout) < 0 && errno != EINTR) throwErrno("poll");
    for (nfds_t i = 0; i < count; ++i) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const bool isAnswer = fds[i].fd == answerPipe_.get();
      std::string& out = isAnswer ? answer_ : errors_;
      if (!drain(fds[i].fd, out)) (isAnswer ? answerPipe_ : errorPipe_).reset();
      if (!isAnswer && errors_.size() > kErrorTailBytes)
        errors_.erase(0, errors_.size() - kErrorTailBytes);
      if (isAnswer && answer_.size() > maxAnswerBytes) return stop(Stop::AnswerTooLong);
    }
  }
}

}  // namespace lacrima::rigging
