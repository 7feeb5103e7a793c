#pragma once
/// Files whose every write is checked. A full disk, a vanished file system or a write the kernel
/// refuses is a WriteError naming the file, never a silent short file or a crash, and what is on
/// disk stays readable: a whole file is written under a temporary name and renamed, and a
/// record file is cut back to its last whole record when a record cannot be written whole.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace mcdyna::io {

/// A write that failed; what() names the file and the system's reason ("No space left on
/// device").
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `bytes` to `path` through `path.part` and a rename. On failure the part file is removed
/// and WriteError thrown; a file already at `path` is then the earlier, whole one.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// An append-only file written in whole records: text is collected in pending() and commit()
/// writes it in one go. A record that cannot be written whole is cut off again, so the file ends
/// with the last whole record (a CSV never ends mid-row).
class RecordFile {
 public:
  RecordFile() = default;
  /// Creates `path` empty (truncating it).
  static RecordFile create(const std::filesystem::path& path);
  /// Continues `path` cut back to `bytes` (its size at a restart dump); a file that is missing or
  /// shorter is not the one the dump continues: std::runtime_error.
  static RecordFile continue_at(const std::filesystem::path& path, std::uint64_t bytes);
  RecordFile(RecordFile&& o) noexcept;
  RecordFile& operator=(RecordFile&& o) noexcept;
  RecordFile(const RecordFile&) = delete;
  RecordFile& operator=(const RecordFile&) = delete;
  ~RecordFile();

  /// The record being built; commit() writes it.
  [[nodiscard]] std::string& pending() { return pending_; }
  /// Writes the pending record whole or throws WriteError with the file cut back to size().
  void commit();
  /// Cuts the file back to `bytes` (no more than size()): the tail of a record that the next one
  /// replaces (d3plot's end-of-file marker and padding before the next state).
  void cut_back(std::uint64_t bytes);
  /// Bytes on disk: whole records only.
  [[nodiscard]] std::uint64_t size() const { return size_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  RecordFile(std::filesystem::path path, int fd, std::uint64_t size);
  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  std::string pending_;
};

}  // namespace mcdyna::io
