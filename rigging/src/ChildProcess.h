#pragma once
// A program run as a child whose answer comes back on a pipe: started with posix_spawn, read
// with poll() under a deadline and a cancel check, killed and reaped by the destructor whatever
// happens (an exception, a cancel), so no child outlives the call that started it.
//
// The child gets: fd 3 the write end of the answer pipe, stderr a pipe whose last few KiB are
// kept (assimp prints its failed assertions there), stdin and stdout /dev/null, no other
// descriptor, every signal at its default and none blocked (a thread of the parent may block
// some; the child must die of SIGXCPU and SIGSEGV, not ignore them).
#include "UniqueFd.h"

#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace lacrima::rigging {

class ChildProcess {
 public:
  using Clock = std::chrono::steady_clock;

  // How the wait ended.
  enum class Stop {
    Exited,        // the child ended by itself: see status()
    Deadline,      // killed at the deadline
    Cancelled,     // killed because cancelled() said so
    AnswerTooLong  // killed: it sent more than maxAnswerBytes
  };

  // Starts `argv` (argv[0] the program's path). Throws std::system_error when it cannot be
  // started (no such program, not executable).
  explicit ChildProcess(const std::vector<std::string>& argv);
  ~ChildProcess();  // a child still running is killed (SIGKILL) and reaped
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // Reads the answer and stderr until the child exits, `deadline` passes, `cancelled` returns
  // true (checked at least every `pollInterval`) or the answer grows past `maxAnswerBytes`; in
  // the last three cases the child is killed at once. The child is reaped before this returns.
  Stop wait(Clock::time_point deadline, const std::function<bool()>& cancelled,
            std::size_t maxAnswerBytes,
            std::chrono::milliseconds pollInterval = std::chrono::milliseconds(20));

  // After wait(): the waitpid status (Exited), the answer's bytes and stderr's last bytes.
  int status() const { return status_; }
  std::string& answer() { return answer_; }
  const std::string& errors() const { return errors_; }

 private:
  void kill();
  void reapBlocking();

  pid_t pid_ = -1;
  bool reaped_ = false;
  int status_ = 0;
  UniqueFd answerPipe_, errorPipe_;
  std::string answer_, errors_;
};

}  // namespace lacrima::rigging
