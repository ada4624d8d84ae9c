#include "rewriting/term.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/input_error.hpp"
#include "core/limits.hpp"
#include "core/orbit_notation.hpp"
#include "rewriting/term_functions.hpp"

namespace dartcheck {

namespace {

struct Token {
  enum Kind { end, name, number, string, punct } kind = end;
  std::string text;
  std::size_t offset = 0;
};

class Lexer {
 public:
  explicit Lexer(const std::string& s) : s_(s) { advance(); }
  const Token& peek() const { return tok_; }
  Token take() {
    Token t = tok_;
    advance();
    return t;
  }
  bool at(const char* p) const { return tok_.kind == Token::punct && tok_.text == p; }
  /// The raw text from the current token (an opening bracket) through the
  /// first `close` after it, read past; an orbit type is read by
  /// core/orbit_notation, not token by token.
  std::string_view take_through(char close) {
    const std::size_t open = tok_.offset, end = s_.find(close, open + 1);
    if (end == std::string::npos) throw TermError(open, fmt::format("'{}' is never closed by '{}'", tok_.text, close));
    k_ = end + 1;
    advance();
    return std::string_view(s_).substr(open, end + 1 - open);
  }

 private:
  void advance() {
    while (k_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[k_]))) ++k_;
    tok_ = {Token::end, "", k_};
    if (k_ == s_.size()) return;
    const char c = s_[k_];
    const std::size_t start = k_;
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (k_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[k_])) || s_[k_] == '_')) ++k_;
      tok_ = {Token::name, s_.substr(start, k_ - start), start};
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && k_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k_ + 1])))) {
      while (k_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[k_])) || s_[k_] == '.')) ++k_;
      if (k_ < s_.size() && (s_[k_] == 'e' || s_[k_] == 'E')) {
        ++k_;
        if (k_ < s_.size() && (s_[k_] == '+' || s_[k_] == '-')) ++k_;
        while (k_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k_]))) ++k_;
      }
      tok_ = {Token::number, s_.substr(start, k_ - start), start};
    } else if (c == '"') {
      ++k_;
      while (k_ < s_.size() && s_[k_] != '"') ++k_;
      if (k_ == s_.size()) throw TermError(start, "unterminated string");
      ++k_;
      tok_ = {Token::string, s_.substr(start + 1, k_ - start - 2), start};
    } else if (std::string_view("+-*/().,<>[]:").find(c) != std::string_view::npos) {
      ++k_;
      tok_ = {Token::punct, std::string(1, c), start};
    } else {
      throw TermError(start, fmt::format("unexpected character '{}'", printable(std::string_view(&c, 1))));
    }
  }
  const std::string& s_;
  std::size_t k_ = 0;
  Token tok_;
};

std::string describe(const Token& t) { return t.kind == Token::end ? "the end of the term" : fmt::format("'{}'", t.text); }

class Parser {
 public:
  explicit Parser(const std::string& s) : lex_(s) {}

  Term whole() {
    Term t = sum();
    if (lex_.peek().kind != Token::end)
      throw TermError(lex_.peek().offset, fmt::format("unexpected {} after a complete term", describe(lex_.peek())));
    return t;
  }

 private:
  void expect(const char* p, const char* after) {
    if (!lex_.at(p)) throw TermError(lex_.peek().offset, fmt::format("expected '{}' {}, found {}", p, after, describe(lex_.peek())));
    lex_.take();
  }

  // Arguments are moved in one by one: a braced list would copy them, and
  // copying the left operand at every '+' made parsing quadratic.
  static Term call(std::string op, std::size_t offset, Term a) {
    Term t;
    t.kind = Term::Kind::call;
    t.name = std::move(op);
    t.offset = offset;
    t.args.push_back(std::move(a));
    return t;
  }
  static Term call(std::string op, std::size_t offset, Term a, Term b) {
    Term t = call(std::move(op), offset, std::move(a));
    t.args.push_back(std::move(b));
    return t;
  }

  // Two bounds keep every recursion over a term (parsing, checking,
  // evaluation, printing, destruction) off the end of the stack: the
  // parser's own nesting (parentheses, arguments, unary signs), and the
  // depth of the tree it builds (depth_: of the term just returned).
  void deeper(std::size_t depth, std::size_t offset) const {
    if (depth > limits().term_depth) throw TermError(offset, over_limit("the term's nesting", depth, limits().term_depth, "--limit-term-depth"));
  }
  struct Nest {
    Parser& p;
    Nest(Parser& parser, std::size_t offset) : p(parser) { p.deeper(++p.nesting_, offset); }
    ~Nest() { --p.nesting_; }
    Nest(const Nest&) = delete;
    Nest& operator=(const Nest&) = delete;
  };

  // A left-associative chain of `next` terms joined by operator `a` or `b`.
  Term chain(Term (Parser::*next)(), const char* a, const char* b) {
    Term t = (this->*next)();
    std::size_t d = depth_;
    while (lex_.at(a) || lex_.at(b)) {
      const Token op = lex_.take();
      Term rhs = (this->*next)();
      d = std::max(d, depth_) + 1;
      deeper(d, op.offset);
      t = call(op.text, op.offset, std::move(t), std::move(rhs));
    }
    depth_ = d;
    return t;
  }
  Term sum() {
    const Nest nest(*this, lex_.peek().offset);
    return chain(&Parser::product, "+", "-");
  }
  Term product() { return chain(&Parser::unary, "*", "/"); }
  Term unary() {
    if (lex_.at("-")) {
      const Token op = lex_.take();
      const Nest nest(*this, op.offset);
      Term t = call("-", op.offset, unary());
      deeper(++depth_, op.offset);
      return t;
    }
    return postfix();
  }
  Term postfix() {
    Term t = primary();
    while (lex_.at(".")) {
      deeper(++depth_, lex_.peek().offset);
      lex_.take();
      const Token n = lex_.take();
      if (n.kind != Token::name) throw TermError(n.offset, fmt::format("expected an embedding or alpha_i after '.', found {}", describe(n)));
      Term op;
      op.offset = n.offset;
      std::string_view v = n.text;
      if (v.starts_with("alpha")) {
        v.remove_prefix(5);
        if (v.starts_with("_")) v.remove_prefix(1);
        int d = -1;
        const auto r = std::from_chars(v.data(), v.data() + v.size(), d);
        if (v.empty() || r.ec != std::errc{} || r.ptr != v.data() + v.size())
          throw TermError(n.offset, fmt::format("'{}' is not alpha_i with i a dimension", n.text));
        op.kind = Term::Kind::neighbour;
        op.dim = d;
      } else {
        op.kind = Term::Kind::access;
        op.name = n.text;
      }
      op.args.push_back(std::move(t));
      t = std::move(op);
    }
    return t;
  }
  Term primary() {
    const Token t = lex_.take();
    Term r;
    r.offset = t.offset;
    depth_ = 1;
    switch (t.kind) {
      case Token::number: {
        const bool real = t.text.find_first_of(".eE") != std::string::npos;
        r.kind = Term::Kind::literal;
        if (real) {
          double v = 0;
          const auto e = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
          if (e.ec != std::errc{} || e.ptr != t.text.data() + t.text.size()) throw TermError(t.offset, fmt::format("'{}' is not a number", t.text));
          r.literal = Value::real(v);
        } else {
          std::int64_t v = 0;
          const auto e = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
          if (e.ec != std::errc{}) throw TermError(t.offset, fmt::format("'{}' is not a number", t.text));
          r.literal = Value::integer(v);
        }
        return r;
      }
      case Token::string:
        r.kind = Term::Kind::literal;
        r.literal = Value::text(t.text);
        return r;
      case Token::punct:
        if (t.text == "(") {
          Term inner = sum();
          expect(")", "to close '('");
          return inner;
        }
        if (t.text == "[") {
          r.kind = Term::Kind::list;
          std::size_t d = 0;
          do {
            if (!r.args.empty()) lex_.take();  // ','
            r.args.push_back(sum());
            d = std::max(d, depth_);
          } while (lex_.at(","));
          expect("]", "to close the list");
          depth_ = d + 1;
          deeper(depth_, t.offset);
          return r;
        }
        throw TermError(t.offset, fmt::format("expected a term, found {}", describe(t)));
      case Token::end:
        throw TermError(t.offset, "expected a term, found the end of the term");
      case Token::name:
        break;
    }
    if (t.text == "each" && lex_.at("(")) return each(t);
    if (t.text == "true" || t.text == "false") {
      r.kind = Term::Kind::literal;
      r.literal = Value::boolean(t.text == "true");
      return r;
    }
    if (lex_.at("<")) return collect(t);
    if (lex_.at("(")) {
      lex_.take();
      r.kind = Term::Kind::call;
      r.name = t.text;
      std::size_t d = 0;
      if (!lex_.at(")")) {
        r.args.push_back(sum());
        d = depth_;
        while (lex_.at(",")) {
          lex_.take();
          r.args.push_back(sum());
          d = std::max(d, depth_);
        }
      }
      expect(")", fmt::format("to close the arguments of '{}'", t.text).c_str());
      depth_ = d + 1;
      deeper(depth_, t.offset);
      return r;
    }
    r.kind = Term::Kind::variable;
    r.name = t.text;
    return r;
  }
  // An orbit type in core/orbit_notation's syntax ("<0,2>"), sorted; '_',
  // a dimension above max_dimension and a repeat are refused (nothing of
  // what was written is dropped); `what` names the operator in messages.
  std::vector<Dim> dims(const std::string& what) {
    if (!lex_.at("<")) expect("<", fmt::format("to open the orbit type of {}", what).c_str());
    const std::size_t at = lex_.peek().offset;
    const std::string_view text = lex_.take_through('>');
    std::vector<Dim> out;
    const auto entry = [&](const OrbitEntry& e) {
      const std::size_t offset = at + e.offset;
      if (e.text == "_") throw TermError(offset, fmt::format("'_' in the orbit type of {} is not a dimension: an orbit removes none", what));
      int dim = -1;
      const auto r = std::from_chars(e.text.data(), e.text.data() + e.text.size(), dim);
      if (r.ec != std::errc{} || dim > max_dimension)
        throw TermError(offset, fmt::format("'{}' in the orbit type of {} is not a dimension (0 to {})", e.text, what, max_dimension));
      if (std::find(out.begin(), out.end(), dim) != out.end())
        throw TermError(offset, fmt::format("dimension {} appears twice in the orbit type of {}", dim, what));
      out.push_back(dim);
    };
    try {
      read_orbit_entries(text, entry);
    } catch (const OrbitNotationError& e) {
      throw TermError(at + e.offset(), fmt::format("the orbit type of {}: {}", what, e.what()));
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  // each(x in <o>(y): t) or each(x in <o>_<s>(y): t).
  Term each(const Token& kw) {
    lex_.take();  // '('
    Term r;
    r.kind = Term::Kind::each;
    r.offset = kw.offset;
    const Token x = lex_.take();
    if (x.kind != Token::name) throw TermError(x.offset, fmt::format("expected the name of each's dart variable, found {}", describe(x)));
    r.name = x.text;
    const Token in = lex_.take();
    if (in.kind != Token::name || in.text != "in") throw TermError(in.offset, fmt::format("expected 'in' after '{}', found {}", x.text, describe(in)));
    r.orbit = dims("each");
    if (lex_.peek().kind == Token::name && lex_.peek().text == "_") {
      lex_.take();
      r.per_sub = true;
      r.sub_orbit = dims("each's sub-orbit");
    }
    expect("(", "after the orbit type of each");
    r.args.push_back(sum());
    std::size_t d = depth_;
    expect(")", "to close each's start node");
    expect(":", "before each's body");
    r.args.push_back(sum());
    d = std::max(d, depth_);
    expect(")", "to close each");
    depth_ = d + 1;
    deeper(depth_, kw.offset);
    return r;
  }
  // pi<o'>(x) or pi_<o'>(x).
  Term collect(const Token& name) {
    Term r;
    r.kind = Term::Kind::collect;
    r.offset = name.offset;
    r.name = name.text;
    if (r.name.size() > 1 && r.name.back() == '_') r.name.pop_back();
    r.orbit = dims(fmt::format("'{}'", r.name));
    expect("(", fmt::format("after the orbit type of the collect operator '{}'", r.name).c_str());
    r.args.push_back(sum());
    expect(")", "to close the collect operator");
    deeper(++depth_, name.offset);
    return r;
  }

  Lexer lex_;
  std::size_t nesting_ = 0, depth_ = 0;
};

bool is_infix(const Term& t) {
  return t.kind == Term::Kind::call && t.args.size() == 2 && (t.name == "+" || t.name == "-" || t.name == "*" || t.name == "/");
}
int precedence(const Term& t) {
  if (is_infix(t)) return t.name == "+" || t.name == "-" ? 1 : 2;
  if (t.kind == Term::Kind::call && t.args.size() == 1 && t.name == "-") return 3;
  return 4;
}

// The free node variables of t: each's dart variable is bound in its body.
void collect_variables(const Term& t, std::vector<std::string>& out, std::vector<std::string>& bound) {
  if (t.kind == Term::Kind::variable && std::find(bound.begin(), bound.end(), t.name) == bound.end()) out.push_back(t.name);
  if (t.kind == Term::Kind::each) {
    collect_variables(t.args[0], out, bound);
    bound.push_back(t.name);
    collect_variables(t.args[1], out, bound);
    bound.pop_back();
    return;
  }
  for (const Term& a : t.args) collect_variables(a, out, bound);
}

std::string dims_str(const std::vector<Dim>& o) { return fmt::format("{}", fmt::join(o, ",")); }

}  // namespace

Term parse_term(const std::string& text) {
  if (text.size() > limits().term_length)
    throw TermError(limits().term_length, over_limit("the term's length", text.size(), limits().term_length, "--limit-term-length"));
  return Parser(text).whole();
}

std::string Term::str() const {
  auto sub = [](const Term& t, int min) { return precedence(t) < min ? fmt::format("({})", t.str()) : t.str(); };
  switch (kind) {
    case Kind::variable:
    case Kind::parameter:
      return name;
    case Kind::literal:
      return literal.str();
    case Kind::access:
      return fmt::format("{}.{}", sub(args[0], 4), name);
    case Kind::neighbour:
      return fmt::format("{}.alpha{}", sub(args[0], 4), dim);
    case Kind::collect:
      return fmt::format("{}<{}>({})", name, dims_str(orbit), args[0].str());
    case Kind::each:
      return fmt::format("each({} in <{}>{}({}): {})", name, dims_str(orbit), per_sub ? fmt::format("_<{}>", dims_str(sub_orbit)) : "", args[0].str(),
                         args[1].str());
    case Kind::list: {
      std::vector<std::string> parts;
      for (const Term& a : args) parts.push_back(a.str());
      return fmt::format("[{}]", fmt::join(parts, ", "));
    }
    case Kind::call:
      break;
  }
  if (implicit) return args[0].str();
  if (is_infix(*this)) {
    const int p = precedence(*this);
    return fmt::format("{} {} {}", sub(args[0], p), name, sub(args[1], p + 1));
  }
  if (args.size() == 1 && name == "-") return fmt::format("-{}", sub(args[0], 3));
  std::vector<std::string> parts;
  for (const Term& a : args) parts.push_back(a.str());
  return fmt::format("{}({})", name, fmt::join(parts, ", "));
}

bool Term::same(const Term& o) const {
  // Conversions inserted by the checker are invisible.
  if (implicit) return args[0].same(o);
  if (o.implicit) return same(o.args[0]);
  if (kind != o.kind || name != o.name || dim != o.dim || orbit != o.orbit || per_sub != o.per_sub || sub_orbit != o.sub_orbit || args.size() != o.args.size())
    return false;
  if (kind == Kind::literal && !(literal == o.literal)) return false;
  for (std::size_t k = 0; k < args.size(); ++k)
    if (!args[k].same(o.args[k])) return false;
  return true;
}

std::vector<std::string> Term::variables() const {
  std::vector<std::string> r, bound;
  collect_variables(*this, r, bound);
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}

const EmbeddingSignature* TermScope::find_embedding(const std::string& name) const {
  if (!embeddings) return nullptr;
  for (const auto& e : *embeddings)
    if (e.name == name) return &e;
  return nullptr;
}

namespace {

std::string known_embeddings(const TermScope& s) {
  std::string r;
  if (s.embeddings)
    for (const auto& e : *s.embeddings) r += (r.empty() ? "" : ", ") + e.name;
  return r.empty() ? "none declared" : r;
}

Sort expect_node(Term& arg, const TermScope& scope, const Term& op, const char* what) {
  const Sort s = check_term(arg, scope);
  if (s.kind != Sort::node) throw TermError(arg.offset, fmt::format("{} applies to a node, '{}' is a {}", what, arg.str(), s.str()));
  (void)op;
  return s;
}

// each(x in <o>(y): t): a bag of the body's values, x a new dart variable.
Sort check_each(Term& t, const TermScope& scope) {
  for (const auto* o : {&t.orbit, &t.sub_orbit})
    for (Dim d : *o)
      if (scope.model && !scope.model->contains(d))
        throw TermError(t.offset, fmt::format("each: {} is not a dimension of the model {}", d, scope.model->name));
  expect_node(t.args[0], scope, t, "each");
  if (std::find(scope.variables.begin(), scope.variables.end(), t.name) != scope.variables.end() || scope.parameters.count(t.name))
    throw TermError(t.offset, fmt::format("each: the dart variable '{}' hides a node or parameter of that name", t.name));
  TermScope inner = scope;
  inner.variables.push_back(t.name);
  const Sort body = check_term(t.args[1], inner);
  if (body.kind != Sort::value)
    throw TermError(t.args[1].offset, fmt::format("each's body must be a value, '{}' is a {}", t.args[1].str(), body.str()));
  return t.sort = Sort::bag(body.type);
}

// [a, b, ...]: a bag of values of one type.
Sort check_list(Term& t, const TermScope& scope) {
  std::optional<ValueType> type;
  for (Term& a : t.args) {
    const Sort s = check_term(a, scope);
    if (s.kind == Sort::node) throw TermError(a.offset, fmt::format("a list holds values, '{}' is a node", a.str()));
    if (type && s.type != *type)
      throw TermError(a.offset,
                      fmt::format("a list holds values of one type: '{}' is a {}, the list's first element a {}", a.str(), s.str(), name_of(*type)));
    type = s.type;
  }
  if (!type) throw TermError(t.offset, "an empty list has no type");
  return t.sort = Sort::bag(*type);
}

// A function call: the overload of the arguments' sorts, an integer
// argument promoted to real where that finds one.
Sort check_call(Term& t, const TermScope& scope) {
  std::vector<Sort> sorts;
  for (Term& a : t.args) sorts.push_back(check_term(a, scope));
  const FunctionRegistry& reg = scope.functions ? *scope.functions : FunctionRegistry::builtin();
  const Function* f = reg.find(t.name, sorts);
  if (!f) {
    // An integer argument may stand for a real one (2 * v, point2(0, 1)).
    std::vector<Sort> promoted = sorts;
    for (Sort& s : promoted)
      if (s == Sort::of(ValueType::integer)) s = Sort::of(ValueType::real);
    if (promoted != sorts && (f = reg.find(t.name, promoted))) {
      for (std::size_t k = 0; k < t.args.size(); ++k)
        if (sorts[k] != promoted[k]) {
          Term conv;
          conv.kind = Term::Kind::call;
          conv.name = "real";
          conv.implicit = true;
          conv.offset = t.args[k].offset;
          conv.function = reg.find("real", {Sort::of(ValueType::integer)});
          conv.sort = Sort::of(ValueType::real);
          conv.args.push_back(std::move(t.args[k]));
          t.args[k] = std::move(conv);
        }
    }
  }
  if (!f) {
    std::string args;
    for (std::size_t k = 0; k < sorts.size(); ++k) args += (k ? " x " : "") + sorts[k].str();
    const auto over = reg.overloads(t.name);
    if (over.empty()) throw TermError(t.offset, fmt::format("unknown function '{}'", t.name));
    std::string known;
    for (const Function* o : over) known += fmt::format("\n  {}", o->profile());
    throw TermError(t.offset, fmt::format("no '{}' takes ({}); known profiles:{}", t.name, args, known));
  }
  t.function = f;
  return t.sort = f->result;
}

}  // namespace

Sort check_term(Term& t, const TermScope& scope) {
  switch (t.kind) {
    case Term::Kind::literal:
      return t.sort = Sort::of(t.literal.type);
    case Term::Kind::parameter:
      return t.sort;
    case Term::Kind::variable: {
      if (std::find(scope.variables.begin(), scope.variables.end(), t.name) != scope.variables.end()) return t.sort = Sort::node_sort();
      if (const auto p = scope.parameters.find(t.name); p != scope.parameters.end()) {
        t.kind = Term::Kind::parameter;
        t.literal = p->second;
        return t.sort = Sort::of(p->second.type);
      }
      std::string vars;
      for (const auto& v : scope.variables) vars += (vars.empty() ? "" : ", ") + v;
      throw TermError(t.offset,
                      fmt::format("'{}' is neither a node of the left-hand side ({}) nor a parameter", t.name, vars.empty() ? "no nodes" : vars));
    }
    case Term::Kind::access: {
      expect_node(t.args[0], scope, t, fmt::format("'.{}'", t.name).c_str());
      const EmbeddingSignature* e = scope.find_embedding(t.name);
      if (!e) throw TermError(t.offset, fmt::format("'{}' is not an embedding (embeddings: {})", t.name, known_embeddings(scope)));
      return t.sort = Sort::of(e->type);
    }
    case Term::Kind::neighbour:
      expect_node(t.args[0], scope, t, "'.alpha'");
      if (scope.model && !scope.model->contains(t.dim))
        throw TermError(t.offset, fmt::format("alpha{}: {} is not a dimension of the model {}", t.dim, t.dim, scope.model->name));
      return t.sort = Sort::node_sort();
    case Term::Kind::collect: {
      const EmbeddingSignature* e = scope.find_embedding(t.name);
      if (!e) throw TermError(t.offset, fmt::format("'{}' is not an embedding (embeddings: {})", t.name, known_embeddings(scope)));
      for (Dim d : t.orbit)
        if (scope.model && !scope.model->contains(d))
          throw TermError(t.offset, fmt::format("{}<...>: {} is not a dimension of the model {}", t.name, d, scope.model->name));
      expect_node(t.args[0], scope, t, fmt::format("the collect operator '{}'", t.name).c_str());
      return t.sort = Sort::bag(e->type);
    }
    case Term::Kind::each:
      return check_each(t, scope);
    case Term::Kind::list:
      return check_list(t, scope);
    case Term::Kind::call:
      break;
  }
  return check_call(t, scope);
}

}  // namespace dartcheck
