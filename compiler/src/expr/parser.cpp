// Recursive-descent parser for scene expressions. Grammar:
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := '-' unary | power
//   power   := atom ('^' unary)?          right-associative; -2^2 = -(2^2)
//   atom    := number | name | name '(' sum (',' sum)* ')' | '(' sum ')'
#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <unordered_map>
#include <algorithm>

#include "functions.hpp"
#include "sdfc/expr/expr.hpp"

namespace sdfc::expr {

namespace {

// Deeper nesting than this is refused rather than risking the stack.
constexpr int kMaxDepth = 100;
// Caps on what one expression may hold, so that every pass over its tree
// (folding, intervals, derivatives, printing, the emitted OpenCL, where
// clang allows 256 nested brackets) recurses at most kMaxHeight deep
// however long the input is: a chain "1+1+1+..." is one level per term.
constexpr int kMaxHeight = 120;
constexpr size_t kMaxLength = 8000;
// Expressions in messages are cut to this many characters.
constexpr size_t kEchoLength = 80;

class Parser {
 public:
  Parser(std::string_view text, const SourceLoc& at, const std::vector<std::string>& vars)
      : s_(text), at_(at), vars_(vars) {}

  ExprPtr parse() {
    if (s_.size() > kMaxLength)
      error(0, fmt::format("the expression is {} characters long; at most {} are allowed", s_.size(), kMaxLength),
            "split it over several shapes or simplify it");
    ExprPtr e = sum();
    skip();
    if (i_ < s_.size()) error(i_, fmt::format("unexpected '{}'", s_[i_]), "expected an operator or the end");
    return e;
  }

 private:
  [[noreturn]] void error(size_t offset, std::string msg, std::string hint = {}) const {
    SourceLoc loc = at_;
    if (loc.line > 0) loc.column += static_cast<int>(offset);
    std::string shown(s_.substr(0, kEchoLength));
    if (s_.size() > kEchoLength) shown += "...";
    fail(loc, "in expression \"" + shown + "\": " + msg, std::move(hint));
  }

  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  ExprPtr node(Op op, size_t at, std::vector<ExprPtr> args = {}, double v = 0, std::string name = {}) {
    auto e = std::make_shared<Expr>();
    e->op = op;
    e->offset = static_cast<int>(at);
    e->args = std::move(args);
    e->value = v;
    e->name = std::move(name);
    int h = 1;
    for (const auto& a : e->args) h = std::max(h, 1 + height_[a.get()]);
    if (h > kMaxHeight)
      error(at, fmt::format("more than {} operations deep (a chain of + or * counts one level per term)", kMaxHeight),
            "use fewer terms, or group them in parentheses such as (a+b)+(c+d)");
    height_[e.get()] = h;
    return e;
  }
  struct Depth {
    Parser& p;
    size_t at;
    Depth(Parser& parser, size_t offset) : p(parser), at(offset) {
      if (++p.depth_ > kMaxDepth) p.error(at, fmt::format("nested deeper than {} levels", kMaxDepth));
    }
    ~Depth() { --p.depth_; }
  };

  ExprPtr sum() {
    Depth guard(*this, i_);
    ExprPtr e = product();
    for (;;) {
      skip();
      size_t at = i_;
      if (eat('+')) e = node(Op::Add, at, {e, product()});
      else if (eat('-')) e = node(Op::Sub, at, {e, product()});
      else return e;
    }
  }
  ExprPtr product() {
    ExprPtr e = unary();
    for (;;) {
      skip();
      size_t at = i_;
      if (eat('*')) e = node(Op::Mul, at, {e, unary()});
      else if (eat('/')) e = node(Op::Div, at, {e, unary()});
      else return e;
    }
  }
  ExprPtr unary() {
    skip();
    size_t at = i_;
    if (eat('-')) {
      Depth guard(*this, at);
      return node(Op::Neg, at, {unary()});
    }
    if (eat('+')) return unary();
    return power();
  }
  ExprPtr power() {
    ExprPtr base = atom();
    skip();
    size_t at = i_;
    if (eat('^')) {
      Depth guard(*this, at);
      return node(Op::Pow, at, {base, unary()});
    }
    return base;
  }
  ExprPtr atom() {
    skip();
    size_t at = i_;
    if (i_ >= s_.size()) error(i_, "unexpected end", "expected a number, a name or '('");
    char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
      std::string name(s_.substr(at, i_ - at));
      if (eat('(')) return call(name, at);
      for (const auto& v : vars_)
        if (v == name) return node(Op::Var, at, {}, 0, name);
      if (find_function(name))
        error(at, fmt::format("'{}' is a function", name), fmt::format("write {}(...)", name));
      std::vector<std::string_view> names(vars_.begin(), vars_.end());
      std::string hint = did_you_mean(name, names);
      if (hint.empty()) {
        std::string all;
        for (const auto& v : vars_) all += (all.empty() ? "" : ", ") + v;
        hint = vars_.empty() ? "no variables are allowed here" : "variables here: " + all;
      }
      error(at, fmt::format("unknown variable '{}'", name), hint);
    }
    if (eat('(')) {
      ExprPtr e = sum();
      if (!eat(')')) error(i_, "missing ')'", fmt::format("the '(' at column {} is not closed", at_.column + int(at)));
      return e;
    }
    error(at, fmt::format("unexpected '{}'", c), "expected a number, a name or '('");
  }
  ExprPtr number() {
    size_t at = i_;
    const char* begin = s_.data() + i_;
    // strtod would read past the view; copy the longest numeric prefix.
    size_t j = i_;
    while (j < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[j])) || s_[j] == '.' || s_[j] == 'e' ||
                             s_[j] == 'E' || ((s_[j] == '-' || s_[j] == '+') && j > i_ && (s_[j - 1] == 'e' || s_[j - 1] == 'E'))))
      ++j;
    std::string digits(begin, j - i_);
    char* end = nullptr;
    double v = std::strtod(digits.c_str(), &end);
    if (end == digits.c_str()) error(at, fmt::format("'{}' is not a number", digits));
    if (!std::isfinite(v) || std::fabs(v) > 1e12) error(at, fmt::format("{} is too large", digits));
    i_ += static_cast<size_t>(end - digits.c_str());
    return node(Op::Number, at, {}, v);
  }
  ExprPtr call(const std::string& name, size_t at) {
    Depth guard(*this, at);
    const Function* f = find_function(name);
    if (f && f->internal) f = nullptr;
    if (!f) {
      std::vector<std::string_view> names;
      for (const auto& fn : functions())
        if (!fn.internal) names.push_back(fn.name);
      std::string hint = did_you_mean(name, names);
      if (hint.empty()) hint = "functions: sin cos tan exp log sqrt abs min max clamp mix smoothstep";
      error(at, fmt::format("unknown function '{}'", name), hint);
    }
    std::vector<ExprPtr> args;
    if (!eat(')')) {
      do args.push_back(sum());
      while (eat(','));
      if (!eat(')')) error(i_, fmt::format("missing ')' after the arguments of {}", name));
    }
    if (static_cast<int>(args.size()) != f->arity)
      error(at, fmt::format("{} takes {} argument{}, got {}", name, f->arity, f->arity == 1 ? "" : "s", args.size()));
    return node(Op::Call, at, std::move(args), 0, name);
  }

  std::string_view s_;
  SourceLoc at_;
  const std::vector<std::string>& vars_;
  size_t i_ = 0;
  int depth_ = 0;
  std::unordered_map<const Expr*, int> height_;  // tree height of each node built
};

}  // namespace

ExprPtr parse(std::string_view text, const SourceLoc& at, const std::vector<std::string>& variables) {
  return Parser(text, at, variables).parse();
}

bool looks_like_expression(std::string_view text) {
  char* end = nullptr;
  std::string s(text);
  std::strtod(s.c_str(), &end);
  return s.empty() || end != s.c_str() + s.size();
}

}  // namespace sdfc::expr
