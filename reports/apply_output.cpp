#include "reports/apply_output.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dartcheck::reports {

std::string not_applied_text(Refusal refusal, const std::string& why) { return fmt::format("not applied ({}): {}\n", name_of(refusal), why); }

std::string embedded_application_text(const EmbeddedApplication& a, Instantiation instantiation, std::size_t h_size) {
  std::string s = fmt::format("applied ({} instantiation): {} darts matched, {} added; result has {} darts\n",
                              instantiation == Instantiation::direct ? "direct" : "extended", a.matched, a.added, h_size);
  for (const auto& w : a.written) s += fmt::format("  {}.{} = {} (dart {})\n", w.node, w.embedding, w.value.str(), w.dart);
  for (const auto& c : a.conflicts) s += fmt::format("  conflict: {}\n", c);
  return s;
}

std::string application_text(const Rule& rule, const Application& a, std::size_t h_size) {
  std::string comatch;
  for (NodeId v = 0; v < rule.right().node_count(); ++v)
    comatch += fmt::format("{}{}={}", v ? " " : "", rule.right().name(v), fmt::join(a.comatch[v], ","));
  if (a.pattern)
    return fmt::format("applied scheme: pattern graph of {} darts; result has {} darts; comatch {}\n", a.match.empty() ? 0 : a.match[0].size(),
                       h_size, comatch);
  return fmt::format("applied: result has {} darts; comatch {}\n", h_size, comatch);
}

std::string embedding_check_text(const Embedding& e, const EmbeddingConsistency& c, bool foreign, std::size_t limit) {
  std::string s = fmt::format(
      "embedding {} <{}>: {} orbits, {}\n", e.signature.name, fmt::join(e.signature.orbit, ","), c.orbits,
      c.consistent() ? "consistent (every dart labeled, one value per orbit)" : fmt::format("{} inconsistent orbits", c.conflicts.size()));
  if (foreign && !c.consistent())
    return s + "  (not an embedding of the rule's modeler: its new darts get no value, and H is judged on the modeler's embeddings)\n";
  for (std::size_t k = 0; k < c.conflicts.size() && (limit == 0 || k < limit); ++k)
    s += fmt::format("  {}\n", c.conflicts[k].describe(e.signature.name, e.signature.orbit));
  return s;
}

std::string renumbered_text(std::size_t moved, std::size_t preserved, bool kappa_out) {
  if (moved == 0) return {};
  return fmt::format("darts renumbered: {} of the {} preserved darts have another id in the result{}\n", moved, preserved,
                     kappa_out ? "" : " (--kappa-out FILE writes the correspondence for infer --kappa)");
}

}  // namespace dartcheck::reports
