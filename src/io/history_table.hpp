// Reading time histories back: our CSV files, other engineers' CSV and LS-DYNA's ASCII files
// (glstat, rcforc, nodout, spcforc, bndout, matsum, rwforc) into one wide table of named columns.
//
// Files that list several entities per time (rcforc sides, nodout nodes, matsum parts …) are
// pivoted: one column per quantity and entity, named `quantity@key`, e.g. `z_force@1/slave`,
// `x_disp@1009569`, `internal_energy@3`, `z_force@rigid_part/3`. Our CSV and LS-DYNA's ASCII
// file of the same kind give the same names, so either can be compared with the other.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace mcdyna::io {

struct HistoryTable {
  std::string source;                        ///< file name for messages
  std::string format;                        ///< csv, glstat, rcforc, nodout, …
  std::vector<std::string> names;            ///< column names
  std::vector<std::vector<double>> columns;  ///< columns[k][row]; NaN where an entity is absent

  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  /// Index of the column called `name`, or -1.
  int find(const std::string& name) const;
};

/// Unreadable history: the message names file:line:column and echoes the line.
class HistoryReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads a history file; the format is recognised from its content.
HistoryTable read_history(const std::filesystem::path& path);
/// Same from text in memory (`source` names it in messages).
HistoryTable read_history_text(const std::string& text, const std::string& source);

namespace detail {

/// Collects values row by row into named columns (new columns are NaN-padded backwards).
class WideTableBuilder {
 public:
  /// Starts a row at `time` (and sets the "time" column), or continues the last one when it has
  /// the same time (files listing several entities per time).
  void row_at(double time);
  /// Starts a new row unconditionally (plain CSV).
  void new_row();
  void set(const std::string& name, double value);
  /// Registers a column (NaN-padded to the rows so far) and returns its index for set_at().
  std::size_t add_column(const std::string& name);
  /// Sets the current row's value of a column from add_column() (a row must be started).
  void set_at(std::size_t column, double value);
  HistoryTable finish(const std::string& source, const std::string& format);

 private:
  std::size_t column(const std::string& name);
  std::vector<std::string> names_;
  std::unordered_map<std::string, std::size_t> index_;  ///< name -> position in names_
  std::vector<std::vector<double>> columns_;
  std::size_t rows_ = 0;
  double last_time_ = 0.0;
  bool have_time_ = false;
};

/// `file:line:col: error: message` with the line echoed below it and a caret.
std::string located_message(const std::string& source, std::size_t line_number,
                            const std::string& line, std::size_t column, const std::string& what);

/// The ASCII readers (history_table_ascii.cpp); lines are the file's lines.
HistoryTable read_lsdyna_ascii(const std::string& format, const std::vector<std::string>& lines,
                               const std::string& source);
/// The ASCII format a text is in ("" when it is none of them).
std::string detect_lsdyna_ascii(const std::vector<std::string>& lines);

}  // namespace detail

}  // namespace mcdyna::io
