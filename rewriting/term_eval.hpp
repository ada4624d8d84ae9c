// Evaluation of embedding terms on an embedded G-map (003 Def. 9-10): the
// user algebra extended by the map. A node variable is the dart its L node
// matched; `x.pi` reads pi at x; `x.alpha_i` is x's i-neighbour; and
// `pi<o'>(x)` is the multiset of the labels of the quotient by pi of the
// <o'>-orbit of x: one value per pi-orbit of that orbit, the pi-orbits
// being taken inside it (through the dimensions of <o> ∩ <o'>).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/dart_table.hpp"
#include "rewriting/embedded_map.hpp"
#include "core/orbit.hpp"
#include "rewriting/term_functions.hpp"

namespace dartcheck {

class TermEvaluator;

/// The multiset of each(x in <o>(y): t) or each(x in <o>_<s>(y): t) from
/// its body's values on a walk `orbit` of y's <o>-orbit (`values[k]` at
/// `orbit[k]`), in place: every value, or with `per_sub` one per <s>-orbit
/// inside it (`sub`: the generators of <s> ∩ <o>, walked with `walker`),
/// each dart of a sub-orbit giving the same value or EvaluationError
/// (Jerboa takes the dart its traversal meets first); sorted by value_less.
/// `text` and `sub_dims` (<s>) name the term in the message. The evaluator
/// and compiled rules both finish an each through it.
void each_values(std::vector<Value>& values, std::span<const Dart> orbit, bool per_sub, std::span<const OrbitWord> sub, OrbitWalker& walker,
                 const std::string& text, const std::vector<Dim>& sub_dims);

/// The multiset of a collect pi<o'>(x) (003 Def. 9) from a walk `orbit` of
/// x's <o'>-orbit: one value per pi-orbit inside it (that of its smallest
/// labeled dart), each pi-orbit taken through `inner`, the generators of
/// <o> ∩ <o'> (walked with `inner_walker`), appended to `out` in a
/// canonical order (value_less), so the multiset is the same from any dart
/// of the orbit, even where G is not consistent. `done` holds one
/// bit per dart, clear before and after. Throws EvaluationError, naming
/// pi (`name`) and <o'> (`dims`), when a pi-orbit has no value. The
/// evaluator and compiled rules (rewriting/compiled_terms.hpp) both
/// collect through it.
void collect_orbit_values(const Map& map, const Embedding& e, std::span<const Dart> orbit, std::span<const OrbitWord> inner,
                          OrbitWalker& inner_walker, std::vector<std::uint64_t>& done, std::vector<Value>& out, const std::string& name,
                          const std::vector<Dim>& dims);

/// A checked term compiled for one evaluator, in postfix order: node
/// variables resolved to binding slots, embeddings to the map's embedding
/// index, collects to the evaluator's memo. Running it looks nothing up by
/// name and allocates nothing once the evaluator's stack has grown. What
/// cannot be resolved (an unbound variable, an embedding the map lacks)
/// compiles to a step that throws when run, as a tree walk would. Valid
/// while the term lives and the map's embeddings are only appended to.
class CompiledTerm {
 private:
  friend class TermEvaluator;

  struct Step {
    enum class Op : std::uint8_t { literal, access, collect, call, each, list, fail };
    Op op = Op::literal;
    std::uint32_t slot = 0;             // access, collect: binding of the node variable
    std::uint32_t first = 0, last = 0;  // access, collect: links_[first, last) followed from it
    std::uint32_t target = 0;           // embedding (access), memo (collect, each, list), argument count (call, list), message (fail)
    std::uint32_t body = 0;             // each: its body in bodies_
    const Term* term = nullptr;         // the literal, the function, the text in messages
  };
  // An each term's body, compiled with its dart variable bound last.
  struct Body {
    std::unique_ptr<CompiledTerm> program;
    std::vector<OrbitWord> outer, sub;  // generators of <o> and of <s> ∩ <o>
  };
  struct Link {
    Dim dim;
    const Term* term;  // x.alpha_i, for the message when d has no i-arc
  };
  std::vector<Step> steps_;
  std::vector<Link> links_;
  std::vector<std::string> failures_;
  std::vector<Body> bodies_;
  const Term* root_ = nullptr;
};

/// Evaluates checked terms against one map; reuses its traversal marks
/// across calls, so evaluating many terms costs the orbits they read. A
/// collect is memorised for every dart of the <o'>-orbit it walked (the
/// multiset is the same from any of them), so the copies of one term in
/// one orbit collect it once: the map must not change while the evaluator
/// is used, or forget() must be called after the change.
class TermEvaluator {
 public:
  explicit TermEvaluator(const EmbeddedMap& g);

  /// Compiles `t` with node variables `names[k]` bound to the k-th dart of
  /// the bindings it will run on (out is reused: no allocation once grown).
  void compile(const Term& t, std::span<const std::string> names, CompiledTerm& out);
  /// The value of a compiled value-sorted term on `darts`. Throws
  /// EvaluationError when a dart has no value, an alpha_i has no arc, or
  /// a function has no value.
  Value value(const CompiledTerm& c, std::span<const Dart> darts);
  /// Compiles and runs `t` once (for callers that evaluate a term once).
  Value value(const Term& t, std::span<const std::string> names, std::span<const Dart> darts);
  /// The multiset of a collect term (valid until the next collect).
  std::span<const Value> collect(const std::string& embedding, const std::vector<Dim>& orbit, Dart d);
  /// Drops the memorised collects (after a change of the map).
  void forget();
  /// Whether collects are memorised (the default). Without, each collect
  /// walks its orbit and its multiset lives until the next value() call:
  /// for a caller that evaluates one term per orbit, where a memo would be
  /// written for every dart and never read. A change forgets the memo.
  void memorise(bool on);

 private:
  // The collects of one (embedding, <o'>): bag_of[d] is the bag of every
  // dart of an <o'>-orbit already walked; bag k is elements[start[k],
  // start[k + 1]) (one array for all bags: no allocation per bag).
  struct CollectMemo {
    std::string name;
    std::size_t embedding;  // index in the map's embeddings
    std::vector<Dim> orbit;
    std::vector<OrbitWord> outer, inner;  // generators of <o'> and <o> ∩ <o'>
    DartTable bag_of;
    std::vector<Value> elements;
    std::vector<std::uint32_t> start{0};
    // Without the memo: the dart and bag of this call's last collect (a
    // term that repeats a collect reads it once).
    Dart last_dart = no_dart;
    std::uint32_t last_bag = 0;
    const Term* owner = nullptr;  // an each or list term's own bags (embedding: none)
    std::span<const Value> bag(std::uint32_t k) const { return {elements.data() + start[k], elements.data() + start[k + 1]}; }
    /// Drops the bags (the per-dart memo stays: forget() clears it).
    void empty() {
      elements.clear();
      start.resize(1);
      last_dart = no_dart;
    }
  };
  // A stack entry: a value, or the multiset bag(bag) of memo_[memo] (an
  // index: elements may grow while later arguments are evaluated).
  struct Entry {
    Value value;
    std::uint32_t memo = DartTable::none, bag = 0;
  };

  void emit(const Term& t, std::span<const std::string> names, CompiledTerm& out);
  // Runs c on darts above the stack's current top; returns its value.
  Value run(const CompiledTerm& c, std::span<const Dart> darts);
  // The multiset of an each step: its body on every dart of the orbit (or
  // once per sub-orbit), appended as a bag of memo s.target.
  std::uint32_t each_bag(const CompiledTerm& c, const CompiledTerm::Step& s, std::span<const Dart> darts);
  // A memo that only holds the bags of one each or list step.
  std::uint32_t scratch_memo(const Term& owner);
  bool emit_node(const Term& t, std::span<const std::string> names, CompiledTerm& out, CompiledTerm::Step& s);
  bool emit_start(const Term& node, std::span<const std::string> names, CompiledTerm& out, CompiledTerm::Step& s);
  Dart node(const CompiledTerm& c, const CompiledTerm::Step& s, std::span<const Dart> darts) const;
  const Embedding* embedding(const std::string& name, std::size_t* index = nullptr) const;
  std::size_t memo_for(const std::string& name, std::size_t embedding, const std::vector<Dim>& orbit);
  std::uint32_t collect_bag(CollectMemo& memo, Dart d);

  const EmbeddedMap& g_;
  OrbitWalker outer_, inner_;
  // The last orbit outer_ walked, from outer_dart_ through outer_orbit_:
  // collects of several embeddings over one orbit walk it once (the map
  // does not change between forget() calls).
  Dart outer_dart_ = no_dart;
  std::vector<Dim> outer_orbit_;
  std::span<const Dart> outer_last_;
  // One bit per dart: the darts of the collected orbit already in a
  // pi-orbit (cleared through the orbit's list after each collect).
  std::vector<std::uint64_t> done_;
  std::vector<CollectMemo> memo_;
  std::vector<Entry> stack_;
  std::vector<Operand> args_;
  CompiledTerm once_;
  bool memorise_ = true;
};

}  // namespace dartcheck
