#include "querymodify/overlap.hpp"

#include <algorithm>
#include <numeric>
#include <set>
#include <thread>
#include <unordered_map>

namespace dartcheck::querymodify {

bool conflict(const QueryMatch& a, const QueryMatch& b) {
  std::vector<Dart> x = a.darts, y = b.darts;
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  std::vector<Dart> both;
  std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(both));
  return !both.empty();
}

std::vector<QueryMatch> greedy_matches(const Map& input, const QueryTrie& trie, const ClassBound* bound,
                                       const std::function<bool(const QueryMatch&)>& accept) {
  std::vector<bool> blocked(input.size(), false);
  std::vector<std::uint32_t> scratch(input.size(), 0);
  std::vector<QueryMatch> out;
  for (Dart d = 0; d < input.size(); ++d) {
    if (blocked[d]) continue;
    for (auto& m : trie.match(input, d, &blocked, &scratch, bound)) {
      if (accept && !accept(m)) continue;
      for (Dart x : m.darts) blocked[x] = true;
      out.push_back(std::move(m));
      break;
    }
  }
  return out;
}

namespace {

// Distinct matches by (query, dart set), kept in the order found. Only a
// hash of each key is stored (the darts are sorted again on a hash hit):
// the raw matches are several times the distinct ones and are not kept.
class DistinctMatches {
 public:
  /// True if m was new (then it is kept).
  bool add(QueryMatch&& m) {
    std::vector<Dart> key = m.darts;
    std::sort(key.begin(), key.end());
    std::uint64_t h = static_cast<std::uint64_t>(m.query) * 0x9E3779B97F4A7C15ull;
    for (Dart d : key) h = (h ^ d) * 0x100000001B3ull;
    const auto [lo, hi] = index_.equal_range(h);
    for (auto it = lo; it != hi; ++it) {
      const QueryMatch& other = list_[it->second];
      if (other.query != m.query || other.darts.size() != m.darts.size()) continue;
      std::vector<Dart> other_key = other.darts;
      std::sort(other_key.begin(), other_key.end());
      if (other_key == key) return false;
    }
    index_.emplace(h, list_.size());
    list_.push_back(std::move(m));
    return true;
  }
  std::vector<QueryMatch>& list() { return list_; }

 private:
  std::vector<QueryMatch> list_;
  std::unordered_multimap<std::uint64_t, std::size_t> index_;
};

}  // namespace

AllMatches all_matches(const Map& input, const QueryTrie& trie, const ClassBound* bound, unsigned threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, input.size() / 1024)));
  // Contiguous ranges of start darts, each deduplicated by its thread (a
  // match's start darts are its own, mostly in one range), then merged in
  // order: the same list as one thread would find.
  std::vector<DistinctMatches> found(threads);
  std::vector<std::size_t> raw(threads, 0);
  auto work = [&](unsigned t) {
    const Dart begin = static_cast<Dart>(input.size() * t / threads), end = static_cast<Dart>(input.size() * (t + 1) / threads);
    std::vector<std::uint32_t> scratch(input.size(), 0), counts;
    ClassBound mine;
    if (bound) {
      counts.assign(bound->count->size(), 0);
      mine = {bound->class_of, bound->most, &counts};
    }
    for (Dart d = begin; d < end; ++d)
      for (auto& m : trie.match(input, d, nullptr, &scratch, bound ? &mine : nullptr)) {
        ++raw[t];
        found[t].add(std::move(m));
      }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  AllMatches all;
  for (std::size_t r : raw) all.raw += r;
  if (threads == 1) {
    all.distinct = std::move(found[0].list());
    return all;
  }
  DistinctMatches merged;
  for (auto& f : found) {
    for (auto& m : f.list()) merged.add(std::move(m));
    f = DistinctMatches();
  }
  all.distinct = std::move(merged.list());
  return all;
}

std::vector<QueryMatch> global_matches(const Map& input, const QueryTrie& trie, const std::function<double(const QueryMatch&)>& score) {
  return global_matches(all_matches(input, trie), input.size(), score);
}

std::vector<QueryMatch> global_matches(const AllMatches& all, std::size_t darts, const std::function<double(const QueryMatch&)>& score) {
  std::vector<double> s;
  for (const auto& m : all.distinct) s.push_back(score(m));
  return global_matches(all, darts, s);
}

std::vector<QueryMatch> global_matches(const AllMatches& all, std::size_t darts, const std::vector<double>& s) {
  std::vector<std::size_t> order(all.distinct.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s[a] > s[b]; });
  std::vector<bool> used(darts, false);
  std::vector<QueryMatch> out;
  for (std::size_t k : order) {
    const auto& m = all.distinct[k];
    if (std::any_of(m.darts.begin(), m.darts.end(), [&](Dart d) { return used[d]; })) continue;
    for (Dart d : m.darts) used[d] = true;
    out.push_back(m);
  }
  return out;
}

}  // namespace dartcheck::querymodify
