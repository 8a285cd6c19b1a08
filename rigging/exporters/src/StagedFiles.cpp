#include "StagedFiles.h"

#include <lacrima/common/Diagnostics.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include <fcntl.h>
#include <unistd.h>

namespace lacrima::exporters {
namespace {

[[noreturn]] void failWith(const std::string& path, const std::string& action, int error) {
  throw FileError({path, 0, 0}, action + ": " + std::strerror(error));
}

// Opens a new file "<target>.tmp-<random>" that did not exist before (O_EXCL), so two exports
// of the same target never write into each other's temporary. Mode 0666 lets the umask decide
// the final permissions, as they would be for a file written directly.
int createTemporary(const std::string& target, std::string& temporary) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::random_device entropy;
  for (int attempt = 0; attempt < 16; ++attempt) {
    const unsigned long long bits = (static_cast<unsigned long long>(entropy()) << 32) ^ entropy();
    temporary = target + ".tmp-";
    for (int k = 0; k < 12; ++k) temporary += kHex[(bits >> (4 * k)) & 0xf];
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

// write() may write less than asked (signals, pipes); loop until everything is out.
bool writeAll(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

}  // namespace

StagedFiles::~StagedFiles() {
  for (const Staged& s : staged_) ::unlink(s.temporary.c_str());
}

void StagedFiles::add(const std::string& path, std::string_view bytes) {
  std::string temporary;
  const int fd = createTemporary(path, temporary);
  if (fd < 0) failWith(path, "cannot write", errno);
  // fsync before the rename: otherwise a crash soon after commit() can leave an empty file
  // under the target's name on file systems that reorder metadata and data.
  const bool ok = writeAll(fd, bytes) && ::fsync(fd) == 0;
  const int error = errno;
  const bool closed = ::close(fd) == 0;
  if (!ok || !closed) {
    const int reason = ok ? errno : error;
    ::unlink(temporary.c_str());
    failWith(path, "cannot write", reason);
  }
  staged_.push_back({path, std::move(temporary)});
}

void StagedFiles::commit() {
  while (!staged_.empty()) {
    const Staged& s = staged_.front();
    if (std::rename(s.temporary.c_str(), s.target.c_str()) != 0)
      failWith(s.target, "cannot replace", errno);
    staged_.erase(staged_.begin());
  }
}

std::string readFileBytes(const std::string& path, const std::string& what) {
  const std::string action = "cannot read " + what;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) failWith(path, action, errno);
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      const int error = errno;  // e.g. EISDIR: open() accepts a directory, read() does not
      ::close(fd);
      failWith(path, action, error);
    }
    bytes.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(fd);
  return bytes;
}

}  // namespace lacrima::exporters
