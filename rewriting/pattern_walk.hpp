// The walk that builds P_v (002 Def. 20): one BFS per hook dart along W's
// generators, shared by the interpreter (scheme_rewriter.cpp) and the
// generated code (compiled_runtime.hpp), so that both number the pattern's
// positions the same way.
//
// The walk writes the dart it reached at the queue's tail and moves the
// tail only when the dart is new, so it has no branch on "new or met",
// which a processor cannot predict (a third of the steps find a new dart).
// Every hook's walk must give the first one's shift tables (002 Sec. 6.3:
// one pattern for every component of L).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

/// Why a walk stopped early.
struct PatternWalkStop {
  enum Kind { none, no_path, not_isomorphic } kind = none;
  Dart at = no_dart;          // no_path: the dart with no path
  std::size_t generator = 0;  // no_path: the generator it lacks
  std::size_t hook = 0;       // not_isomorphic: the hook whose walk differs from the first one's
};

/// Walks P_v from each of `hooks` along `generators` generators:
/// `follow(w, d)` is the dart reached from d along generator w (no_dart:
/// none). `position` (one entry per dart, `none` everywhere before and
/// after) and `queue` (at least one entry more than the map has darts) are
/// the caller's scratch; `shift[w]` receives the position of p·w for each
/// position p of the first hook's walk; `walked(h, darts)` hears each
/// hook's pattern, darts in position order.
template <class Follow, class Walked>
PatternWalkStop walk_pattern_graphs(std::span<const Dart> hooks, std::size_t generators, Follow&& follow, std::vector<std::uint32_t>& position,
                                    std::vector<Dart>& queue, std::vector<std::vector<std::uint32_t>>& shift, Walked&& walked) {
  constexpr std::uint32_t none = 0xffffffffU;
  for (std::size_t h = 0; h < hooks.size(); ++h) {
    std::size_t size = 1;
    // The marks go on every exit: the scratch is clean between walks.
    struct Unmark {
      std::vector<std::uint32_t>& position;
      const std::vector<Dart>& queue;
      const std::size_t& size;
      ~Unmark() {
        for (std::size_t k = 0; k < size; ++k) position[queue[k]] = none;
      }
    } const unmark{position, queue, size};
    queue[0] = hooks[h];
    position[hooks[h]] = 0;
    for (std::size_t k = 0; k < size; ++k)
      for (std::size_t w = 0; w < generators; ++w) {
        const Dart here = queue[k];
        const Dart t = follow(w, here);
        if (t == no_dart) return {PatternWalkStop::no_path, here, w, h};
        const std::uint32_t met = position[t];
        const std::uint32_t at = met == none ? static_cast<std::uint32_t>(size) : met;
        position[t] = at;
        queue[size] = t;
        size += met == none;
        if (h == 0)
          shift[w].push_back(at);
        else if (shift[w][k] != at)
          return {PatternWalkStop::not_isomorphic, no_dart, w, h};
      }
    walked(h, std::span<const Dart>(queue.data(), size));
  }
  return {};
}

}  // namespace dartcheck
