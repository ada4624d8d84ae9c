#include "querymodify/overlap.hpp"

#include <algorithm>
#include <numeric>
#include <set>

namespace dartcheck::querymodify {

bool conflict(const QueryMatch& a, const QueryMatch& b) {
  std::vector<Dart> x = a.darts, y = b.darts;
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  std::vector<Dart> both;
  std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(both));
  return !both.empty();
}

std::vector<QueryMatch> greedy_matches(const Map& input, const QueryTrie& trie) {
  std::vector<bool> blocked(input.size(), false);
  std::vector<std::uint32_t> scratch(input.size(), 0);
  std::vector<QueryMatch> out;
  for (Dart d = 0; d < input.size(); ++d) {
    if (blocked[d]) continue;
    auto found = trie.match(input, d, &blocked, &scratch);
    if (found.empty()) continue;
    for (Dart x : found.front().darts) blocked[x] = true;
    out.push_back(std::move(found.front()));
  }
  return out;
}

AllMatches all_matches(const Map& input, const QueryTrie& trie) {
  AllMatches all;
  std::vector<std::uint32_t> scratch(input.size(), 0);
  std::set<std::pair<int, std::vector<Dart>>> seen;
  for (Dart d = 0; d < input.size(); ++d)
    for (auto& m : trie.match(input, d, nullptr, &scratch)) {
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
