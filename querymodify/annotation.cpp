#include "querymodify/annotation.hpp"

#include <stdexcept>

namespace dartcheck::querymodify {
namespace {

constexpr std::uint32_t unmatched = 0;
constexpr std::uint32_t empty_mark = 0xFFFFFFFF;  // annotated ∅

// The table of the header, for one letter. `mark` is the annotation of
// d_i (0: none, empty_mark: ∅, else a label); returns what to annotate d_i
// with (0: nothing), or nullopt for a violation.
std::optional<std::uint32_t> check(std::uint32_t letter, bool free, std::uint32_t mark, bool label_taken) {
  if (letter == 0 || letter == static_cast<std::uint32_t>(Constraint::any)) return 0;  // ε in a plain word, or '*'
  if (letter == static_cast<std::uint32_t>(Constraint::boundary)) return free ? std::optional<std::uint32_t>(0) : std::nullopt;
  if (letter == static_cast<std::uint32_t>(Constraint::interior)) return free ? std::nullopt : std::optional<std::uint32_t>(0);
  if (letter == static_cast<std::uint32_t>(Constraint::no_connection)) {
    if (free || mark == empty_mark) return 0;
    if (mark == unmatched) return empty_mark;
    return std::nullopt;
  }
  // A label.
  if (free || mark == empty_mark) return std::nullopt;
  if (mark == unmatched) return label_taken ? std::nullopt : std::optional<std::uint32_t>(letter);
  return mark == letter ? std::optional<std::uint32_t>(0) : std::nullopt;
}

}  // namespace

std::optional<QueryMatch> annotate(const Map& input, const QueryWord& w, Dart start, const std::vector<bool>* blocked) {
  if (blocked && (*blocked)[start]) return std::nullopt;
  std::vector<std::uint32_t> annotation(input.size(), unmatched);
  if (blocked)
    for (Dart d = 0; d < input.size(); ++d)
      if ((*blocked)[d]) annotation[d] = empty_mark;
  std::vector<Dart> dart_of(w.darts + 1, no_dart);
  annotation[start] = 1;
  dart_of[1] = start;
  std::vector<Dart> queue{start};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Dart d = queue[head];
    for (std::size_t i = 0; i < w.dims.size(); ++i) {
      const bool free = is_free(input, w.dims[i], d);
      const Dart di = free ? no_dart : input.link(w.dims[i], d);
      const std::uint32_t c = w.at(annotation[d], i);
      const std::uint32_t mark = free ? unmatched : annotation[di];
      const auto result = check(c, free, mark, !is_constraint(c) && c != 0 && dart_of[c] != no_dart);
      if (!result) return std::nullopt;
      if (*result == 0) continue;
      annotation[di] = *result;
      if (*result != empty_mark) {
        dart_of[*result] = di;
        queue.push_back(di);
      }
    }
  }
  QueryMatch m;
  for (std::size_t k = 1; k <= w.darts; ++k) {
    if (dart_of[k] == no_dart) return std::nullopt;  // a label the word never reached
    m.darts.push_back(dart_of[k]);
  }
  return m;
}

void QueryTrie::add(const QueryWord& w, int id) {
  if (dims_.empty()) dims_ = w.dims;
  if (w.dims != dims_) throw std::invalid_argument("a prefix tree holds words of one model");
  std::uint32_t at = 0;
  for (std::uint32_t letter : w.letters) {
    std::uint32_t next = 0;
    for (std::uint32_t c : nodes_[at].children)
      if (nodes_[c].letter == letter) next = c;
    if (next == 0) {
      next = static_cast<std::uint32_t>(nodes_.size());
      nodes_.push_back(Node{letter, {}, {}});
      nodes_[at].children.push_back(next);
    }
    at = next;
  }
  nodes_[at].terminal.push_back(id);
  ++count_;
}

namespace {

// Depth-first walk of the tree and the input together, undoing the
// annotations of a branch when it is left.
struct TrieSearch {
  const Map& input;
  const std::vector<Dim>& dims;
  std::vector<std::uint32_t>& annotation;  // all unmatched on entry and on exit
  const std::vector<bool>* blocked;
  std::vector<Dart> dart_of{no_dart};
  std::vector<QueryMatch>* out;

  std::uint32_t mark(Dart d) const { return blocked && (*blocked)[d] ? empty_mark : annotation[d]; }

  void visit(const auto& nodes, std::uint32_t node, std::size_t depth) {
    const std::size_t n = dims.size();
    for (int q : nodes[node].terminal) {
      // Depth n * |D|: every label 1..|D| has its dart.
      QueryMatch m{q, {dart_of.begin() + 1, dart_of.begin() + 1 + static_cast<std::ptrdiff_t>(depth / n)}};
      out->push_back(std::move(m));
    }
    if (nodes[node].children.empty()) return;
    const std::uint32_t k = static_cast<std::uint32_t>(depth / n) + 1;
    const std::size_t i = depth % n;
    if (k >= dart_of.size() || dart_of[k] == no_dart) return;  // the word refers to a label not reached
    const Dart d = dart_of[k];
    const bool free = is_free(input, dims[i], d);
    const Dart di = free ? no_dart : input.link(dims[i], d);
    const std::uint32_t m = free ? unmatched : mark(di);
    for (std::uint32_t child : nodes[node].children) {
      const std::uint32_t c = nodes[child].letter;
      const bool taken = !is_constraint(c) && c != 0 && c < dart_of.size() && dart_of[c] != no_dart;
      const auto result = check(c, free, m, taken);
      if (!result) continue;
      if (*result == 0) {
        visit(nodes, child, depth + 1);
        continue;
      }
      annotation[di] = *result;
      if (*result != empty_mark) {
        if (dart_of.size() <= *result) dart_of.resize(*result + 1, no_dart);
        dart_of[*result] = di;
      }
      visit(nodes, child, depth + 1);
      if (*result != empty_mark) dart_of[*result] = no_dart;
      annotation[di] = unmatched;
    }
  }
};

}  // namespace

std::vector<QueryMatch> QueryTrie::match(const Map& input, Dart start, const std::vector<bool>* blocked, std::vector<std::uint32_t>* scratch) const {
  std::vector<QueryMatch> out;
  if (blocked && (*blocked)[start]) return out;
  std::vector<std::uint32_t> local;
  std::vector<std::uint32_t>& annotation = scratch ? *scratch : local;
  if (annotation.size() < input.size()) annotation.resize(input.size(), unmatched);
  TrieSearch s{input, dims_, annotation, blocked, {no_dart, start}, &out};
  annotation[start] = 1;
  s.visit(nodes_, 0, 0);
  annotation[start] = unmatched;
  return out;
}

}  // namespace dartcheck::querymodify
