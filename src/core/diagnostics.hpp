#pragma once
/// Collected deck problems. Readers and checks report here and carry on; nothing aborts.
#include <fmt/format.h>

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "core/source.hpp"

namespace mcdyna::core {

enum class Severity { note, warning, error };

struct Diagnostic {
  Severity severity = Severity::error;
  SourceLoc loc;
  std::string message;
};

/// Error sink. Keeps every diagnostic in report order with exact counts; limiting how many are
/// printed is the printer's job.
class Diagnostics {
 public:
  void report(Severity severity, SourceLoc loc, std::string message);

  template <typename... Args>
  void error(SourceLoc loc, fmt::format_string<Args...> f, Args&&... args) {
    report(Severity::error, loc, fmt::format(f, std::forward<Args>(args)...));
  }
  template <typename... Args>
  void warning(SourceLoc loc, fmt::format_string<Args...> f, Args&&... args) {
    report(Severity::warning, loc, fmt::format(f, std::forward<Args>(args)...));
  }
  template <typename... Args>
  void note(SourceLoc loc, fmt::format_string<Args...> f, Args&&... args) {
    report(Severity::note, loc, fmt::format(f, std::forward<Args>(args)...));
  }

  [[nodiscard]] std::size_t error_count() const { return errors_; }
  [[nodiscard]] std::size_t warning_count() const { return warnings_; }
  [[nodiscard]] bool has_errors() const { return errors_ > 0; }
  [[nodiscard]] const std::vector<Diagnostic>& all() const { return items_; }

 private:
  std::vector<Diagnostic> items_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
};

/// `text` for quoting in a message: as it is up to `max` characters, else its head and the count
/// ("1**1**1** ... (900000 characters)"), so a 70 kB field does not become a 70 kB message.
std::string excerpt(std::string_view text, std::size_t max = 60);

/// "file:line:cols: severity: message" followed by the echoed line and a caret marker.
std::string format_diagnostic(const Diagnostic& d, const SourceFiles& files);

/// Prints diagnostics in report order; at most `limit` (0 = all), then a count of the rest.
void print_diagnostics(std::ostream& out, const Diagnostics& diags, const SourceFiles& files,
                       std::size_t limit = 0);

}  // namespace mcdyna::core
