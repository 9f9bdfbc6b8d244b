#include "scene/expression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace mrsph {

namespace {

class Parser {
 public:
  Parser(const std::string& text, const ParameterTable& parameters) : s_(text), parameters_(parameters) {}

  double parse() {
    const double v = sum();
    skip_space();
    if (pos_ != s_.size()) fail("unexpected '" + std::string(1, s_[pos_]) + "'");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    const std::string shown = s_.size() > 80 ? s_.substr(0, 77) + "..." : s_;
    throw ExpressionError("cannot evaluate \"" + shown + "\": " + what + " at character " + std::to_string(pos_ + 1));
  }
  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == c) { ++pos_; return true; }
    return false;
  }
  double sum() {
    double v = product();
    for (;;) {
      if (accept('+')) v += product();
      else if (accept('-')) v -= product();
      else return v;
    }
  }
  double product() {
    double v = unary();
    for (;;) {
      if (accept('*')) v *= unary();
      else if (accept('/')) v /= unary();
      else return v;
    }
  }
  // Unary minus binds looser than '^', as in mathematics: -2^2 = -4, 2^-1 = 0.5.
  double unary() {
    const DepthGuard guard(*this);
    if (accept('-')) return -unary();
    if (accept('+')) return unary();
    return power();
  }
  // Recursion depth: an expression nested deeper than this is refused, not a stack overflow.
  struct DepthGuard {
    explicit DepthGuard(Parser& p) : parser(p) {
      if (++parser.depth_ > 200) parser.fail("nesting deeper than 200 levels");
    }
    ~DepthGuard() { --parser.depth_; }
    Parser& parser;
  };
  double power() {
    const double base = primary();
    if (accept('^')) return std::pow(base, unary());  // right-associative
    return base;
  }
  double primary() {
    skip_space();
    if (pos_ >= s_.size()) fail("unexpected end");
    if (accept('(')) {
      const double v = sum();
      if (!accept(')')) fail("missing ')'");
      return v;
    }
    const char c = s_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      char* end = nullptr;
      const double v = std::strtod(s_.c_str() + pos_, &end);
      if (end == s_.c_str() + pos_) fail("bad number");
      pos_ = static_cast<std::size_t>(end - s_.c_str());
      return v;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = pos_;
      while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) ++pos_;
      const std::string name = s_.substr(start, pos_ - start);
      if (accept('(')) return call(name);
      if (name == "pi") return 3.14159265358979323846;
      const auto it = parameters_.find(name);
      if (it == parameters_.end()) {
        pos_ = start;
        fail("unknown parameter '" + name + "'");
      }
      return it->second;
    }
    fail("unexpected '" + std::string(1, c) + "'");
  }
  double call(const std::string& name) {
    std::vector<double> args{sum()};
    while (accept(',')) args.push_back(sum());
    if (!accept(')')) fail("missing ')' after arguments of " + name);
    auto need = [&](std::size_t n) {
      if (args.size() != n) fail(name + " takes " + std::to_string(n) + " argument(s)");
    };
    if (name == "sqrt") { need(1); return std::sqrt(args[0]); }
    if (name == "sin") { need(1); return std::sin(args[0]); }
    if (name == "cos") { need(1); return std::cos(args[0]); }
    if (name == "exp") { need(1); return std::exp(args[0]); }
    if (name == "log") { need(1); return std::log(args[0]); }
    if (name == "abs") { need(1); return std::abs(args[0]); }
    if (name == "min") { need(2); return std::min(args[0], args[1]); }
    if (name == "max") { need(2); return std::max(args[0], args[1]); }
    fail("unknown function '" + name + "'");
  }

  const std::string& s_;
  const ParameterTable& parameters_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

double evaluate_expression(const std::string& text, const ParameterTable& parameters) {
  return Parser(text, parameters).parse();
}

}  // namespace mrsph
