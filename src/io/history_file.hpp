#pragma once
/// An LS-DYNA ASCII history file and its CSV twin (one header row, one row per entity and output
/// time). Each output block is written whole at flush(), every write checked: a killed run or a
/// full disk leaves whole rows (a block that cannot be written is cut off again and WriteError
/// names the file).
#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "io/checked_file.hpp"
#include "solver/history_records.hpp"
#include "solver/state.hpp"

namespace mcdyna::io {

/// What every history writer gets at an output time.
struct OutputContext {
  const solver::State& state;
  const Eigen::Matrix3Xd& previous;  ///< v^{n-1/2} (the state holds v^{n+1/2})
  const Eigen::Matrix3Xd& velocity;  ///< nodal velocities at t^n (mean of the half steps)
  /// The blocks' lines of the histories at t^n, collected once for every file written.
  const solver::HistoryRecords& records;
  double nanoseconds_per_zone_cycle = 0.0;
};

/// Where a history file continues after a restart dump: its two files' sizes at the dump (what
/// was written later is cut off) and the writer's own values (HistoryFile::saved_values).
struct HistoryResume {
  std::string name;
  std::uint64_t ascii_bytes = 0, csv_bytes = 0;
  std::vector<double> values;
};

/// The output directory, and for a restarted run the histories to continue (by name).
struct HistoryPlace {
  std::filesystem::path dir;
  const std::vector<HistoryResume>* resume = nullptr;
};

class HistoryFile {
 public:
  /// Opens dir/name and dir/name.csv and writes the LS-DYNA header and the CSV header row; when
  /// `place` continues a run, cuts both files back to their size at the dump and appends to them
  /// instead, writing nothing until continue_records().
  HistoryFile(const HistoryPlace& place, const std::string& name, const std::string& title,
              const std::string& csv_header);
  virtual ~HistoryFile() = default;
  HistoryFile(const HistoryFile&) = delete;
  HistoryFile& operator=(const HistoryFile&) = delete;

  virtual void write(const OutputContext& c) = 0;
  [[nodiscard]] const std::string& name() const { return name_; }
  /// For a restart dump: the files' sizes now and the writer's own values.
  [[nodiscard]] HistoryResume resume_point() const;
  /// After a restarted run built this writer: restores its values; records follow.
  void continue_records(const HistoryResume& r);

 protected:
  // The format strings are checked against the arguments at the call site; numbers are printed
  // with -0 as 0 (a reaction of -0.0000E+00 reads like a sign error).
  template <typename... Args>
  void ascii(fmt::format_string<Args...> f, Args&&... args) {
    if (holding_) return;
    fmt::format_to(std::back_inserter(ascii_.pending()), fmt::runtime(fmt::string_view(f)),
                   without_negative_zero(args)...);
  }
  template <typename... Args>
  void csv(fmt::format_string<Args...> f, Args&&... args) {
    if (holding_) return;
    fmt::format_to(std::back_inserter(csv_.pending()), fmt::runtime(fmt::string_view(f)),
                   without_negative_zero(args)...);
  }
  /// Values beside the files that later records depend on (glstat's initial energy).
  [[nodiscard]] virtual std::vector<double> saved_values() const { return {}; }
  /// Writes the block built since the last flush to both files; WriteError if it cannot.
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
  virtual void restore_values(const std::vector<double>& values) {
    if (!values.empty()) throw std::runtime_error(name_ + ": unexpected values in the dump");
  }
  std::string name_;
  RecordFile ascii_, csv_;
  bool holding_ = false;  ///< continuing a run: the headers are in the files already
};

/// Creates the writer for an ASCII database name (glstat, matsum, nodout, spcforc, rwforc,
/// bndout); nullptr for names mcdyna does not write.
std::unique_ptr<HistoryFile> make_history(const std::string& name, const HistoryPlace& place,
                                          const solver::State& state,
                                          const std::vector<solver::Index>& history_nodes);

}  // namespace mcdyna::io
