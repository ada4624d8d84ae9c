#include "core/conjugate_words.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/limits.hpp"

namespace dartcheck {

ConjWord ConjWord::of_dims(const std::vector<Dim>& dims) {
  ConjWord w;
  for (Dim d : dims) w.push(d, false);
  return w;
}

std::string ConjWord::str() const {
  if (empty()) return "ε";
  std::string s;
  for (std::size_t k = 0; k < size(); ++k) {
    if (bar(k)) s += '~';
    s += std::to_string(dim(k));
  }
  return s;
}

ConjWord parse_conj_word(std::string_view text, const Model& model) {
  ConjWord w;
  if (text.empty() || text == "ε" || text == "e") return w;
  bool pending_bar = false;
  std::size_t k = 0;
  auto fail = [&](std::size_t at, const std::string& what) { throw ValueError(fmt::format("word '{}', character {}: {}", text, at + 1, what)); };
  if (text.size() > limits().word_length) throw ValueError(over_limit("a word's length", text.size(), limits().word_length, "--limit-word-length"));
  while (k < text.size()) {
    const char c = text[k];
    if (c == '~') {
      if (pending_bar) fail(k, "two '~' in a row");
      pending_bar = true;
      ++k;
      continue;
    }
    // U+0304 COMBINING MACRON (0xCC 0x84) after a digit: the paper's overbar.
    if (static_cast<unsigned char>(c) == 0xCC && k + 1 < text.size() && static_cast<unsigned char>(text[k + 1]) == 0x84) {
      if (w.empty()) fail(k, "an overbar must follow a dimension");
      const Dim d = w.dim(w.size() - 1);
      ConjWord shorter = ConjWord::from_code(w.code().substr(0, w.size() - 1));
      shorter.push(d, true);
      w = std::move(shorter);
      k += 2;
      continue;
    }
    if (c < '0' || c > '9') fail(k, "expected a dimension digit, '~' or an overbar");
    const Dim d = c - '0';
    if (!model.contains(d)) fail(k, fmt::format("{} is not a dimension of {}", d, model.name));
    w.push(d, pending_bar);
    pending_bar = false;
    ++k;
  }
  if (pending_bar) fail(text.size() - 1, "'~' must precede a dimension");
  return ConjugateRewriting(model).normalize(w);
}

Dart follow(const Map& map, Dart d, const ConjWord& w) {
  for (std::size_t k = 0; k < w.size() && d != no_dart; ++k) d = w.bar(k) ? map.inverse_link(w.dim(k), d) : map.link(w.dim(k), d);
  return d;
}

ConjugateRewriting::ConjugateRewriting(const Model& model) : model_(model) {
  for (auto [i, j] : model.exchangeable) {
    exchangeable_[std::min(i, j)] |= dim_bit(std::max(i, j));
    confluent_ = confluent_ && !(model.is_oriented(i) && model.is_oriented(j));
  }
}

ConjWord ConjugateRewriting::normalize(ConjWord w) const {
  std::string code = w.code();
  for (char& c : code)
    if (!model_.is_oriented(static_cast<unsigned char>(c) >> 1)) c = static_cast<char>(c & ~1);
  return ConjWord::from_code(std::move(code));
}

// The conjugate of a letter: flip the bar of an oriented dimension.
static char conj_letter(const Model& m, char x) { return m.is_oriented(static_cast<unsigned char>(x) >> 1) ? static_cast<char>(x ^ 1) : x; }

ConjWord ConjugateRewriting::conjugate(const ConjWord& w) const {
  std::string code(w.code().rbegin(), w.code().rend());
  for (char& c : code) c = conj_letter(model_, c);
  return ConjWord::from_code(std::move(code));
}

bool ConjugateRewriting::cancels(char x, char y) const { return conj_letter(model_, x) == y; }

bool ConjugateRewriting::swappable(char y, char x) const {
  const Dim dy = static_cast<unsigned char>(y) >> 1, dx = static_cast<unsigned char>(x) >> 1;
  if (!exchangeable(dx, dy)) return false;
  // An oriented letter and a conjugated oriented letter do not commute:
  // C(i, j) closes ijij- and īj̄īj̄-paths, not ij̄ij̄-paths.
  return !(model_.is_oriented(dx) && model_.is_oriented(dy) && ((x ^ y) & 1));
}

bool ConjugateRewriting::rewrite_at(const std::string& w, std::size_t k, std::string& child) const {
  if (cancels(w[k], w[k + 1])) {
    child = w.substr(0, k) + w.substr(k + 2);
  } else if (swappable(w[k], w[k + 1])) {
    child = w;
    child[k] = conj_letter(model_, w[k + 1]);
    child[k + 1] = conj_letter(model_, w[k]);
  } else {
    return false;
  }
  return true;
}

std::vector<ConjugateRewriting::Step> ConjugateRewriting::steps(const ConjWord& w) const {
  std::vector<Step> out;
  const std::string& c = w.code();
  std::string child;
  for (std::size_t k = 0; k + 1 < c.size(); ++k)
    if (rewrite_at(c, k, child)) out.push_back({cancels(c[k], c[k + 1]) ? Step::cancel : Step::swap, k, ConjWord::from_code(child)});
  return out;
}

bool ConjugateRewriting::irreducible(const ConjWord& w) const {
  const std::string& c = w.code();
  for (std::size_t k = 0; k + 1 < c.size(); ++k)
    if (cancels(c[k], c[k + 1]) || swappable(c[k], c[k + 1])) return false;
  return true;
}

// Every state below is the word r · c · (pending, last first), reached from
// w by rewrite steps: c enters at the end of the irreducible r and moves
// left while it swaps (each swap conjugates c and the letter it passes:
// y x -> x̄ ȳ); where it cancels, the letters it passed are taken off r
// again, since the letter now before them may rewrite with them. r stays
// irreducible (a swapped pair x̄ ȳ has increasing dimensions; conjugating
// two letters keeps a pair irreducible), so the last r is a normal form,
// and, the system being confluent, the normal form. Each cancellation
// removes two letters, so at most |w| + |w|²/2 letters enter, each moving
// at most |w| places.
std::string ConjugateRewriting::unique_normal_form(const std::string& w) const {
  std::string r;
  std::string pending(w.rbegin(), w.rend());  // the next letter last
  while (!pending.empty()) {
    r.push_back(pending.back());
    pending.pop_back();
    for (std::size_t k = r.size() - 1; k > 0; --k) {
      if (cancels(r[k - 1], r[k])) {
        pending.append(r.rbegin(), r.rend() - static_cast<std::ptrdiff_t>(k + 1));
        r.resize(k - 1);
        break;
      }
      if (!swappable(r[k - 1], r[k])) break;
      const char y = r[k - 1], x = r[k];
      r[k - 1] = conj_letter(model_, x);
      r[k] = conj_letter(model_, y);
    }
  }
  return r;
}

void ConjugateRewriting::check_budget(const std::string& w) const {
  if (nf_memo_.size() + empty_memo_.size() > limits().rewrite_words)
    throw RewriteLimit(
        fmt::format("the word {} rewrites into more than {} words in R_{{N,E}} of {}, which is not confluent (two oriented "
                    "dimensions are exchangeable): raise --limit-rewrite-words",
                    ConjWord::from_code(w).str(), limits().rewrite_words, model_.name));
}

// Normal forms of every word reachable from w, memoized per word: the
// rewriting graph of a word is a DAG (R_{N,E} terminates), so the normal
// forms of w are the union of those of its one-step rewrites.
const std::vector<std::uint32_t>& ConjugateRewriting::nf_ids(const std::string& w) {
  if (auto it = nf_memo_.find(w); it != nf_memo_.end()) return it->second;
  std::vector<std::uint32_t> ids;
  if (confluent_) {
    const std::string nf = unique_normal_form(w);
    auto [it, fresh] = intern_.try_emplace(nf, static_cast<std::uint32_t>(interned_.size()));
    if (fresh) interned_.push_back(ConjWord::from_code(nf));
    ids.push_back(it->second);
    return nf_memo_.emplace(w, std::move(ids)).first->second;
  }
  check_budget(w);
  bool reducible = false;
  std::string child;
  for (std::size_t k = 0; k + 1 < w.size(); ++k) {
    if (!rewrite_at(w, k, child)) continue;
    reducible = true;
    const auto& sub = nf_ids(child);
    ids.insert(ids.end(), sub.begin(), sub.end());
  }
  if (!reducible) {
    auto [it, fresh] = intern_.try_emplace(w, static_cast<std::uint32_t>(interned_.size()));
    if (fresh) interned_.push_back(ConjWord::from_code(w));
    ids.push_back(it->second);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return nf_memo_.emplace(w, std::move(ids)).first->second;
}

const std::vector<ConjWord>& ConjugateRewriting::normal_forms(const ConjWord& w) {
  const auto& ids = nf_ids(normalize(w).code());
  nf_result_.clear();
  for (auto id : ids) nf_result_.push_back(interned_[id]);
  std::sort(nf_result_.begin(), nf_result_.end(),
            [](const ConjWord& a, const ConjWord& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; });
  return nf_result_;
}

bool ConjugateRewriting::reaches_empty(const std::string& w) {
  if (w.empty()) return true;
  // Invariants of both rule kinds: the length's parity and, per dimension,
  // the parity of its number of letters.
  if (w.size() % 2) return false;
  DimSet odd = 0;
  for (char c : w) odd ^= dim_bit(static_cast<unsigned char>(c) >> 1);
  if (odd) return false;
  if (auto it = empty_memo_.find(w); it != empty_memo_.end()) return it->second;
  if (confluent_) return empty_memo_.emplace(w, unique_normal_form(w).empty()).first->second;
  check_budget(w);
  bool found = false;
  std::string child;
  for (std::size_t k = 0; k + 1 < w.size() && !found; ++k) {
    if (!rewrite_at(w, k, child)) continue;
    found = reaches_empty(child);
  }
  empty_memo_.emplace(w, found);
  return found;
}

bool ConjugateRewriting::reduces_to_empty(const ConjWord& w) { return reaches_empty(normalize(w).code()); }

}  // namespace dartcheck
