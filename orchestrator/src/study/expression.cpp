// SPDX-License-Identifier: GPL-3.0-or-later
// Recursive-descent evaluation of study expressions (study/expression.h).
//
//   expr    := term (('+' | '-') term)*
//   term    := unary (('*' | '/') unary)*
//   unary   := ('+' | '-') unary | power
//   power   := primary ('^' unary)?
//   primary := number | name | name '(' expr (',' expr)* ')' | '(' expr ')'
#include "study/expression.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <vector>

namespace gridfree {
namespace {

struct FunctionArity {
  const char* name;
  std::size_t min_args, max_args;
};

constexpr FunctionArity kExpressionFunctions[] = {
    {"sqrt", 1, 1}, {"pow", 2, 2},  {"min", 2, 64},  {"max", 2, 64}, {"floor", 1, 1},
    {"ceil", 1, 1}, {"round", 1, 1}, {"log", 1, 1}, {"exp", 1, 1},
};

const FunctionArity* find_function(const std::string& name) {
  for (const auto& f : kExpressionFunctions)
    if (name == f.name) return &f;
  return nullptr;
}

double apply_function(const std::string& name, const std::vector<double>& a) {
  if (name == "sqrt") return std::sqrt(a[0]);
  if (name == "pow") return std::pow(a[0], a[1]);
  if (name == "floor") return std::floor(a[0]);
  if (name == "ceil") return std::ceil(a[0]);
  if (name == "round") return std::round(a[0]);
  if (name == "log") return std::log(a[0]);
  if (name == "exp") return std::exp(a[0]);
  double r = a[0];
  for (double x : a) r = name == "min" ? std::min(r, x) : std::max(r, x);
  return r;
}

class ExpressionParser {
 public:
  ExpressionParser(std::string_view text, const std::map<std::string, double>* variables)
      : text_(text), variables_(variables) {}

  double parse_all() {
    const double v = expr();
    skip_space();
    if (pos_ < text_.size()) fail("an operator (+ - * / ^) or the end");
    return v;
  }

  std::set<std::string> names() const { return names_; }

 private:
  [[noreturn]] void fail(const std::string& expected, std::size_t at = std::string::npos) const {
    if (at == std::string::npos) at = pos_;
    const std::string found = at < text_.size() ? "'" + std::string(1, text_[at]) + "'" : "the end";
    fail_with("expected " + expected + ", found " + found, at);
  }

  [[noreturn]] void fail_with(const std::string& what, std::size_t at) const {
    throw ExpressionError("expression '" + std::string(text_) + "': at position " + std::to_string(at + 1) + ": " + what,
                          at + 1);
  }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  bool accept(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  double expr() {
    double v = term();
    for (;;) {
      if (accept('+')) v += term();
      else if (accept('-')) v -= term();
      else return v;
    }
  }

  double term() {
    double v = unary();
    for (;;) {
      if (accept('*')) v *= unary();
      else if (accept('/')) v /= unary();
      else return v;
    }
  }

  double unary() {
    if (accept('-')) return -unary();
    if (accept('+')) return unary();
    return power();
  }

  double power() {
    const double base = primary();
    if (accept('^')) return std::pow(base, unary());
    return base;
  }

  double number() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.'))
      ++pos_;
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      std::size_t p = pos_ + 1;
      if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
      if (p < text_.size() && std::isdigit(static_cast<unsigned char>(text_[p]))) {
        pos_ = p;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      }
    }
    double v = 0;
    const auto [end, ec] = std::from_chars(text_.data() + start, text_.data() + pos_, v);
    if (ec != std::errc() || end != text_.data() + pos_) fail("a number", start);
    return v;
  }

  double primary() {
    skip_space();
    if (pos_ >= text_.size()) fail("a number, a name or '('");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      const double v = expr();
      if (!accept(')')) fail("')'");
      return v;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = pos_;
      while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
        ++pos_;
      const std::string name(text_.substr(start, pos_ - start));
      if (accept('(')) return call(name, start);
      return variable(name, start);
    }
    fail("a number, a name or '('");
  }

  double call(const std::string& name, std::size_t start) {
    const FunctionArity* f = find_function(name);
    if (f == nullptr)
      fail_with("unknown function '" + name + "' (known: sqrt, pow, min, max, floor, ceil, round, log, exp)", start);
    std::vector<double> args{expr()};
    while (accept(',')) args.push_back(expr());
    if (!accept(')')) fail("',' or ')'");
    if (args.size() < f->min_args || args.size() > f->max_args)
      fail_with(name + " takes " +
                    (f->min_args == f->max_args ? std::to_string(f->min_args)
                                                : "at least " + std::to_string(f->min_args)) +
                    " argument(s), not " + std::to_string(args.size()),
                start);
    return apply_function(name, args);
  }

  double variable(const std::string& name, std::size_t start) {
    names_.insert(name);
    if (variables_ == nullptr) return 1;  // names only
    const auto it = variables_->find(name);
    if (it != variables_->end()) return it->second;
    std::string known;
    for (const auto& [n, v] : *variables_) known += (known.empty() ? "" : ", ") + n;
    fail_with("unknown name '" + name + "' (defined: " + (known.empty() ? std::string("none") : known) + ")", start);
  }

  std::string_view text_;
  const std::map<std::string, double>* variables_;
  std::size_t pos_ = 0;
  std::set<std::string> names_;
};

}  // namespace

double evaluate_expression(std::string_view text, const std::map<std::string, double>& variables) {
  ExpressionParser p(text, &variables);
  return p.parse_all();
}

std::set<std::string> expression_names(std::string_view text) {
  ExpressionParser p(text, nullptr);
  p.parse_all();
  return p.names();
}

}  // namespace gridfree
