#include "querymodify/annotation.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace dartcheck::querymodify {

std::vector<Dart> query_to_input(const Map& q, Dart start, const QueryMatch& m) {
  const Labeling l = bfs_labeling(q, start);
  std::vector<Dart> out(q.size(), no_dart);
  for (std::size_t k = 0; k < l.darts.size() && k < m.darts.size(); ++k) out[l.darts[k]] = m.darts[k];
  return out;
}

namespace {

constexpr std::uint32_t unmatched = 0;
constexpr std::uint32_t empty_mark = 0xFFFFFFFF;  // annotated ∅

// The table of the header, for one letter. `mark` is the annotation of
// d_i (0: none, empty_mark: ∅, else a label); returns what to annotate d_i
// with (0: nothing), or nullopt for a violation.
[[gnu::always_inline]] inline std::optional<std::uint32_t> check(std::uint32_t letter, bool free, std::uint32_t mark, bool label_taken) {
  if (letter == 0 || letter == static_cast<std::uint32_t>(BoundaryCondition::any)) return 0;  // ε in a plain word, or '*'
  if (letter == static_cast<std::uint32_t>(BoundaryCondition::boundary)) return free ? std::optional<std::uint32_t>(0) : std::nullopt;
  if (letter == static_cast<std::uint32_t>(BoundaryCondition::interior)) return free ? std::nullopt : std::optional<std::uint32_t>(0);
  if (letter == static_cast<std::uint32_t>(BoundaryCondition::no_connection)) {
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
      const auto result = check(c, free, mark, !is_boundary_condition(c) && c != 0 && dart_of[c] != no_dart);
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
  if (w.dims != dims_) throw ValueError("a prefix tree holds words of one model");
  std::uint32_t labels = 1;  // label 1 is the start dart
  for (std::uint32_t letter : w.letters)
    if (!is_boundary_condition(letter) && letter > labels) {
      if (letter != labels + 1) throw ValueError("a query word must number its labels in order of first use");
      ++labels;
    }
  std::uint32_t at = 0;
  for (std::uint32_t letter : w.letters) {
    auto& ch = nodes_[at].children;
    auto it = std::lower_bound(ch.begin(), ch.end(), std::pair<std::uint32_t, std::uint32_t>{letter, 0});
    if (it == ch.end() || it->first != letter) {
      const auto next = static_cast<std::uint32_t>(nodes_.size());
      it = ch.insert(it, {letter, next});
      const std::uint32_t child = it->second;
      nodes_.push_back(Node{});  // invalidates ch and it
      at = child;
      continue;
    }
    at = it->second;
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
  const ClassBound* bound = nullptr;
  std::vector<bool> oriented;  // per letter: its dimension is a permutation (a fixed point is not free)
  std::uint32_t classes = 0;   // distinct classes of the labeled darts
  std::uint32_t labeled = 1;   // labels 1..labeled are taken (the start dart is 1)

  // Counts dart d's class in; false (and nothing counted) if that would
  // exceed the bound.
  bool enter(Dart d) {
    if (!bound) return true;
    std::uint32_t& c = (*bound->count)[(*bound->class_of)[d]];
    if (c == 0 && classes == bound->most) return false;
    classes += c++ == 0;
    return true;
  }
  void leave(Dart d) {
    if (bound) classes -= --(*bound->count)[(*bound->class_of)[d]] == 0;
  }

  std::uint32_t mark(Dart d) const { return blocked && (*blocked)[d] ? empty_mark : annotation[d]; }

  // Annotates di with `result` (0: nothing) for letter c; false if the
  // class bound refuses it. Undone by undo().
  bool apply(Dart di, std::uint32_t result) {
    if (result == 0) return true;
    if (result != empty_mark && !enter(di)) return false;
    annotation[di] = result;
    if (result != empty_mark) {
      if (dart_of.size() <= result) dart_of.resize(result + 1, no_dart);
      dart_of[result] = di;
      ++labeled;
    }
    return true;
  }
  void undo(Dart di, std::uint32_t result) {
    if (result == 0) return;
    if (result != empty_mark) dart_of[result] = no_dart, leave(di), --labeled;
    annotation[di] = unmatched;
  }

  // Walks a run of single-child nodes in a loop (most of the tree: words
  // share little beyond their first tetrahedra), recursing only where the
  // tree branches; what the run annotated is undone on the way out.
  void visit(const auto& nodes, std::uint32_t node, std::size_t depth) {
    const std::size_t n = dims.size();
    std::array<std::pair<Dart, std::uint32_t>, 64> local;  // undo records of the run (spills to `spill`)
    std::vector<std::pair<Dart, std::uint32_t>> spill;
    std::size_t done = 0;
    auto record = [&](Dart di, std::uint32_t result) {
      if (done < local.size())
        local[done] = {di, result};
      else
        spill.emplace_back(di, result);
      ++done;
    };
    while (true) {
      for (int q : nodes[node].terminal) {
        // Depth n * |D|: every label 1..|D| has its dart.
        QueryMatch m{q, {dart_of.begin() + 1, dart_of.begin() + 1 + static_cast<std::ptrdiff_t>(depth / n)}};
        out->push_back(std::move(m));
      }
      const auto& children = nodes[node].children;
      if (children.empty()) break;
      const std::uint32_t k = static_cast<std::uint32_t>(depth / n) + 1;
      const std::size_t i = depth % n;
      if (k >= dart_of.size() || dart_of[k] == no_dart) break;  // the word refers to a label not reached
      const Dart d = dart_of[k];
      const Dart e = input.link(dims[i], d);
      const bool free = e == no_dart || (e == d && !oriented[i]);  // is_free, inlined
      const Dart di = free ? no_dart : e;
      const std::uint32_t m = free ? unmatched : mark(di);
      auto taken = [&](std::uint32_t c) { return !is_boundary_condition(c) && c != 0 && c < dart_of.size() && dart_of[c] != no_dart; };
      if (children.size() == 1) {
        const std::uint32_t c = children.front().first;
        const auto result = check(c, free, m, taken(c));
        if (!result || !apply(di, *result)) break;
        if (*result != 0) record(di, *result);
        node = children.front().second;
        ++depth;
        continue;
      }
      // The letters the table can accept here, in increasing order (so the
      // children are visited in order): a free link takes ε, '*', '↔' (and
      // 0 in a plain word); a label only the same label; an unannotated
      // dart the next new label, '↔', 'ε̄', '*'; a ∅ dart '↔', 'ε̄', '*'.
      constexpr auto nc = static_cast<std::uint32_t>(BoundaryCondition::no_connection), in = static_cast<std::uint32_t>(BoundaryCondition::interior),
                     bd = static_cast<std::uint32_t>(BoundaryCondition::boundary), any = static_cast<std::uint32_t>(BoundaryCondition::any);
      std::array<std::uint32_t, 4> wanted{};
      std::size_t count = 0;
      if (free)
        wanted = {0, nc, bd, any}, count = 4;
      else if (m == empty_mark)
        wanted = {nc, in, any, 0}, count = 3;
      else if (m == unmatched)
        wanted = {labeled + 1, nc, in, any}, count = 4;
      else
        wanted = {m, in, any, 0}, count = 3;
      auto it = children.begin();
      for (std::size_t w = 0; w < count; ++w) {
        it = std::lower_bound(it, children.end(), std::pair<std::uint32_t, std::uint32_t>{wanted[w], 0});
        if (it == children.end()) break;
        if (it->first != wanted[w]) continue;
        const std::uint32_t c = it->first, child = it->second;
        const auto result = check(c, free, m, taken(c));
        if (!result || !apply(di, *result)) continue;
        visit(nodes, child, depth + 1);
        undo(di, *result);
      }
      break;
    }
    while (done > 0) {
      --done;
      const auto [di, result] = done < local.size() ? local[done] : spill[done - local.size()];
      undo(di, result);
    }
  }
};

}  // namespace

std::vector<QueryMatch> QueryTrie::match(const Map& input, Dart start, const std::vector<bool>* blocked, std::vector<std::uint32_t>* scratch,
                                         const ClassBound* bound) const {
  std::vector<QueryMatch> out;
  if (blocked && (*blocked)[start]) return out;
  std::vector<std::uint32_t> local;
  std::vector<std::uint32_t>& annotation = scratch ? *scratch : local;
  if (annotation.size() < input.size()) annotation.resize(input.size(), unmatched);
  TrieSearch s{input, dims_, annotation, blocked, {no_dart, start}, &out, bound, {}};
  for (Dim i : dims_) s.oriented.push_back(input.model().is_oriented(i));
  if (!s.enter(start)) return out;
  annotation[start] = 1;
  s.visit(nodes_, 0, 0);
  annotation[start] = unmatched;
  s.leave(start);
  return out;
}

}  // namespace dartcheck::querymodify
