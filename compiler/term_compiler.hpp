// The embedding part of a compiled rule (issue 41, 003 Def. 10-13): the
// code around the topological rewrite that rule_compiler generates, doing
// what rewriting/embedded_rewriter.cpp (the Applier on an embedded map) does with one
// evaluation per orbit, in the same order and with the same refusals:
//
// - before the match, the embeddings the rule labels must be in the map;
// - the labeled match of L (each term of L evaluated at its darts and equal
//   to their values) and, for `extended` instantiation, Lemma 3 for each
//   embedding whose orbit L does not close;
// - the classes of the instantiated R (a union per arc of R in the orbit
//   and pattern position), and one source per class: a value of G that R
//   keeps (no evaluation) or the term evaluated once (Thm 4: a consistent
//   rule gives every instance of a class one value);
// - after the rewrite, the writes of 003 Def. 12: a closed class is a whole
//   orbit of H and is written without a walk; otherwise the orbit of H is
//   walked from each labeled instance.
//
// Terms become straight-line code: a node variable is a matched dart, an
// access a pool read, a collect a call of the shared collect, a function
// the call of rewriting/algebra.hpp that the interpreter's registry makes.
#pragma once

#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rewriting/operation.hpp"
#include "rewriting/pattern_graphs.hpp"

namespace dartcheck::compiler {

/// Why the terms of `op` cannot be compiled (a function with no C++ text:
/// one a modeler registered), or nullopt.
std::optional<std::string> terms_not_compilable(const Operation& op);

class TermCode {
 public:
  using Out = std::back_insert_iterator<std::string>;
  /// For an operation with terms; `facts` are its scheme facts (W's
  /// generators, whose shift tables the classes follow).
  TermCode(const Operation& op, const SchemeFacts& facts);
  ~TermCode();
  TermCode(const TermCode&) = delete;
  TermCode& operator=(const TermCode&) = delete;

  /// At the function's start: `Map& g`, the embeddings' pointers, and the
  /// refusal of a map without an embedding the rule labels.
  void lookups(Out out) const;
  /// After the match: L's labels, Lemma 3, R's classes and sources;
  /// `everywhere` for a NAME_everywhere function (positions are darts).
  void before_rewrite(Out out, bool everywhere) const;
  /// After the topological rewrite: the renumbering followed, and the
  /// labels written (`everywhere` as for before_rewrite).
  void after_rewrite(Out out, bool everywhere) const;

 private:
  // The pieces of before_rewrite and after_rewrite.
  void left_labels(Out out) const;
  void overlap_checks(Out out) const;
  void right_sources(Out out, std::size_t u, bool everywhere) const;
  void unlabel_added(Out out, bool everywhere) const;
  void write_values(Out out, std::size_t u, bool everywhere) const;

  struct Plan;
  std::unique_ptr<Plan> plan_;
};

}  // namespace dartcheck::compiler
