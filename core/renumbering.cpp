#include "core/renumbering.hpp"

namespace dartcheck {

Renumbering::Renumbering(std::size_t g_size, std::size_t h_size, std::size_t touched)
    : g_size_(g_size), h_size_(h_size), g2h_(touched, g_size), h2g_(touched, h_size) {}

void Renumbering::map(Dart g, Dart h) {
  g2h_.set(g, h);
  h2g_.set(h, g);
}

void Renumbering::deleted(Dart g) { g2h_.set(g, gone); }

Renumbering Renumbering::compaction(std::size_t g_size, std::size_t h_size, std::span<const Dart> deleted,
                                    std::span<const std::pair<Dart, Dart>> moved) {
  Renumbering r(g_size, h_size, deleted.size() + moved.size());
  for (Dart d : deleted) r.deleted(d);
  for (auto [from, to] : moved) r.map(from, to);
  return r;
}

void Renumbering::created(Dart h) { h2g_.set(h, gone); }

Renumbering Renumbering::then(const Renumbering& next) const {
  Renumbering out(g_size_, next.h_size_, 16);
  // A dart of G that either step touched; the others keep their number.
  auto carry = [&](Dart g) {
    const Dart h = to_h(g);
    const Dart k = h == no_dart ? no_dart : next.to_h(h);
    if (k == no_dart)
      out.deleted(g);
    else if (k != g)
      out.map(g, k);
  };
  g2h_.for_each([&](Dart g, std::uint32_t) { carry(g); });
  next.g2h_.for_each([&](Dart h, std::uint32_t) {
    if (const Dart g = to_g(h); g != no_dart) carry(g);
  });
  // Darts of K that do not come from G.
  auto created_in_k = [&](Dart k) {
    const Dart h = next.to_g(k);
    if (h == no_dart || to_g(h) == no_dart) out.created(k);
  };
  next.h2g_.for_each([&](Dart k, std::uint32_t) { created_in_k(k); });
  h2g_.for_each([&](Dart h, std::uint32_t) {
    if (const Dart k = next.to_h(h); k != no_dart) created_in_k(k);
  });
  return out;
}

}  // namespace dartcheck
