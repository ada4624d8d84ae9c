// Embedding terms (003 Sec. 3.4, 6.3, Def. 8): the labels of rule scheme
// nodes. A term is built from node variables (the names of L's nodes),
// the G-map operators `x.pi` (embedding access), `x.alpha_i` (neighbour)
// and `pi<o'>(x)` (collect: one pi-value per pi-orbit inside the
// <o'>-orbit of x, a multiset), rule parameters, literals and user
// functions (core/term_functions.hpp).
//
// Grammar (precedence climbing, left-associative):
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := '-' unary | postfix
//   postfix := primary ('.' name)*          name: alpha_i, alphai, or an embedding
//   primary := number | "string" | true | false | '(' sum ')'
//            | name '<' dims '>' '(' sum ')'   collect (also name_<dims>)
//            | 'each' '(' name 'in' '<' dims '>' ['_' '<' dims '>'] '(' sum ')' ':' sum ')'
//                                              dart comprehension
//            | '[' sum (',' sum)* ']'          list (a multiset)
//            | name '(' sum (',' sum)* ')'     function call
//            | name                            node variable or parameter
//
// Two extensions of 003's terms serve Jerboa's expressions (docs/
// jerboa-expressions.md says why Theorems 2 and 4 still hold):
// - `each(x in <o>(y): t)` is the multiset of t with x bound to every dart
//   of the <o>-orbit of y, and `each(x in <o>_<s>(y): t)` the multiset of
//   t once per <s>-orbit inside it (Jerboa's `<o>_<s>(y)`: one dart per
//   sub-orbit; t must give one value on every dart of a sub-orbit, or the
//   evaluation fails, since Jerboa's choice of dart is its traversal's);
// - `[t1, ..., tk]` is the multiset of its elements, an element being a
//   value or a multiset whose elements it adds (Jerboa's lists built with
//   `add`).
//
// Two terms are equal when their trees are (003 Sec. 6.1: "embedding
// labels of rule schemes will be compared via the strict syntactic
// equality of terms"); `str()` prints the canonical text of the tree.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/formatting.hpp"
#include "core/model.hpp"
#include "rewriting/value.hpp"

namespace dartcheck {

struct Function;

struct Term {
  enum class Kind : std::uint8_t { variable, parameter, literal, access, neighbour, collect, call, each, list };
  Kind kind = Kind::literal;
  std::string name;        // variable, parameter, embedding (access, collect), function, or each's bound variable
  Dim dim = 0;             // neighbour
  std::vector<Dim> orbit;  // collect, each: ascending
  std::vector<Dim> sub_orbit;  // each with per_sub: the sub-orbit type, ascending
  bool per_sub = false;    // each: one value per <sub>-orbit instead of per dart
  /// access/neighbour/collect: the node term; call, list: the arguments;
  /// each: the node term the orbit starts at, then the body.
  std::vector<Term> args;
  Value literal;           // literal; a parameter's value once resolved
  std::size_t offset = 0;  // 0-based position in the source text
  bool implicit = false;   // a conversion the checker inserted (printed as its argument)

  // Set by type checking.
  Sort sort;
  const Function* function = nullptr;

  std::string str() const;
  /// Syntactic equality: same tree (offsets and resolved data ignored).
  bool same(const Term& o) const;
  /// The node variables the term reads, sorted, without repeats.
  std::vector<std::string> variables() const;
};

/// A parse or type error at a 0-based offset of the term's text.
class TermError : public AtOffset<Error> {
 public:
  using AtOffset::AtOffset;
};

/// Parses a term; throws TermError naming the offending token.
Term parse_term(const std::string& text);

/// An embedding operation pi : <o> -> tau as the term language sees it.
struct EmbeddingSignature {
  std::string name;
  ValueType type;
  std::vector<Dim> orbit;
};

class FunctionRegistry;

/// What a term may refer to.
struct TermScope {
  const Model* model = nullptr;  // alpha_i must name one of its dimensions
  const std::vector<EmbeddingSignature>* embeddings = nullptr;
  std::vector<std::string> variables;       // node variables: L's node names
  std::map<std::string, Value> parameters;  // rule parameters
  const FunctionRegistry* functions = nullptr;
  const EmbeddingSignature* find_embedding(const std::string& name) const;
};

/// Type-checks `t` in place (sorts, overloads, parameters resolved,
/// integer-to-real conversions inserted) and returns its sort. Throws
/// TermError at the offending sub-term.
Sort check_term(Term& t, const TermScope& scope);

// fmt::format("{}", x) prints x.str() (core/formatting.hpp).
template <>
inline constexpr bool formatted_by_str<Term> = true;

}  // namespace dartcheck
