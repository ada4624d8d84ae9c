#include "analysis/embedding_checks.hpp"

#include "checkers/embedding_conditions.hpp"
#include "checkers/embedding_presence.hpp"

namespace dartcheck::analysis {

std::vector<EmbeddingCheck> embedding_checks(const Catalog& catalog, const Operation& entry) {
  std::vector<EmbeddingCheck> out;
  if (entry.terms) {
    const char* source = entry.terms->instantiation == Instantiation::direct ? "003 Theorem 2" : "003 Theorem 4";
    for (auto& v : check_term_conditions(entry.rule, entry.words, *entry.terms))
      out.push_back({v.name(), v.holds, v.required, std::move(v.witnesses), source});
  } else if (!catalog.embeddings.empty()) {
    for (auto& v : check_embedding_presence(entry.rule, entry.words, catalog.embeddings, entry.expressions))
      out.push_back({v.name(), v.holds, true, std::move(v.witnesses), "Jerboa presence check"});
  }
  return out;
}

std::vector<std::string> failing_names(const std::vector<EmbeddingCheck>& checks) {
  std::vector<std::string> r;
  for (const auto& c : checks)
    if (c.required && !c.holds) r.push_back(c.name);
  return r;
}

}  // namespace dartcheck::analysis
