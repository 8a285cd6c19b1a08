#pragma once
// Real file-system faults for tests, each for the lifetime of an object: a disk that fills
// mid-write, and a folder the process may not write to.
//
// Both act on the calling thread or process only and undo themselves, so a suite can go on
// saving normally afterwards. Saves in Lacrima happen on the thread that asks for them, which is
// what makes per-thread faults enough.
#include <fcntl.h>
#include <linux/capability.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <QString>

#include <csignal>
#include <cstdint>
#include <string>

namespace lacrima::test {

// A disk that is full after `bytes`: RLIMIT_FSIZE makes every write past that offset in any
// regular file fail with EFBIG (SIGXFSZ, which would kill the process, is ignored meanwhile).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    previousHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit limited = previous_;
    limited.rlim_cur = bytes;
    active_ = setrlimit(RLIMIT_FSIZE, &limited) == 0;
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previousHandler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

  bool active() const { return active_; }

 private:
  rlimit previous_{};
  void (*previousHandler_)(int) = SIG_DFL;
  bool active_ = false;
};

// A folder this thread may read but not write to: its mode becomes r-x for everyone, and, since
// root ignores modes, the thread also gives up the capabilities that let it (CAP_DAC_OVERRIDE,
// CAP_FOWNER) from its effective set. Both come back afterwards: the capabilities stay in the
// permitted set, from which a thread may raise them again.
class ReadOnlyFolder {
 public:
  explicit ReadOnlyFolder(const QString& folder) : folder_(folder.toStdString()) {
    struct stat info {};
    if (::stat(folder_.c_str(), &info) == 0) previousMode_ = info.st_mode & 07777;
    ::chmod(folder_.c_str(), 0555);
    if (capget(saved_)) {
      __user_cap_data_struct lowered[2] = {saved_[0], saved_[1]};
      lowered[0].effective &= ~((1u << CAP_DAC_OVERRIDE) | (1u << CAP_FOWNER));
      lowered_ = capset(lowered);
    }
  }
  ~ReadOnlyFolder() {
    if (lowered_) capset(saved_);
    ::chmod(folder_.c_str(), previousMode_);
  }
  ReadOnlyFolder(const ReadOnlyFolder&) = delete;
  ReadOnlyFolder& operator=(const ReadOnlyFolder&) = delete;

  // True when a new file really cannot be made in the folder now.
  bool refusesWrites() const {
    const std::string probe = folder_ + "/.lacrima-write-probe";
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) return true;
    ::close(fd);
    ::unlink(probe.c_str());
    return false;
  }

 private:
  static bool capget(__user_cap_data_struct (&data)[2]) {
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    return ::syscall(SYS_capget, &header, data) == 0;
  }
  static bool capset(__user_cap_data_struct (&data)[2]) {
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    return ::syscall(SYS_capset, &header, data) == 0;
  }

  std::string folder_;
  mode_t previousMode_ = 0755;
  __user_cap_data_struct saved_[2]{};
  bool lowered_ = false;
};

}  // namespace lacrima::test
