// Words over the conjugate alphabet and the rewriting system R_{N,E}
// (002 Def. 17, Sec. 9.1-9.2, Lemma 3).
//
// A letter is a dimension d or its conjugate d̄, "follow the d-arc
// backwards". On a non-oriented dimension both directions coincide, so d̄ = d
// for d in N and only oriented letters carry a bar. The conjugate of a word
// reverses it and conjugates every letter.
//
// R_{N,E} has two kinds of rules, rebuilt from the proof of Lemma 3 (the
// extraction lost the bars):
//   cancel   x x̄ -> ε      for every letter x (x x̄ is a back-and-forth),
//   swap     y x -> x̄ ȳ    when (‖x‖, ‖y‖) ∈ E, i.e. ‖x‖ < ‖y‖, and x, y are
//                          both in N ∪ O or both in N ∪ Ō (the y x path from
//                          v closes into an yxyx-cycle, whose other half,
//                          walked backwards, is x̄ ȳ).
// A swap sorts two exchangeable letters by increasing dimension, so the
// system terminates. It is not confluent once two oriented dimensions are
// exchangeable ("321" with O = {1,2,3} has the normal forms 2̄3̄1 and 31̄2̄),
// hence normal_forms() returns all of them. Without such a pair (every
// G-map and n-O-map model: at most dimension 1 is oriented) it is
// confluent, and the one normal form is computed by pushing the letters one
// by one onto an irreducible word, in polynomial time; the general case
// walks every rewriting of the word, which grows exponentially with its
// length ((13)^12 on 3-omap: 2.7 million words), within
// limits().rewrite_words.
#pragma once

#include <compare>
#include <stdexcept>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/error.hpp"
#include "core/formatting.hpp"
#include "core/map.hpp"
#include "core/model.hpp"

namespace dartcheck {

/// A word over D̄. Letters are stored one per byte (dimension << 1 | bar),
/// which makes a word its own hash key.
class ConjWord {
 public:
  ConjWord() = default;
  /// The word of the given dimensions, no bars.
  static ConjWord of_dims(const std::vector<Dim>& dims);

  std::size_t size() const { return code_.size(); }
  bool empty() const { return code_.empty(); }
  Dim dim(std::size_t k) const { return static_cast<unsigned char>(code_[k]) >> 1; }
  bool bar(std::size_t k) const { return code_[k] & 1; }

  void push(Dim d, bool bar) { code_.push_back(static_cast<char>((d << 1) | (bar ? 1 : 0))); }
  ConjWord& operator+=(const ConjWord& w) {
    code_ += w.code_;
    return *this;
  }
  friend ConjWord operator+(ConjWord a, const ConjWord& b) { return a += b; }

  /// The letters as stored (for hashing and rewriting).
  const std::string& code() const { return code_; }
  static ConjWord from_code(std::string code) {
    ConjWord w;
    w.code_ = std::move(code);
    return w;
  }

  /// "ε", or the letters with "~" before a conjugate: "~12".
  std::string str() const;

  friend bool operator==(const ConjWord&, const ConjWord&) = default;
  friend auto operator<=>(const ConjWord& a, const ConjWord& b) { return a.code_ <=> b.code_; }

 private:
  std::string code_;
};

/// Parses a word: digits are dimensions (0-9), "~" or a combining overbar
/// (U+0304) after a digit marks a conjugate, "ε", "e" or "" is the empty
/// word. Bars on non-oriented dimensions of `model` are dropped (d̄ = d).
/// Throws ValueError naming the 1-based character position.
ConjWord parse_conj_word(std::string_view text, const Model& model);

/// Target of the w-path from d in a map, following i-arcs backwards for a
/// conjugate letter; no_dart if an arc is missing.
Dart follow(const Map& map, Dart d, const ConjWord& w);

/// A word whose rewritings in a non-confluent R_{N,E} are more than
/// limits().rewrite_words (--limit-rewrite-words).
class RewriteLimit : public Error {
 public:
  using Error::Error;
};

/// R_{N,E} for one model, with memoized normal forms.
class ConjugateRewriting {
 public:
  explicit ConjugateRewriting(const Model& model);

  const Model& model() const { return model_; }
  /// Drops the bars of non-oriented letters.
  ConjWord normalize(ConjWord w) const;
  ConjWord conjugate(const ConjWord& w) const;

  struct Step {
    enum Kind { cancel, swap } kind;
    std::size_t position;  // of the first rewritten letter
    ConjWord result;
  };
  /// Every one-step rewriting of w.
  std::vector<Step> steps(const ConjWord& w) const;
  bool irreducible(const ConjWord& w) const;

  /// All normal forms of w (the irreducible words w rewrites to), sorted.
  const std::vector<ConjWord>& normal_forms(const ConjWord& w);
  /// w ->* ε.
  bool reduces_to_empty(const ConjWord& w);
  /// w <->* w'. Decided as w·conj(w') ->* ε, which implies w <->* w'
  /// (w <- w·conj(w')·w' ->* w'); it accepts every pair whose normal forms
  /// meet (002 Algorithm 3's test) and more, e.g. "2" and "020".
  bool congruent(const ConjWord& w, const ConjWord& w2) { return reduces_to_empty(w + conjugate(w2)); }

  /// Number of words whose normal forms are memoized.
  std::size_t memo_size() const { return nf_memo_.size(); }

 private:
  bool exchangeable(Dim a, Dim b) const { return a < b && has_dim(exchangeable_[a], b); }
  bool cancels(char x, char y) const;
  bool swappable(char y, char x) const;
  /// The one-step rewriting of w at letters k, k+1 into `child`; false if
  /// no rule applies there.
  bool rewrite_at(const std::string& w, std::size_t k, std::string& child) const;
  const std::vector<std::uint32_t>& nf_ids(const std::string& w);
  bool reaches_empty(const std::string& w);

  /// The normal form when the system is confluent (`confluent_`).
  std::string unique_normal_form(const std::string& w) const;
  /// Throws RewriteLimit when the memoized words pass limits().rewrite_words.
  void check_budget(const std::string& w) const;

  Model model_;
  DimSet exchangeable_[max_dimension + 1] = {};
  bool confluent_ = true;           // no exchangeable pair of oriented dimensions
  std::vector<ConjWord> interned_;  // distinct normal forms, by id
  std::unordered_map<std::string, std::uint32_t> intern_;
  std::unordered_map<std::string, std::vector<std::uint32_t>> nf_memo_;
  std::unordered_map<std::string, bool> empty_memo_;
  std::vector<ConjWord> nf_result_;
};

// fmt::format("{}", x) prints x.str() (core/formatting.hpp).
template <>
inline constexpr bool formatted_by_str<ConjWord> = true;

}  // namespace dartcheck
