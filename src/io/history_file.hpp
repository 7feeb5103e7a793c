#pragma once
/// An LS-DYNA ASCII history file and its CSV twin (one header row, one row per entity and output
/// time). Both are flushed after every output block, so a killed run leaves whole rows.
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <type_traits>

#include "solver/state.hpp"

namespace mcdyna::io {

/// What every history writer gets at an output time.
struct OutputContext {
  const solver::State& state;
  const Eigen::Matrix3Xd& previous;  ///< v^{n-1/2} (the state holds v^{n+1/2})
  const Eigen::Matrix3Xd& velocity;  ///< nodal velocities at t^n (mean of the half steps)
  double nanoseconds_per_zone_cycle = 0.0;
};

class HistoryFile {
 public:
  /// Opens dir/name and dir/name.csv and writes the LS-DYNA header and the CSV header row.
  HistoryFile(const std::filesystem::path& dir, const std::string& name, const std::string& title,
              const std::string& csv_header);
  virtual ~HistoryFile() = default;
  HistoryFile(const HistoryFile&) = delete;
  HistoryFile& operator=(const HistoryFile&) = delete;

  virtual void write(const OutputContext& c) = 0;
  [[nodiscard]] const std::string& name() const { return name_; }

 protected:
  // The format strings are checked against the arguments at the call site; numbers are printed
  // with -0 as 0 (a reaction of -0.0000E+00 reads like a sign error).
  template <typename... Args>
  void ascii(fmt::format_string<Args...> f, Args&&... args) {
    fmt::print(ascii_.get(), fmt::runtime(fmt::string_view(f)), without_negative_zero(args)...);
  }
  template <typename... Args>
  void csv(fmt::format_string<Args...> f, Args&&... args) {
    fmt::print(csv_.get(), fmt::runtime(fmt::string_view(f)), without_negative_zero(args)...);
  }
  void flush();
  /// "{BEGIN LEGEND}" block listing entity IDs and titles.
  void legend(const std::vector<std::pair<long long, std::string>>& entities);

 private:
  template <typename T>
  static decltype(auto) without_negative_zero(const T& v) {
    if constexpr (std::is_floating_point_v<T>)
      return v + T(0);  // -0 + 0 = +0
    else
      return (v);
  }
  struct Closer {
    void operator()(std::FILE* f) const {
      if (f) std::fclose(f);
    }
  };
  std::string name_;
  std::unique_ptr<std::FILE, Closer> ascii_, csv_;
};

/// Creates the writer for an ASCII database name (glstat, matsum, nodout, spcforc, rwforc,
/// bndout); nullptr for names mcdyna does not write.
std::unique_ptr<HistoryFile> make_history(const std::string& name, const std::filesystem::path& dir,
                                          const solver::State& state,
                                          const std::vector<solver::Index>& history_nodes);

}  // namespace mcdyna::io
