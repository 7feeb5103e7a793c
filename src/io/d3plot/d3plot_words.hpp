#pragma once
/// The words of an LS-DYNA binary database ("LS-DYNA Database Binary Output Files", LSTC): every
/// number is one word, 4 bytes in single precision (the default) or 8 with *DATABASE_FORMAT
/// IBINARY 0 read as 64-bit, integers and reals alike, in the machine's byte order (little
/// endian here, as LS-DYNA on x86-64 writes). Text fills whole words, padded with blanks.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace mcdyna::io::d3plot {

/// LS-DYNA's end-of-file marker: a real word -999999.0 after the last state of a file (and
/// after the geometry and after the titles).
inline constexpr double kEndOfFile = -999999.0;
/// Files of a family are written in records of 512 words: a file's length is a multiple of it,
/// the tail zero.
inline constexpr std::int64_t kRecordWords = 512;

class Words {
 public:
  explicit Words(int word_bytes) : bytes_(word_bytes) {}

  void integer(std::int64_t v) {
    if (bytes_ == 4) {
      put(static_cast<std::int32_t>(v));
    } else {
      put(v);
    }
  }
  void real(double v) {
    if (bytes_ == 4) {
      put(static_cast<float>(v));
    } else {
      put(v);
    }
  }
  /// `text` in `words` words, cut or padded with blanks.
  void text(std::string_view text, std::int64_t words) { chars(text, words * bytes_); }
  /// `text` in exactly `count` characters, cut or padded with blanks (the part titles are 72
  /// characters whatever the word size).
  void chars(std::string_view text, std::int64_t count) {
    std::string s(text.substr(0, static_cast<std::size_t>(count)));
    s.resize(static_cast<std::size_t>(count), ' ');
    data_ += s;
  }
  /// Zero words up to the next multiple of kRecordWords.
  void pad_to_record() {
    const auto words = static_cast<std::int64_t>(data_.size()) / bytes_;
    const std::int64_t rest = (kRecordWords - words % kRecordWords) % kRecordWords;
    data_.append(static_cast<std::size_t>(rest * bytes_), '\0');
  }

  [[nodiscard]] std::int64_t size() const {
    return static_cast<std::int64_t>(data_.size()) / bytes_;
  }
  [[nodiscard]] const std::string& bytes() const { return data_; }
  [[nodiscard]] int word_bytes() const { return bytes_; }

 private:
  template <class T>
  void put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    data_.append(b, sizeof(T));
  }
  int bytes_;
  std::string data_;
};

}  // namespace mcdyna::io::d3plot
