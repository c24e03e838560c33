// Recursive-descent parser of expressions (grammar in parser.h).
#include "sillage/expr/parser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>

#include "sillage/error.h"
#include "sillage/expr/literal.h"
#include "sillage/text_utf8.h"

namespace sillage::detail {
namespace {

struct FunctionSpec {
  int arity;
  Expr (*unary)(const Expr&);
  Expr (*binary)(const Expr&, const Expr&);
};

Expr pow_xy(const Expr& x, const Expr& y) { return pow(x, y); }

const std::unordered_map<std::string, FunctionSpec>& functions() {
  static const std::unordered_map<std::string, FunctionSpec> table = {
      {"sqr", {1, sqr, nullptr}},     {"sqrt", {1, sqrt, nullptr}},   {"exp", {1, exp, nullptr}},
      {"log", {1, log, nullptr}},     {"sin", {1, sin, nullptr}},     {"cos", {1, cos, nullptr}},
      {"tan", {1, tan, nullptr}},     {"asin", {1, asin, nullptr}},   {"acos", {1, acos, nullptr}},
      {"atan", {1, atan, nullptr}},   {"sinh", {1, sinh, nullptr}},   {"cosh", {1, cosh, nullptr}},
      {"tanh", {1, tanh, nullptr}},   {"abs", {1, abs, nullptr}},     {"sign", {1, sign, nullptr}},
      {"atan2", {2, nullptr, atan2}}, {"min", {2, nullptr, min}},     {"max", {2, nullptr, max}},
      {"pow", {2, nullptr, pow_xy}},  {"root", {2, nullptr, nullptr}},
  };
  return table;
}

enum class Tok {
  Number, Ident, LParen, RParen, LBracket, RBracket, Comma, Plus, Minus, Star, Slash, Caret, Equals, Semicolon, End
};

struct Token {
  Tok kind;
  std::string text;
  std::size_t col;  // 1-based, in characters
};

const char* tok_name(Tok k) {
  switch (k) {
    case Tok::Number: return "a number";
    case Tok::Ident: return "a name";
    case Tok::LParen: return "'('";
    case Tok::RParen: return "')'";
    case Tok::LBracket: return "'['";
    case Tok::RBracket: return "']'";
    case Tok::Comma: return "','";
    case Tok::Plus: return "'+'";
    case Tok::Minus: return "'-'";
    case Tok::Star: return "'*'";
    case Tok::Slash: return "'/'";
    case Tok::Caret: return "'^'";
    case Tok::Equals: return "'='";
    case Tok::Semicolon: return "';'";
    case Tok::End: return "the end";
  }
  return "?";
}

// A parsed item: one expression, or the elements of a parenthesized vector.
struct Item {
  std::vector<Expr> exprs;
  std::size_t col;
};

class Parser {
 public:
  Parser(const std::vector<std::string>& vars, const std::string& text) : text_(text) {
    for (const std::string& v : vars) vars_.emplace(v, ExprVar(v));
    tokenize();
  }

  std::vector<Expr> parse_all() {
    if (peek().kind == Tok::Ident && peek().text == "let") parse_bindings();
    Item it = parse_sum();
    if (peek().kind != Tok::End) fail("expected an operator or the end", peek().col);
    return it.exprs;
  }

 private:
  // Short texts are quoted whole, long ones around the column.
  [[noreturn]] void fail(const std::string& what, std::size_t col) const {
    const std::string text = text_.size() <= 60 ? valid_utf8(text_) : excerpt(text_, col);
    throw ParseError(what + " at column " + std::to_string(col) + (text_.size() <= 60 ? " in \"" : " near \"") +
                     text + "\"");
  }

  // "let a = e1; b = e2 in e": names for sub-expressions (see operator<<).
  void parse_bindings() {
    next();
    for (;;) {
      const Token name = expect(Tok::Ident);
      if (vars_.count(name.text) || bindings_.count(name.text) || is_reserved_name(name.text)) {
        fail(std::string("'").append(quote_text(name.text)).append("' is a variable, a reserved name or already bound"),
             name.col);
      }
      expect(Tok::Equals);
      const Expr e = scalar(parse_sum());
      bindings_.emplace(name.text, e);
      if (peek().kind == Tok::Semicolon) {
        next();
        continue;
      }
      if (peek().kind == Tok::Ident && peek().text == "in") {
        next();
        return;
      }
      fail("expected ';' or 'in'", peek().col);
    }
  }

  void tokenize() {
    std::size_t i = 0;
    const std::string& s = text_;
    // Columns count characters: the bytes that do not continue a UTF-8 sequence.
    std::size_t counted = 0, chars = 0;
    auto column = [&](std::size_t at) {
      for (; counted < at; ++counted) chars += (static_cast<unsigned char>(s[counted]) & 0xC0) != 0x80;
      return chars + 1;
    };
    while (i < s.size()) {
      const char c = s[i];
      const std::size_t col = column(i);
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
      } else if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < s.size() &&
                                                                 std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
        std::size_t j = i;
        while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) ++j;
        if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
          std::size_t k = j + 1;
          if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
          if (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) {
            j = k;
            while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
          } else {
            fail("expected digits of the exponent", column(k));
          }
        }
        toks_.push_back({Tok::Number, s.substr(i, j - i), col});
        i = j;
      } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        std::size_t j = i;
        while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
        toks_.push_back({Tok::Ident, s.substr(i, j - i), col});
        i = j;
      } else {
        Tok k;
        switch (c) {
          case '(': k = Tok::LParen; break;
          case ')': k = Tok::RParen; break;
          case '[': k = Tok::LBracket; break;
          case ']': k = Tok::RBracket; break;
          case ',': k = Tok::Comma; break;
          case '+': k = Tok::Plus; break;
          case '-': k = Tok::Minus; break;
          case '*': k = Tok::Star; break;
          case '/': k = Tok::Slash; break;
          case '^': k = Tok::Caret; break;
          case '=': k = Tok::Equals; break;
          case ';': k = Tok::Semicolon; break;
          default: unexpected(i, col);
        }
        toks_.push_back({k, std::string(1, c), col});
        ++i;
      }
    }
    toks_.push_back({Tok::End, "", column(s.size())});
  }

  // The whole character at byte i, or the byte if it is not UTF-8.
  [[noreturn]] void unexpected(std::size_t i, std::size_t col) const {
    const unsigned char c = static_cast<unsigned char>(text_[i]);
    if (c < 0x20 || c == 0x7F) fail("unexpected control character " + code_point_name(text_.substr(i, 1)), col);
    const std::size_t n = utf8_sequence_length(text_, i);
    if (n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", c);
      fail(std::string("unexpected byte ") + hex + " (the text is not valid UTF-8)", col);
    }
    const std::string ch = text_.substr(i, n);
    fail("unexpected character '" + ch + "'" + (n > 1 ? " (" + code_point_name(ch) + ")" : ""), col);
  }

  const Token& peek() const { return toks_[pos_]; }
  const Token& next() { return toks_[pos_ < toks_.size() - 1 ? pos_++ : pos_]; }
  const Token& expect(Tok k) {
    if (peek().kind != k) fail(std::string("expected ") + tok_name(k), peek().col);
    return next();
  }

  // The single expression of an item used as an operand.
  Expr scalar(const Item& it) const {
    if (it.exprs.size() != 1) fail("a vector (e1, e2, ...) can only be the whole expression", it.col);
    return it.exprs[0];
  }

  // Bounds the recursion: a pathological text must raise, not overflow the
  // stack. One level per parenthesis, bracket-free call, sign or exponent:
  // exactly the nesting a reader sees.
  struct DepthGuard {
    Parser& p;
    explicit DepthGuard(Parser& parser) : p(parser) {
      if (++p.depth_ > kMaxDepth) p.fail("expression nested too deeply (more than 500 levels)", p.peek().col);
    }
    ~DepthGuard() { --p.depth_; }
  };
  static constexpr int kMaxDepth = 500;

  Item parse_sum() {
    Item left = parse_product();
    while (peek().kind == Tok::Plus || peek().kind == Tok::Minus) {
      const bool plus = next().kind == Tok::Plus;
      Expr a = scalar(left);
      Expr b = scalar(parse_product());
      left = {{plus ? a + b : a - b}, left.col};
    }
    return left;
  }

  Item parse_product() {
    Item left = parse_unary();
    while (peek().kind == Tok::Star || peek().kind == Tok::Slash) {
      const bool times = next().kind == Tok::Star;
      Expr a = scalar(left);
      Expr b = scalar(parse_unary());
      left = {{times ? a * b : a / b}, left.col};
    }
    return left;
  }

  Item parse_unary() {
    if (peek().kind == Tok::Minus || peek().kind == Tok::Plus) {
      DepthGuard guard(*this);
      const Token& t = next();
      const bool minus = t.kind == Tok::Minus;
      const std::size_t col = t.col;
      Expr a = scalar(parse_unary());
      return {{minus ? -a : a}, col};
    }
    return parse_power();
  }

  Item parse_power() {
    Item base = parse_primary();
    if (peek().kind != Tok::Caret) return base;
    next();
    DepthGuard guard(*this);
    Expr b = scalar(base);
    Expr e = scalar(parse_unary());  // right-associative: x^y^z = x^(y^z)
    return {{pow(b, e)}, base.col};
  }

  // Enclosure of a signed interval bound: number, inf or oo.
  Interval parse_bound() {
    bool neg = false;
    if (peek().kind == Tok::Minus || peek().kind == Tok::Plus) neg = next().kind == Tok::Minus;
    const Token& t = next();
    Interval v;
    if (t.kind == Tok::Number) {
      v = number(t);
    } else if (t.kind == Tok::Ident && (t.text == "inf" || t.text == "oo")) {
      v = Interval::from_bounds_unchecked(rounding::kInf, rounding::kInf);
    } else if (t.kind == Tok::Ident && is_nan_name(t.text)) {
      fail("NaN is not a valid bound", t.col);
    } else {
      fail("expected a number, inf or oo as interval bound", t.col);
    }
    return neg ? Interval::from_bounds_unchecked(-v.ub(), -v.lb()) : v;
  }

  Interval number(const Token& t) const {
    try {
      return detail::decimal_enclosure(t.text);
    } catch (const ParseError&) {
      fail("invalid number literal '" + quote_text(t.text) + "'", t.col);
    }
  }

  static bool is_nan_name(const std::string& s) {
    std::string l = s;
    std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return std::tolower(c); });
    return l == "nan";
  }

  Item parse_interval(std::size_t col) {
    if (peek().kind == Tok::Ident && peek().text == "empty") {
      next();
      expect(Tok::RBracket);
      return {{Expr(Interval::empty())}, col};
    }
    const Interval a = parse_bound();
    expect(Tok::Comma);
    const Interval b = parse_bound();
    expect(Tok::RBracket);
    if (a.lb() > b.ub()) fail("invalid interval literal: lower bound above upper bound", col);
    if (a.lb() == rounding::kInf || b.ub() == -rounding::kInf)
      fail("invalid interval literal: it contains no real number", col);
    return {{Expr(Interval(a.lb(), b.ub()))}, col};
  }

  Item parse_call(const Token& name) {
    DepthGuard guard(*this);
    const auto it = functions().find(name.text);
    expect(Tok::LParen);
    std::vector<Expr> args{scalar(parse_sum())};
    while (peek().kind == Tok::Comma) {
      next();
      args.push_back(scalar(parse_sum()));
    }
    expect(Tok::RParen);
    const FunctionSpec& f = it->second;
    if (static_cast<int>(args.size()) != f.arity)
      fail("function '" + name.text + "' takes " + std::to_string(f.arity) + " argument" +
               (f.arity > 1 ? "s" : "") + ", got " + std::to_string(args.size()),
           name.col);
    if (name.text == "root") {
      const Expr& n = args[1];
      const bool ok = n.is_const() && n.node().value.is_degenerate() && n.node().value.lb() >= 1 &&
                      n.node().value.lb() <= 1e6 && n.node().value.lb() == std::floor(n.node().value.lb());
      if (!ok) fail("root(x, n): n must be an integer constant >= 1", name.col);
      return {{root(args[0], static_cast<int>(n.node().value.lb()))}, name.col};
    }
    return {{f.arity == 1 ? f.unary(args[0]) : f.binary(args[0], args[1])}, name.col};
  }

  Item parse_primary() {
    const Token& t = next();
    switch (t.kind) {
      case Tok::Number: return {{Expr(number(t))}, t.col};
      case Tok::LBracket: return parse_interval(t.col);
      case Tok::LParen: {
        DepthGuard guard(*this);
        Item it{{scalar(parse_sum())}, t.col};
        while (peek().kind == Tok::Comma) {
          next();
          it.exprs.push_back(scalar(parse_sum()));
        }
        expect(Tok::RParen);
        return it;
      }
      case Tok::Ident: {
        if (functions().count(t.text)) return parse_call(t);
        if (auto v = vars_.find(t.text); v != vars_.end()) return {{v->second}, t.col};
        if (auto b = bindings_.find(t.text); b != bindings_.end()) return {{b->second}, t.col};
        if (t.text == "pi") return {{expr_pi()}, t.col};
        if (is_nan_name(t.text)) fail("NaN is not a valid number", t.col);
        fail("unknown identifier '" + quote_text(t.text) + "'", t.col);
      }
      case Tok::End: fail("expected an operand", t.col);
      default: fail("expected an operand, got " + std::string(tok_name(t.kind)), t.col);
    }
  }

  std::string text_;
  std::unordered_map<std::string, Expr> vars_;
  std::unordered_map<std::string, Expr> bindings_;  // let
  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

void check_var_names(const std::vector<std::string>& vars) {
  std::unordered_set<std::string> seen;
  for (const std::string& v : vars) {
    ExprVar check(v);  // throws on an invalid identifier
    if (is_reserved_name(v)) throw Error("Function: \"" + v + "\" is a reserved name, not a variable name");
    if (!seen.insert(v).second) throw Error("Function: variable \"" + v + "\" declared twice");
  }
}

}  // namespace

bool is_reserved_name(const std::string& name) {
  std::string l = name;
  std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return std::tolower(c); });
  return name == "pi" || name == "inf" || name == "oo" || name == "empty" || name == "let" || name == "in" ||
         l == "nan" || functions().count(name) > 0;
}

std::vector<Expr> parse_exprs(const std::vector<std::string>& vars, const std::string& text) {
  check_var_names(vars);
  return Parser(vars, text).parse_all();
}

Expr parse_expr(const std::vector<std::string>& vars, const std::string& text) {
  std::vector<Expr> es = parse_exprs(vars, text);
  if (es.size() != 1)
    throw ParseError("expected a scalar expression, got a vector of size " + std::to_string(es.size()) + " in \"" +
                     quote_text(text) + "\"");
  return es[0];
}

}  // namespace sillage::detail
