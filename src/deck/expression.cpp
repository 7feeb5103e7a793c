// Recursive-descent evaluator for *PARAMETER_EXPRESSION (keywords.md §1.10): operators
// + - * / ** and parentheses, the Fortran-style intrinsic functions, constant pi, and parameter
// names written bare or with '&'.
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>

#include "deck/numbers.hpp"
#include "deck/parameters.hpp"
#include "deck/text_util.hpp"

namespace mcdyna::deck {

namespace {

class ExpressionParser {
 public:
  ExpressionParser(std::string_view text,
                   const std::function<std::optional<double>(const std::string&)>& resolve)
      : text_(text), resolve_(resolve) {}

  std::optional<double> run(std::string& error) {
    const double v = sum();
    skip_blanks();
    if (error_.empty() && pos_ != text_.size()) {
      fail("unexpected '" + std::string(text_.substr(pos_, 1)) + "'");
    }
    if (!error_.empty()) {
      error = error_;
      return std::nullopt;
    }
    if (!std::isfinite(v)) {
      error = "result is not a finite number";
      return std::nullopt;
    }
    return v;
  }

 private:
  void fail(std::string what) {
    if (error_.empty()) error_ = what + " at position " + std::to_string(pos_ + 1);
  }
  void skip_blanks() {
    while (pos_ < text_.size() && is_blank_char(text_[pos_]))
      ++pos_;
  }
  bool accept(std::string_view token) {
    skip_blanks();
    if (text_.substr(pos_, token.size()) == token) {
      pos_ += token.size();
      return true;
    }
    return false;
  }

  double sum() {
    double v = product();
    for (;;) {
      if (accept("+")) {
        v += product();
      } else if (accept("-")) {
        v -= product();
      } else {
        return v;
      }
    }
  }

  double product() {
    double v = unary();
    for (;;) {
      skip_blanks();
      if (text_.substr(pos_, 2) == "**") return v;  // handled in power()
      if (accept("*")) {
        v *= unary();
      } else if (accept("/")) {
        const double d = unary();
        if (d == 0.0) fail("division by zero");
        v = d == 0.0 ? 0.0 : v / d;
      } else {
        return v;
      }
    }
  }

  // Every recursion of the grammar (unary signs, right-associative powers, parentheses, function
  // arguments) passes through here, so one depth guard bounds the stack for any input.
  double unary() {
    if (++depth_ > kMaxDepth) {
      fail("expression nested too deeply (more than " + std::to_string(kMaxDepth) +
           " signs, powers or parentheses inside each other)");
      pos_ = text_.size();  // stop reading: the rest cannot be evaluated either
      --depth_;
      return 0.0;
    }
    struct DepthGuard {
      int& d;
      ~DepthGuard() { --d; }
    } guard{depth_};
    if (accept("-")) return -unary();
    if (accept("+")) return unary();
    return power();
  }

  double power() {
    const double base = primary();
    if (accept("**") || accept("^")) return std::pow(base, unary());  // right-associative
    return base;
  }

  double primary() {
    skip_blanks();
    if (pos_ >= text_.size()) {
      fail("expression ends early");
      return 0.0;
    }
    if (accept("(")) {
      const double v = sum();
      if (!accept(")")) fail("missing ')'");
      return v;
    }
    const char c = text_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (c == '&' || std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name_or_call();
    fail("unexpected '" + std::string(1, c) + "'");
    return 0.0;
  }

  double number() {
    std::size_t end = pos_;
    auto digit = [&](std::size_t i) {
      return i < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i]));
    };
    while (digit(end) || (end < text_.size() && text_[end] == '.'))
      ++end;
    if (end < text_.size() &&
        (text_[end] == 'e' || text_[end] == 'E' || text_[end] == 'd' || text_[end] == 'D')) {
      std::size_t e = end + 1;
      if (e < text_.size() && (text_[e] == '+' || text_[e] == '-')) ++e;
      if (digit(e)) {
        end = e;
        while (digit(end))
          ++end;
      }
    }
    const auto v = parse_real(text_.substr(pos_, end - pos_));
    if (!v) fail("malformed number");
    pos_ = end;
    return v.value_or(0.0);
  }

  double name_or_call() {
    const bool ampersand = accept("&");
    std::size_t end = pos_;
    while (end < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '_')) {
      ++end;
    }
    const std::string name = upper(text_.substr(pos_, end - pos_));
    pos_ = end;
    if (name.empty()) {
      fail("expected a name after '&'");
      return 0.0;
    }
    if (!ampersand && accept("(")) return call(name);
    if (!ampersand && name == "PI") return std::numbers::pi;
    const auto v = resolve_(name);
    if (!v) {
      fail("unknown parameter '" + name + "'");
      return 0.0;
    }
    return *v;
  }

  double call(const std::string& fn) {
    std::vector<double> args;
    if (!accept(")")) {
      do {
        args.push_back(sum());
      } while (accept(","));
      if (!accept(")")) fail("missing ')' after arguments of " + fn);
    }
    return apply(fn, args);
  }

  double apply(const std::string& fn, const std::vector<double>& a) {
    using F1 = double (*)(double);
    static const std::map<std::string, F1> one{
        {"SIN", [](double x) { return std::sin(x); }},
        {"COS", [](double x) { return std::cos(x); }},
        {"TAN", [](double x) { return std::tan(x); }},
        {"CSC", [](double x) { return 1.0 / std::sin(x); }},
        {"SEC", [](double x) { return 1.0 / std::cos(x); }},
        {"CTN", [](double x) { return 1.0 / std::tan(x); }},
        {"ASIN", [](double x) { return std::asin(x); }},
        {"ACOS", [](double x) { return std::acos(x); }},
        {"ATAN", [](double x) { return std::atan(x); }},
        {"SINH", [](double x) { return std::sinh(x); }},
        {"COSH", [](double x) { return std::cosh(x); }},
        {"TANH", [](double x) { return std::tanh(x); }},
        {"ASINH", [](double x) { return std::asinh(x); }},
        {"ACOSH", [](double x) { return std::acosh(x); }},
        {"ATANH", [](double x) { return std::atanh(x); }},
        {"SQRT", [](double x) { return std::sqrt(x); }},
        {"ABS", [](double x) { return std::fabs(x); }},
        {"EXP", [](double x) { return std::exp(x); }},
        {"LOG", [](double x) { return std::log(x); }},
        {"LOG10", [](double x) { return std::log10(x); }},
        {"INT", [](double x) { return std::trunc(x); }},
        {"AINT", [](double x) { return std::trunc(x); }},
        {"FLOAT", [](double x) { return x; }},
        {"NINT", [](double x) { return std::round(x); }},
        {"ANINT", [](double x) { return std::round(x); }},
    };
    if (auto it = one.find(fn); it != one.end()) {
      if (a.size() != 1) {
        fail(fn + " takes one argument");
        return 0.0;
      }
      return it->second(a[0]);
    }
    if (fn == "ATAN2" || fn == "SIGN" || fn == "MOD") {
      if (a.size() != 2) {
        fail(fn + " takes two arguments");
        return 0.0;
      }
      if (fn == "ATAN2") return std::atan2(a[0], a[1]);
      if (fn == "SIGN") return std::copysign(std::fabs(a[0]), a[1]);
      if (a[1] == 0.0) fail("MOD by zero");
      return a[1] == 0.0 ? 0.0 : std::fmod(a[0], a[1]);
    }
    if (fn == "MIN" || fn == "MAX") {
      if (a.empty()) {
        fail(fn + " needs arguments");
        return 0.0;
      }
      double v = a[0];
      for (double x : a)
        v = fn == "MIN" ? std::min(v, x) : std::max(v, x);
      return v;
    }
    fail("unknown function '" + fn + "'");
    return 0.0;
  }

  static constexpr int kMaxDepth = 256;
  std::string_view text_;
  const std::function<std::optional<double>(const std::string&)>& resolve_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  std::string error_;
};

}  // namespace

std::optional<double> evaluate_expression(
    std::string_view text, const std::function<std::optional<double>(const std::string&)>& resolve,
    std::string& error) {
  return ExpressionParser(text, resolve).run(error);
}

}  // namespace mcdyna::deck
