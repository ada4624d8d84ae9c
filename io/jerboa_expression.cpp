#include "io/jerboa_expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <deque>
#include <functional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "rewriting/term_functions.hpp"

namespace dartcheck {

namespace {

// --- Tokens ----------------------------------------------------------------

struct Token {
  enum Kind { end, ident, number, text, punct } kind = end;
  std::string s;
  std::size_t offset = 0;
};

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '$'; }

// A decimal number from `start`: digits and '_', a fraction, an exponent,
// a type suffix; returns where it ends.
std::size_t decimal_end(const std::string& s, std::size_t start) {
  std::size_t k = start;
  while (k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '_')) ++k;
  // "2.5", "2.f" and "2." are numbers; "n0@2.pos" is a neighbour's
  // embedding (Jerboa's '@' is read before Java's lexer).
  if (k < s.size() && s[k] == '.') {
    const char n = k + 1 < s.size() ? s[k + 1] : ' ';
    const bool suffix = (n == 'f' || n == 'F' || n == 'd' || n == 'D') && !(k + 2 < s.size() && ident_char(s[k + 2]));
    if (std::isdigit(static_cast<unsigned char>(n)) || suffix || !std::isalpha(static_cast<unsigned char>(n))) {
      ++k;
      while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
    }
  }
  if (k < s.size() && (s[k] == 'e' || s[k] == 'E')) {
    ++k;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
    while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
  }
  if (k < s.size() && std::string_view("fFdDlL").find(s[k]) != std::string_view::npos) ++k;
  if (k < s.size() && ident_char(s[k])) throw JerboaCodeError(start, fmt::format("not Java: '{}' is not a number", s.substr(start, k + 1 - start)));
  return k;
}

// Brackets must balance, as in any Java.
void check_brackets(const std::vector<Token>& tokens) {
  std::vector<const Token*> open;
  for (const Token& t : tokens) {
    if (t.kind != Token::punct) continue;
    if (t.s == "(" || t.s == "[" || t.s == "{") open.push_back(&t);
    if (t.s == ")" || t.s == "]" || t.s == "}") {
      const char want = t.s == ")" ? '(' : t.s == "]" ? '[' : '{';
      if (open.empty() || open.back()->s[0] != want) throw JerboaCodeError(t.offset, fmt::format("not Java: '{}' closes nothing", t.s));
      open.pop_back();
    }
  }
  if (!open.empty()) throw JerboaCodeError(open.back()->offset, fmt::format("not Java: '{}' is never closed", open.back()->s));
}

// Java's tokens, comments dropped; what cannot be Java at all (an
// unterminated literal or comment, a byte Java has no use for) throws.
std::vector<Token> tokens(const std::string& s) {
  std::vector<Token> out;
  std::size_t k = 0;
  static const char* const ops[] = {"+=", "-=", "*=", "/=", "++", "--", "==", "!=", "<=", ">=", "&&", "||", "->", "::"};
  while (k < s.size()) {
    const char c = s[k];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++k;
      continue;
    }
    const std::size_t start = k;
    if (c == '/' && k + 1 < s.size() && s[k + 1] == '/') {
      while (k < s.size() && s[k] != '\n') ++k;
      continue;
    }
    if (c == '/' && k + 1 < s.size() && s[k + 1] == '*') {
      const auto e = s.find("*/", k + 2);
      if (e == std::string::npos) throw JerboaCodeError(start, "not Java: a comment '/*' that is never closed");
      k = e + 2;
      continue;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$') {
      while (k < s.size() && ident_char(s[k])) ++k;
      out.push_back({Token::ident, s.substr(start, k - start), start});
      continue;
    }
    if (c == '0' && k + 1 < s.size() && std::string_view("xXbB").find(s[k + 1]) != std::string_view::npos) {  // 0x1F, 0b101
      k += 2;
      while (k < s.size() && (std::isxdigit(static_cast<unsigned char>(s[k])) || s[k] == '_')) ++k;
      if (k < s.size() && (s[k] == 'l' || s[k] == 'L')) ++k;
      out.push_back({Token::number, s.substr(start, k - start), start});
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && k + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[k + 1])))) {
      k = decimal_end(s, start);
      out.push_back({Token::number, s.substr(start, k - start), start});
      continue;
    }
    if (c == '"' || c == '\'') {
      ++k;
      while (k < s.size() && s[k] != c && s[k] != '\n') k += s[k] == '\\' ? 2 : 1;
      if (k >= s.size() || s[k] != c) throw JerboaCodeError(start, fmt::format("not Java: a {} literal that is never closed", c == '"' ? "string" : "character"));
      ++k;
      out.push_back({Token::text, s.substr(start, k - start), start});
      continue;
    }
    bool two = false;
    for (const char* op : ops)
      if (s.compare(k, 2, op) == 0) {
        out.push_back({Token::punct, op, start});
        k += 2;
        two = true;
        break;
      }
    if (two) continue;
    if (std::string_view("+-*/%()[]{};,.=<>@!&|?:^~").find(c) == std::string_view::npos)
      throw JerboaCodeError(start, fmt::format("not Java: unexpected character '{}'", c >= 0x20 && c < 0x7f ? std::string(1, c) : fmt::format("\\x{:02x}", static_cast<unsigned char>(c))));
    out.push_back({Token::punct, std::string(1, c), start});
    ++k;
  }
  check_brackets(out);
  out.push_back({Token::end, "", s.size()});
  return out;
}

// --- Symbolic values -------------------------------------------------------

// What the reader does not read: caught at the expression's top.
struct Opaque {
  std::size_t offset;
  std::string reason;
};

// A Java value during symbolic execution.
struct Sym {
  enum Kind { none, value, node, darts, list } kind = none;
  Term term;                      // value: its term; node: the node term; darts: the start node
  ValueType type = ValueType::real;  // value; list: element type
  std::vector<Dim> orbit, sub;    // darts
  bool per_sub = false;           // darts: <o>_<s>
  std::vector<Term> parts;        // list: values and multisets, in order
  bool typed = false;             // list: element type known
};

const char* const marker = "@acc:";  // a loop's running value (not a Java name)

Term make_call(std::string name, std::vector<Term> args, std::size_t offset) {
  Term t;
  t.kind = Term::Kind::call;
  t.name = std::move(name);
  t.args = std::move(args);
  t.offset = offset;
  return t;
}
Term make_literal(Value v, std::size_t offset) {
  Term t;
  t.kind = Term::Kind::literal;
  t.literal = v;
  t.offset = offset;
  return t;
}
Term make_variable(std::string name, std::size_t offset) {
  Term t;
  t.kind = Term::Kind::variable;
  t.name = std::move(name);
  t.offset = offset;
  return t;
}

bool mentions_marker(const Term& t) {
  if (t.kind == Term::Kind::variable && t.name.starts_with(marker)) return true;
  return std::any_of(t.args.begin(), t.args.end(), mentions_marker);
}
void substitute(Term& t, const std::string& name, const Term& by) {
  if (t.kind == Term::Kind::variable && t.name == name) {
    t = by;
    return;
  }
  for (Term& a : t.args) substitute(a, name, by);
}

bool geometric(ValueType t) { return t == ValueType::point3 || t == ValueType::vector3 || t == ValueType::color; }
bool scalar(ValueType t) { return t == ValueType::real || t == ValueType::integer; }

std::string last_component(const std::string& type) {
  const auto dot = type.rfind('.');
  return dot == std::string::npos ? type : type.substr(dot + 1);
}

// --- The reader --------------------------------------------------------------

class Reader {
 public:
  Reader(const std::string& code, const JerboaScope& scope) : toks_(tokens(code)), scope_(scope) { vars_.emplace_back(); }

  // The statements, symbolically executed; the returned value.
  Sym body() {
    while (!at_end()) {
      if (returned_) throw Opaque{peek().offset, "has statements after its return"};
      statement(true);
    }
    if (!returned_) throw Opaque{peek().offset, "has no return statement"};
    return result_;
  }

 private:
  struct Var {
    Sym sym;
    std::size_t declared_at = 0;
  };

  // Tokens.
  const Token& peek(std::size_t ahead = 0) const { return toks_[std::min(pos_ + ahead, toks_.size() - 1)]; }
  bool at_end() const { return peek().kind == Token::end; }
  bool at(const char* p, std::size_t ahead = 0) const { return peek(ahead).kind == Token::punct && peek(ahead).s == p; }
  bool at_ident(const char* w, std::size_t ahead = 0) const { return peek(ahead).kind == Token::ident && peek(ahead).s == w; }
  Token take() { return toks_[pos_ < toks_.size() - 1 ? pos_++ : pos_]; }
  void expect(const char* p, const char* where) {
    if (!at(p)) throw JerboaCodeError(peek().offset, fmt::format("not Java: expected '{}' {}, found {}", p, where, shown(peek())));
    take();
  }
  static std::string shown(const Token& t) { return t.kind == Token::end ? "the end of the expression" : fmt::format("'{}'", t.s); }

  // Variables.
  Var* find(const std::string& name) {
    for (auto s = vars_.rbegin(); s != vars_.rend(); ++s)
      if (const auto it = s->find(name); it != s->end()) return &it->second;
    return nullptr;
  }
  const EmbeddingSignature* embedding(const std::string& name) const {
    for (const auto& e : scope_.embeddings)
      if (e.name == name) return &e;
    return nullptr;
  }
  std::string embedding_names() const {
    std::vector<std::string> n;
    for (const auto& e : scope_.embeddings) n.push_back(e.name);
    return n.empty() ? "none" : fmt::format("{}", fmt::join(n, ", "));
  }

  // --- Types ---------------------------------------------------------------

  // A declared type: what kind of Sym the variable holds.
  struct Declared {
    Sym::Kind kind = Sym::value;
    ValueType type = ValueType::real;
    bool inferred = false;  // var
    bool typed = true;      // list: element type known
  };
  std::optional<ValueType> value_class(const std::string& name) const {
    if (name.starts_with("@ebd:")) {
      if (const auto* e = embedding(name.substr(5))) return e->type;
      return std::nullopt;
    }
    const std::string n = last_component(name);
    if (n == "float" || n == "double" || n == "Float" || n == "Double") return ValueType::real;
    if (n == "int" || n == "long" || n == "short" || n == "Integer" || n == "Long") return ValueType::integer;
    if (n == "boolean" || n == "Boolean") return ValueType::boolean;
    return jerboa_value_type(n);
  }
  // type := '@' 'ebd' '<' name '>' | name ('.' name)* ['<' type (',' type)* '>'] ; returns the type's text ("@ebd:pos" for the first form).
  std::string type_text(std::vector<std::string>* args = nullptr) {
    if (at("@")) {
      const Token a = take();
      if (!at_ident("ebd")) throw Opaque{a.offset, "uses an annotation other than @ebd<...>"};
      take();
      expect("<", "after @ebd");
      const Token e = take();
      if (e.kind != Token::ident) throw JerboaCodeError(e.offset, fmt::format("not Java: expected an embedding name in @ebd<...>, found {}", shown(e)));
      if (!embedding(e.s)) throw JerboaCodeError(e.offset, fmt::format("@ebd<{}>: the modeler declares no embedding '{}' (embeddings: {})", e.s, e.s, embedding_names()));
      expect(">", "to close @ebd<...>");
      return "@ebd:" + e.s;
    }
    const Token t = take();
    if (t.kind != Token::ident) throw JerboaCodeError(t.offset, fmt::format("not Java: expected a type, found {}", shown(t)));
    std::string name = t.s;
    while (at(".") && peek(1).kind == Token::ident) {
      take();
      name += "." + take().s;
    }
    if (at("<")) {
      take();
      while (!at(">")) {
        if (at_end()) throw JerboaCodeError(peek().offset, "not Java: a type's '<' is never closed");
        const std::string a = type_text();
        if (args) args->push_back(a);
        if (at(",")) take();
        else if (!at(">")) throw JerboaCodeError(peek().offset, fmt::format("not Java: expected ',' or '>' in a type, found {}", shown(peek())));
      }
      take();
    }
    if (at("[") && at("]", 1)) throw Opaque{t.offset, fmt::format("declares an array ({}[])", name)};
    return name;
  }
  Declared declared(const std::string& name, const std::vector<std::string>& args, std::size_t offset) {
    const std::string n = last_component(name);
    if (n == "var") return {Sym::value, ValueType::real, true, true};
    if (n == "JerboaDart") return {Sym::node, ValueType::real, false, true};
    if (n == "JerboaDarts") return {Sym::darts, ValueType::real, false, true};
    if (n == "JerboaList" || n == "List" || n == "ArrayList" || n == "Collection" || n == "LinkedList") {
      if (args.size() == 1 && last_component(args[0]) == "JerboaDart") return {Sym::darts, ValueType::real, false, true};
      if (args.size() == 1)
        if (const auto t = value_class(args[0])) return {Sym::list, *t, false, true};
      if (args.empty()) return {Sym::list, ValueType::real, false, false};
      throw Opaque{offset, fmt::format("declares a list of {}", fmt::join(args, ", "))};
    }
    if (const auto t = value_class(name)) return {Sym::value, *t, false, true};
    throw Opaque{offset, fmt::format("declares a variable of type {}", name)};
  }
  bool starts_declaration() const {
    if (at("@")) return true;
    if (peek().kind != Token::ident) return false;
    if (at_ident("final")) return true;
    static const char* const primitive[] = {"int", "long", "short", "float", "double", "boolean", "var"};
    for (const char* p : primitive)
      if (at_ident(p)) return true;
    // Type name, then a name or a generic argument list.
    std::size_t k = 1;
    while (at(".", k) && peek(k + 1).kind == Token::ident) k += 2;
    return peek(k).kind == Token::ident || at("<", k);
  }

  // --- Statements ----------------------------------------------------------

  void statement(bool top) {
    const Token& t = peek();
    if (at("{")) {
      take();
      vars_.emplace_back();
      while (!at("}")) statement(false);
      take();
      vars_.pop_back();
      return;
    }
    if (at(";")) {
      take();
      return;
    }
    if (t.kind == Token::ident) {
      if (t.s == "return") return return_statement(top);
      if (t.s == "for") return for_statement();
      static const char* const control[] = {"if", "else", "while", "do", "switch", "try", "throw", "break", "continue", "synchronized", "assert", "case"};
      for (const char* c : control)
        if (t.s == c) throw Opaque{t.offset, fmt::format("uses '{}'", c)};
      if (starts_declaration()) return declaration();
      if (peek(1).kind == Token::punct && (peek(1).s == "=" || peek(1).s == "+=" || peek(1).s == "-=" || peek(1).s == "*=" || peek(1).s == "/="))
        return assignment();
    }
    const Sym s = expression();
    if (s.kind != Sym::none) throw Opaque{t.offset, "has an expression statement whose value is dropped"};
    expect(";", "after a statement");
  }

  void return_statement(bool top) {
    const Token r = take();
    if (!top || vars_.size() > 1) throw Opaque{r.offset, "returns from inside a block or loop"};
    result_ = expression();
    if (result_.kind != Sym::value) throw Opaque{r.offset, "returns something other than a value"};
    expect(";", "after the returned expression");
    returned_ = true;
  }

  void declaration() {
    if (at_ident("final")) take();
    const Token first = peek();
    std::vector<std::string> args;
    const std::string type = type_text(&args);
    const Declared d = declared(type, args, first.offset);
    for (;;) {
      const Token name = take();
      if (name.kind != Token::ident) throw JerboaCodeError(name.offset, fmt::format("not Java: expected a variable name after {}, found {}", type, shown(name)));
      if (find(name.s)) throw JerboaCodeError(name.offset, fmt::format("variable '{}' is already declared", name.s));
      Sym value;
      if (at("=")) {
        take();
        value = expression();
        value = converted(value, d, name);
      } else if (d.kind == Sym::list) {
        value.kind = Sym::list;  // Jerboa's editor starts a declared list empty
        value.type = d.type;
        value.typed = d.typed;
      }
      vars_.back()[name.s] = Var{value, name.offset};
      if (!at(",")) break;
      take();
    }
    expect(";", "after a declaration");
  }

  // A value given to a variable of declared type d.
  Sym converted(Sym v, const Declared& d, const Token& name) {
    if (d.inferred) return v;
    if (v.kind != d.kind) throw Opaque{name.offset, fmt::format("assigns to '{}' a value of another kind than its type", name.s)};
    if (d.kind == Sym::value) {
      if (d.type == ValueType::real && v.type == ValueType::integer) {  // Java's widening
        v.term = make_call("real", {std::move(v.term)}, v.term.offset);
        v.type = ValueType::real;
      }
      if (d.type != v.type) throw Opaque{name.offset, fmt::format("assigns a {} to '{}', a {}", name_of(v.type), name.s, name_of(d.type))};
    }
    if (d.kind == Sym::list && d.typed && v.typed && v.type != d.type) throw Opaque{name.offset, fmt::format("assigns a list of another type to '{}'", name.s)};
    return v;
  }

  void assignment() {
    const Token name = take();
    const Token op = take();
    Var* v = find(name.s);
    if (!v) {
      if (scope_.parameters.count(name.s)) throw Opaque{name.offset, fmt::format("assigns to the rule parameter '{}'", name.s)};
      throw JerboaCodeError(name.offset, fmt::format("'{}' is not a declared variable", name.s));
    }
    Sym value = expression();
    if (op.s != "=") {
      if (v->sym.kind != Sym::value || !scalar(v->sym.type) || value.kind != Sym::value || !scalar(value.type))
        throw Opaque{op.offset, fmt::format("uses '{}' on something other than numbers", op.s)};
      value.term = make_call(op.s.substr(0, 1), {v->sym.term, std::move(value.term)}, op.offset);
      value.type = v->sym.type == ValueType::real || value.type == ValueType::real ? ValueType::real : ValueType::integer;
    }
    const Declared d{v->sym.kind, v->sym.type, v->sym.kind == Sym::none, v->sym.typed};
    v->sym = converted(std::move(value), d, name);
    expect(";", "after an assignment");
  }

  // for (JerboaDart x : <o>(n)) body: the body once, with x a dart variable;
  // what it does to outer variables becomes each terms over the orbit.
  void for_statement() {
    const Token f = take();
    expect("(", "after 'for'");
    if (!(starts_declaration())) throw Opaque{f.offset, "uses a for loop that is not over an orbit's darts"};
    if (at_ident("final")) take();
    std::vector<std::string> args;
    const std::string type = type_text(&args);
    const Token x = take();
    if (x.kind != Token::ident || !at(":")) throw Opaque{f.offset, "uses a counted for loop"};
    take();
    const Sym over = expression();
    expect(")", "to close the for loop's header");
    if (over.kind != Sym::darts) throw Opaque{f.offset, "loops over a list, not over an orbit's darts"};
    if (last_component(type) != "JerboaDart") throw Opaque{f.offset, fmt::format("loops with a variable of type {}", type)};
    if (find(x.s) || std::find(scope_.nodes.begin(), scope_.nodes.end(), x.s) != scope_.nodes.end())
      throw JerboaCodeError(x.offset, fmt::format("variable '{}' is already declared", x.s));

    // Outer values become markers: what the body makes of them is read back.
    struct Saved {
      std::string name;
      Var* var;
      Sym before;
    };
    std::vector<Saved> saved;
    for (auto& s : vars_)
      for (auto& [n, v] : s) {
        saved.push_back({n, &v, v.sym});
        if (v.sym.kind == Sym::value) v.sym.term = make_variable(marker + n, v.sym.term.offset);
      }
    vars_.emplace_back();
    Sym bound;
    bound.kind = Sym::node;
    bound.term = make_variable(x.s, x.offset);
    vars_.back()[x.s] = Var{bound, x.offset};
    const bool returned = returned_;
    statement(false);
    if (returned_ != returned) throw Opaque{f.offset, "returns from inside a loop"};
    vars_.pop_back();

    auto each_of = [&](Term body) {
      Term e;
      e.kind = Term::Kind::each;
      e.name = x.s;
      e.offset = f.offset;
      e.orbit = over.orbit;
      e.sub_orbit = over.sub;
      e.per_sub = over.per_sub;
      e.args.push_back(over.term);
      e.args.push_back(std::move(body));
      return e;
    };
    // Markers of the values the loop leaves unchanged stand for their value.
    std::vector<std::pair<std::string, Term>> unchanged;
    for (const Saved& s : saved)
      if (s.before.kind == Sym::value && s.var->sym.kind == Sym::value && s.var->sym.term.kind == Term::Kind::variable &&
          s.var->sym.term.name == marker + s.name)
        unchanged.emplace_back(marker + s.name, s.before.term);
    auto resolved = [&](Term t, const std::string& what) {
      for (const auto& [m, by] : unchanged) substitute(t, m, by);
      if (mentions_marker(t)) throw Opaque{f.offset, fmt::format("reads, in {}, a value the loop itself accumulates", what)};
      return t;
    };
    for (Saved& s : saved) {
      Sym& now = s.var->sym;
      switch (s.before.kind) {
        case Sym::value: {
          if (now.kind == Sym::value && now.term.kind == Term::Kind::variable && now.term.name == marker + s.name) {
            now = s.before;
            break;
          }
          // An accumulation: v = v.addn(e) or v = v + e, e free of v.
          const bool accumulates = now.kind == Sym::value && now.term.kind == Term::Kind::call && now.term.args.size() == 2 &&
                                   (now.term.name == "addn" || now.term.name == "+") && now.term.args[0].kind == Term::Kind::variable &&
                                   now.term.args[0].name == marker + s.name;
          if (!accumulates)
            throw Opaque{f.offset, mentions_marker(now.term)
                                       ? fmt::format("updates '{}' in its loop other than by an accumulation ({} = {}.addn(...) or += ...)", s.name, s.name, s.name)
                                       : fmt::format("assigns '{}' in its loop: its value would be the last iteration's", s.name)};
          Term step = resolved(now.term.args[1], fmt::format("the sum into '{}'", s.name));
          const std::string op = now.term.name;
          Term sum = make_call("sum", {each_of(std::move(step))}, f.offset);
          now.term = make_call(op, {s.before.term, std::move(sum)}, f.offset);
          now.type = s.before.type;
          break;
        }
        case Sym::list: {
          if (now.kind != Sym::list || now.parts.size() < s.before.parts.size())
            throw Opaque{f.offset, fmt::format("changes the list '{}' in its loop other than by add", s.name)};
          std::vector<Term> parts(now.parts.begin(), now.parts.begin() + static_cast<std::ptrdiff_t>(s.before.parts.size()));
          for (std::size_t k = s.before.parts.size(); k < now.parts.size(); ++k)
            parts.push_back(each_of(resolved(now.parts[k], fmt::format("an element added to '{}'", s.name))));
          now.parts = std::move(parts);
          break;
        }
        case Sym::none:
          if (now.kind != Sym::none) throw Opaque{f.offset, fmt::format("assigns '{}' in its loop: its value would be the last iteration's", s.name)};
          break;
        case Sym::node:
        case Sym::darts:
          if (now.kind != s.before.kind || !now.term.same(s.before.term) || now.orbit != s.before.orbit || now.sub != s.before.sub)
            throw Opaque{f.offset, fmt::format("assigns the dart variable '{}' in its loop", s.name)};
          break;
      }
    }
  }

  // --- Expressions ---------------------------------------------------------

  Sym expression() {
    Sym a = additive();
    static const char* const stop[] = {"<", ">", "<=", ">=", "==", "!=", "&&", "||", "?", "&", "|", "^"};
    for (const char* s : stop)
      if (at(s)) throw Opaque{peek().offset, fmt::format("uses the operator '{}'", s)};
    return a;
  }

  Sym arithmetic(const Token& op, Sym a, Sym b) {
    if (a.kind != Sym::value || b.kind != Sym::value || !scalar(a.type) || !scalar(b.type))
      throw Opaque{op.offset, fmt::format("uses '{}' on something other than numbers (Vec3 has addn, mul, div)", op.s)};
    if (op.s == "%") throw Opaque{op.offset, "uses the operator '%'"};
    Sym r;
    r.kind = Sym::value;
    r.type = a.type == ValueType::real || b.type == ValueType::real ? ValueType::real : ValueType::integer;
    r.term = make_call(op.s, {std::move(a.term), std::move(b.term)}, op.offset);
    return r;
  }
  Sym additive() {
    Sym a = multiplicative();
    while (at("+") || at("-")) {
      const Token op = take();
      a = arithmetic(op, std::move(a), multiplicative());
    }
    return a;
  }
  Sym multiplicative() {
    Sym a = unary();
    while (at("*") || at("/") || at("%")) {
      const Token op = take();
      a = arithmetic(op, std::move(a), unary());
    }
    return a;
  }
  Sym unary() {
    if (at("-") || at("+")) {
      const Token op = take();
      Sym a = unary();
      if (a.kind != Sym::value || !scalar(a.type)) throw Opaque{op.offset, fmt::format("uses unary '{}' on something other than a number", op.s)};
      if (op.s == "-") a.term = make_call("-", {std::move(a.term)}, op.offset);  // as the term language writes -x
      return a;
    }
    if (at("!") || at("~") || at("++") || at("--")) throw Opaque{peek().offset, fmt::format("uses the operator '{}'", peek().s)};
    // A cast to a number type.
    if (at("(") && peek(1).kind == Token::ident && at(")", 2)) {
      const std::string& t = peek(1).s;
      if (t == "float" || t == "double" || t == "int" || t == "long") {
        const Token c = take();
        take();
        take();
        Sym a = unary();
        if (a.kind != Sym::value || !scalar(a.type)) throw Opaque{c.offset, fmt::format("casts something other than a number to {}", t)};
        if ((t == "int" || t == "long") && a.type == ValueType::real) throw Opaque{c.offset, "casts a real to an integer (truncation)"};
        if ((t == "float" || t == "double") && a.type == ValueType::integer) {
          a.term = make_call("real", {std::move(a.term)}, c.offset);
          a.type = ValueType::real;
        }
        return a;
      }
    }
    return postfix();
  }

  Sym postfix() {
    std::string lvalue;  // the variable a mutating method changes
    Sym a = primary(&lvalue);
    for (;;) {
      if (at("@")) {
        const Token at_sign = take();
        const Token d = take();
        if (a.kind != Sym::node) throw Opaque{at_sign.offset, "uses '@' on something other than a node"};
        neighbour(a, d);
        lvalue.clear();
        continue;
      }
      if (!at(".")) return a;
      take();
      const Token m = take();
      if (m.kind != Token::ident) throw JerboaCodeError(m.offset, fmt::format("not Java: expected a name after '.', found {}", shown(m)));
      if (!at("(")) {
        a = field(std::move(a), m);
        lvalue.clear();
        continue;
      }
      take();
      std::vector<Sym> args = arguments(m.s);
      a = method(std::move(a), m, std::move(args), lvalue);
      lvalue.clear();
    }
  }

  // A call's arguments, after its '(' and up to its ')'.
  std::vector<Sym> arguments(const std::string& of) {
    std::vector<Sym> args;
    while (!at(")")) {
      args.push_back(expression());
      if (at(","))
        take();
      else if (!at(")"))
        throw JerboaCodeError(peek().offset, fmt::format("not Java: expected ',' or ')' in the arguments of {}, found {}", of, shown(peek())));
    }
    take();
    return args;
  }

  void neighbour(Sym& a, const Token& d) {
    int dim = -1;
    if (d.kind == Token::number) std::from_chars(d.s.data(), d.s.data() + d.s.size(), dim);
    if (d.kind != Token::number || dim < 0 || std::to_string(dim) != d.s) throw JerboaCodeError(d.offset, fmt::format("expected a dimension after '@', found {}", shown(d)));
    if (scope_.model && !scope_.model->contains(static_cast<Dim>(dim)))
      throw JerboaCodeError(d.offset, fmt::format("{}@{}: {} is not a dimension of the model {}", a.term.str(), dim, dim, scope_.model->name));
    Term n;
    n.kind = Term::Kind::neighbour;
    n.dim = static_cast<Dim>(dim);
    n.offset = d.offset;
    n.args.push_back(std::move(a.term));
    a.term = std::move(n);
  }

  Sym field(Sym a, const Token& m) {
    if (a.kind == Sym::node) {
      const EmbeddingSignature* e = embedding(m.s);
      if (!e) throw JerboaCodeError(m.offset, fmt::format("{}.{}: the modeler declares no embedding '{}' (embeddings: {})", a.term.str(), m.s, m.s, embedding_names()));
      Sym r;
      r.kind = Sym::value;
      r.type = e->type;
      Term t;
      t.kind = Term::Kind::access;
      t.name = m.s;
      t.offset = m.offset;
      t.args.push_back(std::move(a.term));
      r.term = std::move(t);
      return r;
    }
    throw Opaque{m.offset, fmt::format("reads the field '{}'", m.s)};
  }

  Sym value_of(Term t, ValueType type) {
    Sym r;
    r.kind = Sym::value;
    r.type = type;
    r.term = std::move(t);
    return r;
  }
  static std::string class_of(ValueType t) { return t == ValueType::color ? "Color" : t == ValueType::vector3 ? "Normal3" : "Vec3"; }
  const Sym& number_arg(const std::vector<Sym>& args, std::size_t k, const Token& m) {
    if (args[k].kind != Sym::value || !scalar(args[k].type)) throw Opaque{m.offset, fmt::format("calls {} with an argument that is not a number", m.s)};
    return args[k];
  }
  const Sym& same_arg(const std::vector<Sym>& args, std::size_t k, ValueType t, const Token& m) {
    if (args[k].kind != Sym::value || args[k].type != t) throw Opaque{m.offset, fmt::format("calls {} with an argument that is not a {}", m.s, class_of(t))};
    return args[k];
  }

  Sym method(Sym a, const Token& m, std::vector<Sym> args, const std::string& lvalue) {
    const std::size_t o = m.offset;
    switch (a.kind) {
      case Sym::node:
        if (m.s == "alpha" && args.size() == 1 && args[0].kind == Sym::value && args[0].term.kind == Term::Kind::literal && args[0].type == ValueType::integer) {
          Token d{Token::number, std::to_string(args[0].term.literal.i), m.offset};
          neighbour(a, d);
          return a;
        }
        throw Opaque{o, fmt::format("calls JerboaDart.{}", m.s)};
      case Sym::value:
        if (geometric(a.type)) {
          const ValueType t = a.type;
          if (m.s == "addn" && args.size() == 1) return value_of(make_call("addn", {a.term, same_arg(args, 0, t, m).term}, o), t);
          if (m.s == "addn" && args.size() == 3)
            return value_of(make_call("addn", {a.term, number_arg(args, 0, m).term, number_arg(args, 1, m).term, number_arg(args, 2, m).term}, o), t);
          if ((m.s == "mul" || m.s == "div") && args.size() == 1 && args[0].kind == Sym::value && scalar(args[0].type))
            return value_of(make_call(m.s, {a.term, args[0].term}, o), t);
          if ((m.s == "x" || m.s == "y" || m.s == "z") && args.empty()) return value_of(make_call(m.s, {a.term}, o), ValueType::real);
          if (m.s == "barycenter" && args.size() == 1) {
            if (lvalue.empty()) throw Opaque{o, "calls barycenter on a value that is not a variable"};
            Var* v = find(lvalue);
            v->sym = value_of(make_call("barycenter", {bag(args[0], t, m)}, o), t);
            return {};
          }
          throw Opaque{o, fmt::format("calls {}.{}", class_of(t), m.s)};
        }
        throw Opaque{o, fmt::format("calls {}.{}", name_of(a.type), m.s)};
      case Sym::list:
        if (m.s == "add" && args.size() == 1) {
          if (lvalue.empty()) throw Opaque{o, "adds to a list that is not a variable"};
          if (args[0].kind != Sym::value || args[0].term.kind == Term::Kind::collect) throw Opaque{o, "adds something other than a value to a list"};
          Var* v = find(lvalue);
          if (v->sym.typed && args[0].type != v->sym.type)
            throw Opaque{o, fmt::format("adds a {} to a list of {}", name_of(args[0].type), name_of(v->sym.type))};
          v->sym.type = args[0].type;
          v->sym.typed = true;
          v->sym.parts.push_back(args[0].term);
          return {};
        }
        if (m.s == "size" && args.empty()) {
          if (a.parts.empty()) return value_of(make_literal(Value::integer(0), o), ValueType::integer);
          return value_of(make_call("count", {bag(a, a.type, m)}, o), ValueType::integer);
        }
        throw Opaque{o, fmt::format("calls List.{}", m.s)};
      case Sym::darts:
        if (m.s == "size" && args.empty()) {
          // count(each(d in <o>(n): 0)): one element per dart or sub-orbit.
          Term e;
          e.kind = Term::Kind::each;
          e.name = "d";
          while (find(e.name) || std::find(scope_.nodes.begin(), scope_.nodes.end(), e.name) != scope_.nodes.end() || scope_.parameters.count(e.name)) e.name += "_";
          e.orbit = a.orbit;
          e.sub_orbit = a.sub;
          e.per_sub = a.per_sub;
          e.offset = o;
          e.args.push_back(a.term);
          e.args.push_back(make_literal(Value::integer(0), o));
          return value_of(make_call("count", {std::move(e)}, o), ValueType::integer);
        }
        throw Opaque{o, fmt::format("calls JerboaDarts.{}", m.s)};
      case Sym::none:
        break;
    }
    throw Opaque{o, fmt::format("calls {} on nothing", m.s)};
  }

  // A multiset term of element type t: a collect, a list, each terms.
  Term bag(const Sym& s, ValueType t, const Token& m) {
    if (s.kind == Sym::value && s.term.kind == Term::Kind::collect) {
      if (s.type != t) throw Opaque{m.offset, fmt::format("calls {} on values of another type", m.s)};
      return s.term;
    }
    if (s.kind != Sym::list) throw Opaque{m.offset, fmt::format("calls {} on something other than a list or a collect", m.s)};
    if (s.parts.empty()) throw Opaque{m.offset, fmt::format("calls {} on a list that is always empty", m.s)};
    if (s.typed && s.type != t) throw Opaque{m.offset, fmt::format("calls {} on a list of {}", m.s, name_of(s.type))};
    if (s.parts.size() == 1 && s.parts[0].kind == Term::Kind::each) return s.parts[0];
    Term l;
    l.kind = Term::Kind::list;
    l.offset = m.offset;
    l.args = s.parts;
    return l;
  }

  std::vector<Dim> dims() {
    expect("<", "to open an orbit type");
    std::vector<Dim> out;
    while (!at(">")) {
      const Token d = take();
      int v = -1;
      if (d.kind == Token::number) std::from_chars(d.s.data(), d.s.data() + d.s.size(), v);
      if (d.kind != Token::number || v < 0 || std::to_string(v) != d.s)
        throw JerboaCodeError(d.offset, fmt::format("expected a dimension or '>' in an orbit type, found {}", shown(d)));
      if (scope_.model && !scope_.model->contains(static_cast<Dim>(v)))
        throw JerboaCodeError(d.offset, fmt::format("orbit type: {} is not a dimension of the model {}", v, scope_.model->name));
      out.push_back(static_cast<Dim>(v));
      if (at(",")) take();
    }
    take();
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  Term node_argument(const char* what) {
    expect("(", fmt::format("after {}", what).c_str());
    Sym n = expression();
    if (n.kind != Sym::node) throw Opaque{n.term.offset, fmt::format("applies {} to something other than a node", what)};
    expect(")", fmt::format("to close {}", what).c_str());
    return n.term;
  }

  // <o>_pi(n), <o>(n), <o>_<s>(n).
  Sym orbit_expression() {
    const std::size_t o = peek().offset;
    Sym r;
    r.orbit = dims();
    if (peek().kind == Token::ident && peek().s.size() > 1 && peek().s[0] == '_') {
      const Token e = take();
      const std::string name = e.s.substr(1);
      const EmbeddingSignature* sig = embedding(name);
      if (!sig) throw JerboaCodeError(e.offset + 1, fmt::format("<...>_{}: the modeler declares no embedding '{}' (embeddings: {})", name, name, embedding_names()));
      Term c;
      c.kind = Term::Kind::collect;
      c.name = name;
      c.orbit = r.orbit;
      c.offset = o;
      c.args.push_back(node_argument("a collect"));
      r.kind = Sym::value;  // a multiset, used by barycenter or a list
      r.type = sig->type;
      r.term = std::move(c);
      return r;
    }
    if (at_ident("_")) {
      take();
      r.sub = dims();
      r.per_sub = true;
    }
    r.kind = Sym::darts;
    r.term = node_argument("an orbit");
    return r;
  }

  Sym primary(std::string* lvalue) {
    const Token t = peek();
    if (at("<")) return orbit_expression();
    if (at("(")) {
      take();
      Sym a = expression();
      expect(")", "to close '('");
      return a;
    }
    take();
    switch (t.kind) {
      case Token::number:
        return number(t);
      case Token::text:
        throw Opaque{t.offset, "uses a string or character literal"};
      case Token::end:
        throw JerboaCodeError(t.offset, "not Java: the expression ends where a value is expected");
      case Token::punct:
        throw JerboaCodeError(t.offset, fmt::format("not Java: expected a value, found '{}'", t.s));
      case Token::ident:
        break;
    }
    if (t.s == "true" || t.s == "false") return value_of(make_literal(Value::boolean(t.s == "true"), t.offset), ValueType::boolean);
    if (t.s == "null") throw Opaque{t.offset, "uses null"};
    if (t.s == "new") return construction(t);
    if (t.s == "this" || t.s == "gmap" || t.s == "modeler" || t.s == "rule" || t.s == "leftPattern" || t.s == "curleftPattern" || t.s == "rulenode" || t.s == "super")
      throw Opaque{t.offset, fmt::format("reads Jerboa's runtime object '{}'", t.s)};
    if (Var* v = find(t.s)) {
      if (v->sym.kind == Sym::none) throw JerboaCodeError(t.offset, fmt::format("'{}' is read before it is assigned", t.s));
      *lvalue = t.s;
      return v->sym;
    }
    if (const auto p = scope_.parameters.find(t.s); p != scope_.parameters.end()) return value_of(make_variable(t.s, t.offset), p->second.type);
    if (std::find(scope_.nodes.begin(), scope_.nodes.end(), t.s) != scope_.nodes.end()) {
      Sym n;
      n.kind = Sym::node;
      n.term = make_variable(t.s, t.offset);
      return n;
    }
    // A class: a static call.
    if (std::isupper(static_cast<unsigned char>(t.s[0])) && at(".")) {
      std::string cls = t.s;
      while (at(".") && peek(1).kind == Token::ident && at("(", 2) == false && std::isupper(static_cast<unsigned char>(peek(1).s[0]))) {
        take();
        cls = take().s;
      }
      if (!at(".") || peek(1).kind != Token::ident) throw Opaque{t.offset, fmt::format("reads the class {}", cls)};
      take();
      const Token m = take();
      if (!at("(")) throw Opaque{t.offset, fmt::format("reads {}.{}", cls, m.s)};
      take();
      std::vector<Sym> args = arguments(m.s);
      return static_call(cls, m, args);
    }
    if (std::isupper(static_cast<unsigned char>(t.s[0])) || at(".")) throw Opaque{t.offset, fmt::format("reads {}", t.s)};
    if (std::find(scope_.opaque_parameters.begin(), scope_.opaque_parameters.end(), t.s) != scope_.opaque_parameters.end())
      throw Opaque{t.offset, fmt::format("reads the parameter '{}', whose type or value dartcheck does not read", t.s)};
    if (at("(")) throw Opaque{t.offset, fmt::format("calls {}, a method of the rule", t.s)};
    throw JerboaCodeError(t.offset, fmt::format("'{}' is neither a variable, a node of the left side ({}) nor a parameter of the rule", t.s,
                                                scope_.nodes.empty() ? "none" : fmt::format("{}", fmt::join(scope_.nodes, ", "))));
  }

  Sym static_call(const std::string& cls, const Token& m, const std::vector<Sym>& args) {
    const auto t = jerboa_value_type(cls);
    if (t && geometric(*t)) {
      if (m.s == "mid" && args.size() == 2) return value_of(make_call("mid", {same_arg(args, 0, *t, m).term, same_arg(args, 1, *t, m).term}, m.offset), *t);
      if (m.s == "segmentABByWeight" && args.size() == 3)
        return value_of(make_call("segment", {same_arg(args, 0, *t, m).term, same_arg(args, 1, *t, m).term, number_arg(args, 2, m).term}, m.offset), *t);
    }
    throw Opaque{m.offset, fmt::format("calls {}.{}", cls, m.s)};
  }

  Sym construction(const Token& kw) {
    const Token c = peek();
    std::vector<std::string> targs;
    const std::string type = type_text(&targs);
    expect("(", fmt::format("after new {}", type).c_str());
    std::vector<Sym> args = arguments("new " + type);
    if (at("{")) throw Opaque{kw.offset, "declares an anonymous class"};
    const std::string n = last_component(type);
    if (n == "ArrayList" || n == "JerboaList" || n == "LinkedList") {
      if (!args.empty()) throw Opaque{kw.offset, fmt::format("builds a {} from another collection", n)};
      Sym l;
      l.kind = Sym::list;
      if (targs.size() == 1)
        if (const auto t = value_class(targs[0])) {
          l.type = *t;
          l.typed = true;
        }
      return l;
    }
    const auto t = jerboa_value_type(type);
    if (!t || !geometric(*t)) throw Opaque{c.offset, fmt::format("builds a {}", type)};
    if (args.empty()) {  // the zero vector, as the constructor call (its text reads back)
      std::vector<Term> zero;
      for (int k = 0; k < 3; ++k) zero.push_back(make_literal(Value::real(0), kw.offset));
      return value_of(make_call(std::string(name_of(*t)), std::move(zero), kw.offset), *t);
    }
    if (args.size() == 1 && args[0].kind == Sym::value && args[0].type == *t) return args[0];  // a copy
    if (args.size() == 3 || (args.size() == 4 && *t == ValueType::color)) {
      if (args.size() == 4) throw Opaque{kw.offset, "builds a color with an alpha channel (dartcheck's colors have three components)"};
      std::vector<Term> xs;
      for (std::size_t k = 0; k < 3; ++k) xs.push_back(number_arg(args, k, c).term);
      return value_of(make_call(std::string(name_of(*t)), std::move(xs), kw.offset), *t);
    }
    throw Opaque{kw.offset, fmt::format("builds a {} from {} argument(s)", type, args.size())};
  }

  Sym number(const Token& t) {
    std::string s;
    for (char c : t.s)
      if (c != '_') s += c;  // 1_000
    if (s.size() > 2 && s[0] == '0' && std::string_view("xXbB").find(s[1]) != std::string_view::npos) {
      if (s.back() == 'l' || s.back() == 'L') s.pop_back();
      const int base = s[1] == 'x' || s[1] == 'X' ? 16 : 2;
      std::uint64_t v = 0;
      const auto r = std::from_chars(s.data() + 2, s.data() + s.size(), v, base);
      if (r.ec != std::errc{} || r.ptr != s.data() + s.size()) throw JerboaCodeError(t.offset, fmt::format("not Java: '{}' is not a number", t.s));
      return value_of(make_literal(Value::integer(static_cast<std::int64_t>(v)), t.offset), ValueType::integer);
    }
    const char suffix = s.empty() ? ' ' : s.back();
    const bool is_float = suffix == 'f' || suffix == 'F';
    if (std::string_view("fFdDlL").find(suffix) != std::string_view::npos) s.pop_back();
    const bool real = is_float || suffix == 'd' || suffix == 'D' || s.find_first_of(".eE") != std::string::npos;
    if (real) {
      double v = std::strtod(s.c_str(), nullptr);
      if (is_float) v = static_cast<double>(static_cast<float>(v));  // Java's float literal, widened
      return value_of(make_literal(Value::real(v), t.offset), ValueType::real);
    }
    // A leading 0 makes an octal literal in Java (0775 is 509; 079 is no number).
    const int base = s.size() > 1 && s[0] == '0' ? 8 : 10;
    std::int64_t v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v, base);
    if (r.ec != std::errc{} || r.ptr != s.data() + s.size())
      throw JerboaCodeError(t.offset, fmt::format("not Java: '{}' is not a{} number", t.s, base == 8 ? "n octal" : ""));
    return value_of(make_literal(Value::integer(v), t.offset), ValueType::integer);
  }

  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  const JerboaScope& scope_;
  std::deque<std::map<std::string, Var>> vars_;  // a deque: pointers to variables outlive a new scope
  Sym result_;
  bool returned_ = false;
};

}  // namespace

std::optional<ValueType> jerboa_value_type(const std::string& java_type) {
  const std::string n = last_component(java_type);
  if (n == "Vec3" || n == "Point3" || n == "Point3D" || n == "Vec3D") return ValueType::point3;
  if (n == "Normal3" || n == "Vector3" || n == "Vector3D") return ValueType::vector3;
  if (n == "Color" || n == "Color3" || n == "Color4") return ValueType::color;
  if (n == "Boolean" || n == "boolean") return ValueType::boolean;
  if (n == "Float" || n == "Double" || n == "float" || n == "double") return ValueType::real;
  if (n == "Integer" || n == "Long" || n == "int" || n == "long") return ValueType::integer;
  if (n == "String") return ValueType::string;
  return std::nullopt;
}

ReadExpression read_jerboa_expression(const std::string& code, const JerboaScope& scope, ValueType result) {
  ReadExpression out;
  try {
    Reader reader(code, scope);
    Sym s = reader.body();
    Term t = std::move(s.term);
    if (result == ValueType::real && s.type == ValueType::integer) t = make_call("real", {std::move(t)}, t.offset);
    TermScope ts{scope.model, &scope.embeddings, scope.nodes, scope.parameters, nullptr};
    try {
      const Sort sort = check_term(t, ts);
      if (sort != Sort::of(result))
        return {std::nullopt, fmt::format("returns a {} where the embedding is a {}", sort.str(), name_of(result)), t.offset};
    } catch (const TermError& e) {
      return {std::nullopt, e.what(), e.offset()};
    }
    out.term = std::move(t);
  } catch (const Opaque& o) {
    out.reason = o.reason;
    out.offset = o.offset;
  }
  return out;
}

std::optional<Value> jerboa_parameter_value(const std::string& java_type, const std::string& text) {
  const auto t = jerboa_value_type(java_type);
  if (!t) return std::nullopt;
  std::string trimmed = text;
  trimmed.erase(0, trimmed.find_first_not_of(" \t\r\n"));
  trimmed.erase(trimmed.find_last_not_of(" \t\r\n;") + 1);
  if (trimmed.empty()) {
    if (*t == ValueType::string) return std::nullopt;
    return *t == ValueType::boolean ? Value::boolean(false) : *t == ValueType::integer ? Value::integer(0) : scalar(*t) ? Value::real(0) : Value::coords(*t, {0, 0, 0});
  }
  // The text as an expression of constants: `return text;` read, then
  // evaluated (it reads no node).
  JerboaScope none;
  try {
    const ReadExpression r = read_jerboa_expression("return " + trimmed + ";", none, *t);
    if (!r.term) return std::nullopt;
    // Constants only: literals and calls of literals.
    std::function<std::optional<Value>(const Term&)> eval = [&](const Term& x) -> std::optional<Value> {
      if (x.kind == Term::Kind::literal) return x.literal;
      if (x.kind != Term::Kind::call || !x.function) return std::nullopt;
      std::vector<Value> vs;
      for (const Term& a : x.args) {
        const auto v = eval(a);
        if (!v) return std::nullopt;
        vs.push_back(*v);
      }
      std::vector<Operand> ops(vs.begin(), vs.end());
      return x.function->apply(ops);
    };
    return eval(*r.term);
  } catch (const JerboaCodeError&) {
    return std::nullopt;
  }
}

}  // namespace dartcheck
