#include "querymodify/overlap.hpp"

#include <algorithm>
#include <numeric>
#include <set>
#include <thread>
#include <unordered_set>

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

AllMatches all_matches(const Map& input, const QueryTrie& trie, const ClassBound* bound, unsigned threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, input.size() / 1024)));
  // Contiguous ranges of start darts, concatenated in order afterwards:
  // the same list as one thread would find.
  std::vector<std::vector<QueryMatch>> found(threads);
  auto work = [&](unsigned t) {
    const Dart begin = static_cast<Dart>(input.size() * t / threads), end = static_cast<Dart>(input.size() * (t + 1) / threads);
    std::vector<std::uint32_t> scratch(input.size(), 0), counts;
    ClassBound mine;
    if (bound) {
      counts.assign(bound->count->size(), 0);
      mine = {bound->class_of, bound->most, &counts};
    }
    for (Dart d = begin; d < end; ++d)
      for (auto& m : trie.match(input, d, nullptr, &scratch, bound ? &mine : nullptr)) found[t].push_back(std::move(m));
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  AllMatches all;
  struct KeyHash {
    std::size_t operator()(const std::pair<int, std::vector<Dart>>& k) const {
      std::size_t h = std::hash<int>()(k.first);
      for (Dart d : k.second) h = h * 0x9E3779B97F4A7C15ull + d;
      return h;
    }
  };
  std::unordered_set<std::pair<int, std::vector<Dart>>, KeyHash> seen;
  for (auto& list : found)
    for (auto& m : list) {
      ++all.raw;
      std::vector<Dart> key = m.darts;
      std::sort(key.begin(), key.end());
      if (seen.emplace(m.query, std::move(key)).second) all.distinct.push_back(std::move(m));
    }
  return all;
}

std::vector<QueryMatch> global_matches(const Map& input, const QueryTrie& trie, const std::function<double(const QueryMatch&)>& score) {
  return global_matches(all_matches(input, trie), input.size(), score);
}

std::vector<QueryMatch> global_matches(const AllMatches& all, std::size_t darts, const std::function<double(const QueryMatch&)>& score) {
  std::vector<double> s;
  for (const auto& m : all.distinct) s.push_back(score(m));
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
