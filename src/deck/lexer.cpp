// Splits deck files into keyword blocks (keywords.md §1): comments, keyword lines with their
// format flags, *INCLUDE and its search paths, *PARAMETER definitions, *COMMENT and *END.
#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

#include "deck/deck.hpp"
#include "deck/numbers.hpp"
#include "deck/text_util.hpp"

namespace mcdyna::deck {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxFileBytes = 4'000'000'000ULL;  // line offsets are 32-bit

struct KeywordLine {
  std::string name;
  char format_suffix = 0;  // '+', '-', '%' or 0
  std::string_view arguments;
};

KeywordLine parse_keyword_line(std::string_view text) {
  KeywordLine k;
  std::string_view rest = text.substr(1);
  std::size_t end = 0;
  while (end < rest.size() && !is_blank_char(rest[end]))
    ++end;
  std::string_view name = rest.substr(0, end);
  k.arguments = trim(rest.substr(end));
  if (!name.empty() && (name.back() == '+' || name.back() == '-' || name.back() == '%')) {
    k.format_suffix = name.back();
    name.remove_suffix(1);
  } else if (k.arguments.size() == 1 &&
             (k.arguments[0] == '+' || k.arguments[0] == '-' || k.arguments[0] == '%')) {
    k.format_suffix = k.arguments[0];
  }
  k.name = upper(name);
  return k;
}

std::optional<std::string> read_file(const fs::path& path, std::string& error) {
  error = file_problem(path);
  if (!error.empty()) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot open";
    return std::nullopt;
  }
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::size_t>(in.tellg());
  if (size > kMaxFileBytes) {
    error = "file larger than 4 GB";
    return std::nullopt;
  }
  in.seekg(0, std::ios::beg);
  std::string text(size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (!in) {
    error = "read failed";
    return std::nullopt;
  }
  return text;
}

class Lexer {
 public:
  Lexer(Deck& deck, core::Diagnostics& diags, const ReadOptions& options, fs::path main_dir)
      : deck_(deck), diags_(diags), options_(options), main_dir_(std::move(main_dir)) {}

  void lex(const fs::path& path, std::string text, std::optional<std::uint32_t> parent_scope,
           int depth, CardFormat inherited_format);

  std::optional<fs::path> resolve_include(std::string_view name, const fs::path& including_dir,
                                          std::string& searched) const;

  /// At the end of the deck: a *CASE_BEGIN_n left open is an error.
  void finish();

 private:
  struct FileState {
    std::uint32_t file = 0;
    std::uint32_t scope = 0;
    int depth = 0;
    CardFormat format = CardFormat::standard;
    fs::path dir;
  };

  void finish_block(FileState& st);
  void handle_keyword_arguments(FileState& st, const KeywordBlock& b, std::string_view args);
  void handle_include(FileState& st, const KeywordBlock& b);
  /// *INCLUDE_PATH and *INCLUDE_PATH_RELATIVE: relative names are taken from the main deck's dir.
  void handle_include_path(const KeywordBlock& b);
  void handle_parameter(const KeywordBlock& b, bool expression, bool local);
  void handle_duplication(const KeywordBlock& b);
  std::vector<long> subcases_of(const KeywordLine& k, const core::SourceLoc& loc);

  struct OpenCase {
    long id = 0;
    core::SourceLoc loc;
  };
  std::vector<OpenCase> open_cases_;  ///< *CASE_BEGIN_n not yet closed, innermost last

  Deck& deck_;
  core::Diagnostics& diags_;
  const ReadOptions& options_;
  fs::path main_dir_;
  std::vector<fs::path> include_paths_;
  std::vector<fs::path> open_files_;
  std::optional<KeywordBlock> current_;
  std::string current_args_;
  int duplication_flag_ = 1;
};

void Lexer::lex(const fs::path& path, std::string text, std::optional<std::uint32_t> parent_scope,
                int depth, CardFormat inherited_format) {
  deck_.bytes_read += text.size();
  std::error_code ec;
  open_files_.push_back(fs::weakly_canonical(path, ec));
  FileState st;
  st.file = deck_.files.add(path, std::move(text));
  st.scope = deck_.parameters.new_scope(parent_scope);
  st.depth = depth;
  st.format = inherited_format;
  st.dir = path.parent_path();
  const core::SourceFile& file = deck_.files.file(st.file);
  const std::string_view all = file.text;
  bool in_comment = false;
  bool warned_stray = false;
  const auto n = static_cast<std::uint32_t>(file.line_starts.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::size_t begin = file.line_starts[i];
    std::size_t end = i + 1 < n ? file.line_starts[i + 1] - 1 : all.size();
    if (i + 1 == n && end > begin && all[end - 1] == '\n') --end;
    if (end > begin && all[end - 1] == '\r') --end;
    const std::string_view line = all.substr(begin, end - begin);
    const std::uint32_t line_no = i + 1;
    if (!line.empty() && line[0] == '$') continue;
    if (!line.empty() && line[0] == '*') {
      finish_block(st);
      KeywordLine k = parse_keyword_line(line);
      in_comment = k.name == "COMMENT";
      KeywordBlock b;
      b.name = k.name;
      b.loc =
          core::SourceLoc{st.file, line_no, 1,
                          static_cast<std::uint16_t>(std::min<std::size_t>(line.size(), 65535))};
      b.format = k.format_suffix == '+'   ? CardFormat::long_format
                 : k.format_suffix == '-' ? CardFormat::standard
                 : k.format_suffix == '%' ? CardFormat::i10
                                          : st.format;
      b.scope = st.scope;
      b.subcases = subcases_of(k, b.loc);
      b.first_line = b.end_line = static_cast<std::uint32_t>(deck_.lines.size());
      if (b.name.empty()) diags_.error(b.loc, "keyword line without a keyword name");
      current_ = std::move(b);
      current_args_ = std::string(k.arguments);
      if (current_->name == "KEYWORD") handle_keyword_arguments(st, *current_, k.arguments);
      if (current_->name == "END") {
        finish_block(st);
        open_files_.pop_back();
        return;  // *END ends this file; the including file continues
      }
      continue;
    }
    if (in_comment) continue;
    if (!current_) {
      if (!trim(line).empty() && !warned_stray) {
        diags_.warning(core::SourceLoc{st.file, line_no, 0, 0},
                       "data line before the first keyword is ignored");
        warned_stray = true;
      }
      continue;
    }
    deck_.lines.push_back(DataLine{line, st.file, line_no});
  }
  finish_block(st);
  open_files_.pop_back();
}

// *CASE_BEGIN_n opens subcase n and *CASE_END_n closes it (they nest, across *INCLUDE files);
// a keyword line's "CID=n" puts that one keyword in subcase n.
std::vector<long> Lexer::subcases_of(const KeywordLine& k, const core::SourceLoc& loc) {
  auto number = [&](std::string_view text, std::string_view what) -> std::optional<long> {
    const std::optional<std::int64_t> n = parse_integer(text);
    if (!n || *n <= 0) {
      diags_.error(loc, "{}: \"{}\" is not a subcase number (a positive integer)", what, text);
      return std::nullopt;
    }
    return static_cast<long>(*n);
  };
  constexpr std::string_view kBegin = "CASE_BEGIN_", kEnd = "CASE_END_";
  std::string_view name = k.name;
  if (name.substr(0, kBegin.size()) == kBegin) {
    if (const auto n = number(name.substr(kBegin.size()), "*CASE_BEGIN_n"))
      open_cases_.push_back({*n, loc});
    return {};
  }
  if (name.substr(0, kEnd.size()) == kEnd) {
    const auto n = number(name.substr(kEnd.size()), "*CASE_END_n");
    if (!n) return {};
    if (open_cases_.empty() || open_cases_.back().id != *n) {
      diags_.error(loc, "*CASE_END_{} without a matching *CASE_BEGIN_{}{}", *n, *n,
                   open_cases_.empty()
                       ? std::string()
                       : fmt::format(" (the open one is *CASE_BEGIN_{})", open_cases_.back().id));
      return {};
    }
    open_cases_.pop_back();
    return {};
  }
  std::vector<long> tags;
  for (const OpenCase& c : open_cases_)
    tags.push_back(c.id);
  for (const std::string_view arg : split_whitespace(k.arguments)) {
    if (upper(arg.substr(0, 4)) != "CID=") continue;
    if (const auto n = number(arg.substr(4), "keyword option CID=n")) tags.push_back(*n);
  }
  return tags;
}

void Lexer::finish() {
  for (const OpenCase& c : open_cases_)
    diags_.error(c.loc, "*CASE_BEGIN_{} is not closed by a *CASE_END_{}", c.id, c.id);
}

void Lexer::finish_block(FileState& st) {
  if (!current_) return;
  KeywordBlock b = std::move(*current_);
  current_.reset();
  b.end_line = static_cast<std::uint32_t>(deck_.lines.size());
  deck_.blocks.push_back(b);
  const std::string& name = b.name;
  if (name == "INCLUDE") {
    handle_include(st, b);
  } else if (name == "INCLUDE_PATH") {
    handle_include_path(b);
  } else if (name == "INCLUDE_PATH_RELATIVE") {
    handle_include_path(b);
  } else if (name == "PARAMETER" || name == "PARAMETER_NOECHO") {
    handle_parameter(b, false, false);
  } else if (name == "PARAMETER_LOCAL" || name == "PARAMETER_LOCAL_NOECHO") {
    handle_parameter(b, false, true);
  } else if (name == "PARAMETER_EXPRESSION" || name == "PARAMETER_EXPRESSION_NOECHO") {
    handle_parameter(b, true, false);
  } else if (name == "PARAMETER_EXPRESSION_LOCAL" || name == "PARAMETER_EXPRESSION_LOCAL_NOECHO") {
    handle_parameter(b, true, true);
  } else if (name == "PARAMETER_DUPLICATION") {
    handle_duplication(b);
  }
}

void Lexer::handle_keyword_arguments(FileState& st, const KeywordBlock& b, std::string_view args) {
  for (std::string_view arg : split_whitespace(args)) {
    const std::string a = upper(arg);
    const auto eq = a.find('=');
    const std::string key = a.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : a.substr(eq + 1);
    const int col = static_cast<int>(arg.data() - deck_.files.file(b.loc.file).text.data() -
                                     deck_.files.file(b.loc.file).line_starts[b.loc.line - 1]) +
                    1;
    const core::SourceLoc at = b.loc.with_columns(col, col + static_cast<int>(arg.size()) - 1);
    if (key == "LONG") {
      if (value == "Y") {
        st.format = CardFormat::long_format;
      } else if (value == "S" || value == "K" || value == "N") {
        st.format = CardFormat::standard;
      } else {
        diags_.error(at, "*KEYWORD LONG= expects Y or S, got \"{}\"", value);
      }
    } else if (key == "I10") {
      if (value == "Y") {
        st.format = CardFormat::i10;
      } else if (value != "N") {
        diags_.error(at, "*KEYWORD I10= expects Y or N, got \"{}\"", value);
      }
    } else if (key == "NCPU" || key == "MEMORY" || key == "MEMORY2" ||
               (eq == std::string::npos &&
                a.find_first_not_of("0123456789MGKBW") == std::string::npos)) {
      // Memory size and CPU count: mcdyna sizes its memory itself; --threads sets threads.
    } else {
      diags_.warning(at, "*KEYWORD argument \"{}\" is not known and is ignored", std::string(arg));
    }
  }
}

void Lexer::handle_include(FileState& st, const KeywordBlock& b) {
  // A name may continue on the next line when a line ends in " +" (keywords.md §1.9).
  std::string name;
  core::SourceLoc name_loc;
  for (std::uint32_t i = b.first_line; i < b.end_line; ++i) {
    const DataLine& dl = deck_.lines[i];
    std::string_view piece = trim(dl.text);
    if (name.empty()) name_loc = dl.loc();
    if (piece.empty()) continue;
    const bool continues =
        piece.size() >= 2 && piece.back() == '+' && piece[piece.size() - 2] == ' ';
    if (continues) piece = trim(piece.substr(0, piece.size() - 1));
    name += piece;
    if (continues) continue;
    if (st.depth + 1 > options_.max_include_depth) {
      diags_.error(name_loc, "include depth exceeds {} (is there a runaway include chain?)",
                   options_.max_include_depth);
      name.clear();
      continue;
    }
    std::string searched;
    const auto path = resolve_include(name, st.dir, searched);
    if (!path) {
      diags_.error(name_loc, "include file \"{}\" not found (searched: {})", name, searched);
      name.clear();
      continue;
    }
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(*path, ec);
    if (std::find(open_files_.begin(), open_files_.end(), canonical) != open_files_.end()) {
      std::string chain;
      for (const auto& f : open_files_)
        chain += f.filename().string() + " -> ";
      diags_.error(name_loc, "include cycle: {}{}", chain, canonical.filename().string());
      name.clear();
      continue;
    }
    std::string error;
    auto text = read_file(*path, error);
    if (!text) {
      diags_.error(name_loc, "include file \"{}\": {}", path->string(), error);
      name.clear();
      continue;
    }
    lex(*path, std::move(*text), st.scope, st.depth + 1, st.format);
    name.clear();
  }
  if (!name.empty())
    diags_.error(name_loc, "include file name continues with ' +' but no line follows");
}

std::optional<fs::path> Lexer::resolve_include(std::string_view raw, const fs::path& including_dir,
                                               std::string& searched) const {
  std::string name(trim(raw));
  std::replace(name.begin(), name.end(), '\\', '/');
  const fs::path p(name);
  std::error_code ec;
  auto ok = [&](const fs::path& c) { return fs::is_regular_file(c, ec); };
  if (p.is_absolute()) {
    searched = "absolute path";
    return ok(p) ? std::optional<fs::path>(p) : std::nullopt;
  }
  std::vector<fs::path> dirs;
  auto add = [&](const fs::path& d) {
    if (std::find(dirs.begin(), dirs.end(), d) == dirs.end()) dirs.push_back(d);
  };
  add(including_dir);
  add(main_dir_);
  for (const auto& d : include_paths_)
    add(d);
  add(fs::current_path(ec));
  for (const auto& d : dirs) {
    if (!searched.empty()) searched += ", ";
    searched += d.empty() ? "." : d.string();
    const fs::path c = d / p;
    if (ok(c)) return c.lexically_normal();
  }
  return std::nullopt;
}

void Lexer::handle_include_path(const KeywordBlock& b) {
  for (std::uint32_t i = b.first_line; i < b.end_line; ++i) {
    std::string dir(trim(deck_.lines[i].text));
    if (dir.empty()) continue;
    std::replace(dir.begin(), dir.end(), '\\', '/');
    const fs::path p(dir);
    include_paths_.push_back(p.is_absolute() ? p : main_dir_ / p);
  }
}

void Lexer::handle_parameter(const KeywordBlock& b, bool expression, bool local) {
  const int w = field_width(b.format, 10);
  const std::string_view kind = expression ? "*PARAMETER_EXPRESSION" : "*PARAMETER";
  for (std::uint32_t i = b.first_line; i < b.end_line; ++i) {
    const DataLine& dl = deck_.lines[i];
    // (name field, value field, first column of name) pairs on this line.
    struct Pair {
      std::string_view name, value;
      int col;
    };
    std::vector<Pair> pairs;
    const bool free_format = dl.text.find(',') != std::string_view::npos && !expression;
    if (expression) {
      const std::size_t comma = dl.text.find(',');
      if (comma != std::string_view::npos && comma < static_cast<std::size_t>(w)) {
        pairs.push_back({dl.text.substr(0, comma), dl.text.substr(comma + 1), 1});
      } else {
        pairs.push_back({dl.text.substr(0, std::min<std::size_t>(w, dl.text.size())),
                         dl.text.size() > static_cast<std::size_t>(w) ? dl.text.substr(w) : "", 1});
      }
    } else if (free_format) {
      const auto items = split(dl.text, ',');
      for (std::size_t k = 0; k + 1 < items.size(); k += 2) {
        pairs.push_back(
            {items[k], items[k + 1], static_cast<int>(items[k].data() - dl.text.data()) + 1});
      }
    } else {
      for (int k = 0; k < 4; ++k) {
        const std::size_t at = static_cast<std::size_t>(2 * k * w);
        if (at >= dl.text.size()) break;
        pairs.push_back({dl.text.substr(at, w),
                         at + w < dl.text.size() ? dl.text.substr(at + w, w) : std::string_view{},
                         static_cast<int>(at) + 1});
      }
    }
    for (const Pair& pr : pairs) {
      const std::string_view prmr = trim(pr.name);
      if (prmr.empty()) continue;
      const core::SourceLoc at = dl.loc().with_columns(pr.col, pr.col + w - 1);
      const char type = static_cast<char>(std::toupper(static_cast<unsigned char>(prmr[0])));
      const std::string name = upper(trim(prmr.substr(1)));
      if (type != 'R' && type != 'I' && type != 'C') {
        diags_.error(at, "{} name \"{}\" must start with its type R, I or C", kind, prmr);
        continue;
      }
      if (name.empty() || name.find_first_of(" \t&") != std::string::npos) {
        diags_.error(at, "{} name \"{}\" is not a valid parameter name", kind, prmr);
        continue;
      }
      if (expression && type == 'C') {
        diags_.error(at, "*PARAMETER_EXPRESSION defines R or I parameters, not C");
        continue;
      }
      if (trim(pr.value).empty() && type != 'C') {
        diags_.error(at, "{} {} has no value", kind, name);
        continue;
      }
      deck_.parameters.define(Parameters::Definition{name, type, std::string(trim(pr.value)),
                                                     expression, local, b.scope, at},
                              duplication_flag_, diags_);
    }
  }
}

void Lexer::handle_duplication(const KeywordBlock& b) {
  if (b.line_count() == 0) return;
  const DataLine& dl = deck_.lines[b.first_line];
  const std::string_view f = trim(dl.text.substr(0, std::min<std::size_t>(10, dl.text.size())));
  if (f.empty()) return;
  if (f.size() == 1 && f[0] >= '1' && f[0] <= '5') {
    duplication_flag_ = f[0] - '0';
  } else {
    diags_.error(dl.loc().with_columns(1, 10),
                 "*PARAMETER_DUPLICATION DFLAG must be 1..5, got \"{}\"", f);
  }
}

}  // namespace

std::string file_problem(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) return "no such file";
  if (fs::is_directory(status)) return "is a directory";
  if (!fs::is_regular_file(status)) return "is not a regular file";  // a FIFO would block
  return {};
}

Deck read_deck_text(std::string text, const fs::path& virtual_path, core::Diagnostics& diags,
                    const ReadOptions& options) {
  Deck deck;
  Lexer lexer(deck, diags, options, virtual_path.parent_path());
  lexer.lex(virtual_path, std::move(text), std::nullopt, 0, CardFormat::standard);
  lexer.finish();
  deck.parameters.evaluate_all(diags);
  return deck;
}

Deck read_deck(const fs::path& path, core::Diagnostics& diags, const ReadOptions& options) {
  std::string error;
  auto text = read_file(path, error);
  if (!text) {
    diags.error(core::SourceLoc{}, "cannot read deck \"{}\": {}", path.string(), error);
    return Deck{};
  }
  return read_deck_text(std::move(*text), path, diags, options);
}

}  // namespace mcdyna::deck
