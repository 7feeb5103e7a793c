#include "io/output_lock.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string_view>

namespace mcdyna::io {

OutputLock::OutputLock(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / ".mcdyna.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    problem_ = fmt::format("cannot open {}: {}", path.string(), std::strerror(errno));
    return;
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    char pid[32] = {};
    const ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
    std::string_view holder(pid, n > 0 ? static_cast<std::size_t>(n) : 0);
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' '))
      holder.remove_suffix(1);
    problem_ = error == EWOULDBLOCK
                   ? fmt::format(
                         "another mcdyna run{} is writing to {}; give each run its own "
                         "--out directory",
                         holder.empty() ? "" : fmt::format(" (process {})", holder), dir.string())
                   : fmt::format("cannot lock {}: {}", path.string(), std::strerror(error));
    ::close(fd_);
    fd_ = -1;
    return;
  }
  // Who holds it, for the message of a run that is refused. Best effort: if this write fails the
  // lock holds all the same, and only a refused run's message lacks the process id.
  const std::string me = fmt::format("{}\n", ::getpid());
  if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, me.data(), me.size(), 0);
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace mcdyna::io
