#include "io/checked_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

namespace mcdyna::io {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const char* doing, int error) {
  throw WriteError(fmt::format("cannot {} {}: {}", doing, path.string(),
                               std::generic_category().message(error)));
}

// write(2) until every byte is out; false (errno set) on the first failure. A short write with no
// error (a full disk reports one before ENOSPC) is retried, which then reports the error.
bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

int open_for_writing(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | flags, 0644);
  if (fd < 0) fail(path, "open for writing", errno);
  return fd;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  const std::filesystem::path part = path.string() + ".part";
  const int fd = open_for_writing(part, O_TRUNC);
  const bool written = write_all(fd, bytes);
  const int write_error = errno;
  // close() reports errors a file system defers (NFS, quota) to the last moment.
  const bool closed = ::close(fd) == 0;
  const int close_error = errno;
  std::error_code ec;
  if (!written || !closed) {
    std::filesystem::remove(part, ec);
    fail(path, "write", !written ? write_error : close_error);
  }
  std::filesystem::rename(part, path, ec);
  if (ec) {
    const int rename_error = ec.value();  // before remove() overwrites ec
    std::filesystem::remove(part, ec);
    fail(path, "rename into place", rename_error);
  }
}

RecordFile::RecordFile(std::filesystem::path path, int fd, std::uint64_t size)
    : path_(std::move(path)), fd_(fd), size_(size) {}

RecordFile RecordFile::create(const std::filesystem::path& path) {
  return RecordFile(path, open_for_writing(path, O_TRUNC), 0);
}

RecordFile RecordFile::continue_at(const std::filesystem::path& path, std::uint64_t bytes) {
  std::error_code ec;
  const std::uintmax_t have = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot continue {}: it is missing", path.string()));
  if (have < bytes)
    throw std::runtime_error(
        fmt::format("cannot continue {}: it is shorter ({} bytes) than when the restart dump was "
                    "written ({} bytes)",
                    path.string(), have, bytes));
  const int fd = open_for_writing(path, 0);
  if (::ftruncate(fd, static_cast<off_t>(bytes)) != 0 ||
      ::lseek(fd, static_cast<off_t>(bytes), SEEK_SET) < 0) {
    const int error = errno;
    ::close(fd);
    fail(path, "cut back", error);
  }
  return RecordFile(path, fd, bytes);
}

RecordFile::RecordFile(RecordFile&& o) noexcept
    : path_(std::move(o.path_)), fd_(o.fd_), size_(o.size_), pending_(std::move(o.pending_)) {
  o.fd_ = -1;
}

RecordFile& RecordFile::operator=(RecordFile&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) ::close(fd_);
    path_ = std::move(o.path_);
    fd_ = o.fd_;
    size_ = o.size_;
    pending_ = std::move(o.pending_);
    o.fd_ = -1;
  }
  return *this;
}

RecordFile::~RecordFile() {
  if (fd_ >= 0) ::close(fd_);
}

void RecordFile::cut_back(std::uint64_t bytes) {
  if (bytes > size_) throw std::logic_error("RecordFile::cut_back beyond the file's end");
  if (::ftruncate(fd_, static_cast<off_t>(bytes)) != 0 ||
      ::lseek(fd_, static_cast<off_t>(bytes), SEEK_SET) < 0)
    fail(path_, "truncate", errno);
  size_ = bytes;
}

void RecordFile::commit() {
  if (pending_.empty()) return;
  if (!write_all(fd_, pending_)) {
    const int error = errno;
    pending_.clear();
    // Cut off the part of the record that did reach the disk (freeing room, if anything).
    if (::ftruncate(fd_, static_cast<off_t>(size_)) == 0)
      ::lseek(fd_, static_cast<off_t>(size_), SEEK_SET);
    fail(path_, "write", error);
  }
  size_ += pending_.size();
  pending_.clear();
}

}  // namespace mcdyna::io
