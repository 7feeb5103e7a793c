#pragma once
/// Binary archives for restart dumps. Each struct that goes into a dump lists its members once,
/// in a function found by argument-dependent lookup:
///   template <class Archive> void fields(Archive& ar, Nodes& n) { ar(n.ids, n.position, ...); }
/// and the same function writes (OutArchive) and reads (InArchive). Numbers are stored in the
/// machine's own representation: a dump is read back by the binary that wrote it, on the same
/// kind of machine (as LS-DYNA's d3dump), and every double comes back bit for bit.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace mcdyna::core {

/// A dump that cannot be read: truncated, or not what the reader expects.
class ArchiveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <typename T>
inline constexpr bool kPlainValue = std::is_arithmetic_v<T> || std::is_enum_v<T>;

// Fixed-size aggregates are their members in order, in either direction (found by
// argument-dependent lookup through the archive, which lives here).
template <class Ar, typename T, std::size_t N>
void fields(Ar& ar, std::array<T, N>& a) {
  for (T& x : a)
    ar(x);
}
template <class Ar, typename A, typename B>
void fields(Ar& ar, std::pair<A, B>& p) {
  ar(p.first, p.second);
}

/// 64-bit checksum of a dump section: FNV-1a over 8-byte words with an xorshift after each
/// multiply, so that a change in a high bit reaches every bit. Each step is a bijection of the
/// running value for a given word, so any change confined to one word (a flipped bit, a
/// overwritten byte) always changes the sum; other damage goes unseen with odds of 2^-64.
inline std::uint64_t checksum(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ULL ^ bytes.size();
  auto step = [&h](std::uint64_t word) {
    h ^= word;
    h *= 1099511628211ULL;
    h ^= h >> 32;
  };
  std::size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    std::uint64_t w = 0;
    std::memcpy(&w, bytes.data() + i, 8);
    step(w);
  }
  std::uint64_t tail = 0;
  if (i < bytes.size()) std::memcpy(&tail, bytes.data() + i, bytes.size() - i);
  step(tail);
  return h;
}

/// Writes values into a byte string (a dump section).
class OutArchive {
 public:
  explicit OutArchive(std::string& out) : out_(out) {}
  template <typename... T>
  void operator()(T&... values) {
    (put(values), ...);
  }

 private:
  void bytes(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  void size(std::size_t n) {
    const auto v = static_cast<std::uint64_t>(n);
    bytes(&v, sizeof v);
  }
  template <typename T>
  void put(T& v) {
    if constexpr (kPlainValue<T>) {
      bytes(&v, sizeof v);
    } else {
      fields(*this, v);  // the struct's member list (argument-dependent lookup)
    }
  }
  void put(std::string& s) {
    size(s.size());
    bytes(s.data(), s.size());
  }
  template <typename T>
  void put(std::vector<T>& v) {
    size(v.size());
    if constexpr (kPlainValue<T>) {
      bytes(v.data(), v.size() * sizeof(T));
    } else {
      for (T& x : v)
        put(x);
    }
  }
  template <typename S, int R, int C, int O, int MR, int MC>
  void put(Eigen::Matrix<S, R, C, O, MR, MC>& m) {
    size(static_cast<std::size_t>(m.rows()));
    size(static_cast<std::size_t>(m.cols()));
    bytes(m.data(), static_cast<std::size_t>(m.size()) * sizeof(S));
  }
  std::string& out_;
};

/// Reads values back from bytes written by OutArchive; a size that cannot fit in what is left is
/// refused before anything is allocated for it.
class InArchive {
 public:
  explicit InArchive(std::string_view in) : in_(in), left_(in.size()) {}
  template <typename... T>
  void operator()(T&... values) {
    (get(values), ...);
  }
  /// Bytes not read yet.
  [[nodiscard]] std::uint64_t left() const { return left_; }
  /// Passes over `n` bytes (read by another archive over them).
  void skip(std::uint64_t n) {
    if (n > left_) throw ArchiveError("the dump ends early (truncated file?)");
    left_ -= n;
  }

 private:
  void bytes(void* p, std::size_t n) {
    if (n > left_) throw ArchiveError("the dump ends early (truncated file?)");
    if (n > 0) std::memcpy(p, in_.data() + (in_.size() - left_), n);
    left_ -= n;
  }
  // A count of `element` bytes each that cannot fit in what is left is a corrupt dump.
  std::size_t size(std::size_t element) {
    std::uint64_t v = 0;
    bytes(&v, sizeof v);
    if (element > 0 && v > left_ / element)
      throw ArchiveError("the dump ends early (truncated file?) or is corrupt");
    return static_cast<std::size_t>(v);
  }
  template <typename T>
  void get(T& v) {
    if constexpr (kPlainValue<T>) {
      bytes(&v, sizeof v);
    } else {
      fields(*this, v);
    }
  }
  void get(std::string& s) {
    s.resize(size(1));
    bytes(s.data(), s.size());
  }
  template <typename T>
  void get(std::vector<T>& v) {
    if constexpr (kPlainValue<T>) {
      v.resize(size(sizeof(T)));
      bytes(v.data(), v.size() * sizeof(T));
    } else {
      v.resize(size(1));
      for (T& x : v)
        get(x);
    }
  }
  template <typename S, int R, int C, int O, int MR, int MC>
  void get(Eigen::Matrix<S, R, C, O, MR, MC>& m) {
    const std::size_t rows = size(0), cols = size(0);
    if ((R != Eigen::Dynamic && rows != static_cast<std::size_t>(R)) ||
        (C != Eigen::Dynamic && cols != static_cast<std::size_t>(C)))
      throw ArchiveError("corrupt dump (matrix shape)");
    if (rows > 0 && cols > left_ / (rows * sizeof(S)))
      throw ArchiveError("the dump ends early (truncated file?) or is corrupt");
    m.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    bytes(m.data(), rows * cols * sizeof(S));
  }
  std::string_view in_;
  std::uint64_t left_;
};

}  // namespace mcdyna::core
