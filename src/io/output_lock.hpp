#pragma once
/// One run per output directory. Two runs writing the same --out directory interleave their
/// histories and rename each other's restart dumps away, so a run holds an advisory lock on
/// DIR/.mcdyna.lock (flock) for as long as it writes there; a second run is refused with the
/// first one's process id. The lock goes with the process, however it ends.
#include <filesystem>
#include <string>

namespace mcdyna::io {

class OutputLock {
 public:
  /// Takes the lock of `dir` (an existing directory). On failure holds nothing and problem()
  /// says why ("another mcdyna run (process 123) is writing to DIR").
  explicit OutputLock(const std::filesystem::path& dir);
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  ~OutputLock();
  [[nodiscard]] const std::string& problem() const { return problem_; }

 private:
  int fd_ = -1;
  std::string problem_;
};

}  // namespace mcdyna::io
