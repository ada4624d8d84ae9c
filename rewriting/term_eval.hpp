// Evaluation of embedding terms on an embedded G-map (003 Def. 9-10): the
// user algebra extended by the map. A node variable is the dart its L node
// matched; `x.pi` reads pi at x; `x.alpha_i` is x's i-neighbour; and
// `pi<o'>(x)` is the multiset of the labels of the quotient by pi of the
// <o'>-orbit of x: one value per pi-orbit of that orbit, the pi-orbits
// being taken inside it (through the dimensions of <o> ∩ <o'>).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/dart_table.hpp"
#include "rewriting/embedded_map.hpp"
#include "core/orbit.hpp"
#include "rewriting/term_functions.hpp"

namespace dartcheck {

/// Evaluates checked terms against one map; reuses its traversal marks
/// across calls, so evaluating many terms costs the orbits they read. A
/// collect is memorised for every dart of the <o'>-orbit it walked (the
/// multiset is the same from any of them), so the copies of one term in
/// one orbit collect it once: the map must not change while the evaluator
/// is used, or forget() must be called after the change.
class TermEvaluator {
 public:
  explicit TermEvaluator(const EmbeddedMap& g);

  /// The value of a value-sorted term with node variables `names[k]`
  /// bound to `darts[k]`. Throws EvaluationError when a dart has no value,
  /// an alpha_i has no arc, or a function has no value.
  Value value(const Term& t, std::span<const std::string> names, std::span<const Dart> darts);
  /// The multiset of a collect term.
  const Multiset& collect(const std::string& embedding, const std::vector<Dim>& orbit, Dart d) { return collect_memo(embedding, orbit, d); }
  /// Drops the memorised collects (after a change of the map).
  void forget();

 private:
  Operand eval(const Term& t, std::span<const std::string> names, std::span<const Dart> darts);
  Dart node(const Term& t, std::span<const std::string> names, std::span<const Dart> darts);
  const Embedding& embedding(const std::string& name) const;
  Multiset& collect_memo(const std::string& embedding, const std::vector<Dim>& orbit, Dart d);

  // The collects of one (embedding, <o'>): bag_of[d] indexes `bags` for
  // every dart of an <o'>-orbit already walked.
  struct CollectMemo {
    std::string embedding;
    std::vector<Dim> orbit;
    std::vector<Word> outer, inner;  // generators of <o'> and <o> ∩ <o'>
    DartTable bag_of;
    std::vector<Multiset> bags;
  };

  const EmbeddedMap& g_;
  OrbitWalker outer_, inner_;
  std::vector<Dart> orbit_;
  DartTable done_;
  std::vector<CollectMemo> memo_;
};

}  // namespace dartcheck
