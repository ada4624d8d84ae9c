// The one union-find (core/disjoint_sets.hpp). Properties, on random
// sequences of joins over up to 40 elements, against a brute-force closure
// (two elements are together iff a chain of joined pairs links them):
// find names the same representative exactly for elements in one set;
// `join` leaves every set represented by its smallest element, whatever
// the order of the joins; `attach` represents the union of the last
// attach by the target's representative; the free functions on a
// std::array agree with the class.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>

#include "core/disjoint_sets.hpp"

using namespace dartcheck;

namespace {

// Component of each element by repeated relaxation over the pairs.
std::vector<int> closure(std::size_t n, const std::vector<std::pair<int, int>>& pairs) {
  std::vector<int> c(n);
  for (std::size_t x = 0; x < n; ++x) c[x] = static_cast<int>(x);
  for (bool changed = true; changed;) {
    changed = false;
    for (auto [a, b] : pairs) {
      const int m = std::min(c[static_cast<std::size_t>(a)], c[static_cast<std::size_t>(b)]);
      for (int* x : {&c[static_cast<std::size_t>(a)], &c[static_cast<std::size_t>(b)]})
        if (*x != m) *x = m, changed = true;
    }
  }
  return c;
}

std::vector<std::pair<int, int>> random_pairs(std::size_t n) {
  return *rc::gen::container<std::vector<std::pair<int, int>>>(
      rc::gen::pair(rc::gen::inRange(0, static_cast<int>(n)), rc::gen::inRange(0, static_cast<int>(n))));
}

}  // namespace

RC_GTEST_PROP(DisjointSets, JoinGroupsAsTheClosureAndKeepsTheSmallest, ()) {
  const auto n = static_cast<std::size_t>(*rc::gen::inRange(1, 40));
  const auto pairs = random_pairs(n);
  DisjointSets<int> sets(n);
  for (auto [a, b] : pairs) sets.join(a, b);
  const auto c = closure(n, pairs);
  // The closure's label is the smallest element of each component.
  for (std::size_t x = 0; x < n; ++x) RC_ASSERT(sets.find(static_cast<int>(x)) == c[x]);
  RC_ASSERT(sets.representatives() == c);
}

RC_GTEST_PROP(DisjointSets, AttachGroupsAsTheClosureUnderTheTargetsRepresentative, ()) {
  const auto n = static_cast<std::size_t>(*rc::gen::inRange(1, 40));
  const auto pairs = random_pairs(n);
  DisjointSets<int> sets(n);
  for (auto [a, b] : pairs) {
    const int target = sets.find(b);
    sets.attach(a, b);
    RC_ASSERT(sets.find(a) == target);
    RC_ASSERT(sets.find(b) == target);
  }
  const auto c = closure(n, pairs);
  for (std::size_t x = 0; x < n; ++x)
    for (std::size_t y = 0; y < n; ++y) RC_ASSERT((sets.find(static_cast<int>(x)) == sets.find(static_cast<int>(y))) == (c[x] == c[y]));
}

RC_GTEST_PROP(DisjointSets, FreeFunctionsOnAnArrayAgreeWithTheClass, ()) {
  const auto pairs = random_pairs(8);
  std::array<int, 8> table{0, 1, 2, 3, 4, 5, 6, 7};
  DisjointSets<int> sets(8);
  for (auto [a, b] : pairs) {
    attach_set(table, a, b);
    sets.attach(a, b);
  }
  for (int x = 0; x < 8; ++x) RC_ASSERT(find_representative(table, x) == sets.find(x));
}
