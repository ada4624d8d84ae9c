#include "cli/embedding_checks.hpp"

#include "checkers/embedding_conditions.hpp"
#include "checkers/embedding_presence.hpp"

namespace dartcheck::cli {

std::vector<EmbeddingCheck> embedding_checks(const Catalog& catalog, const CatalogRule& entry) {
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

EmbeddingPicture embedding_picture(const CatalogRule& entry, const std::vector<EmbeddingCheck>& checks) {
  EmbeddingPicture out;
  out.terms.terms = entry.terms ? &*entry.terms : nullptr;
  for (const auto& c : checks) {
    if (c.holds) continue;
    out.witnesses.insert(out.witnesses.end(), c.witnesses.begin(), c.witnesses.end());
    const std::size_t open = c.name.find('('), close = c.name.rfind(')');
    if (open != std::string::npos && close > open) out.terms.failing.push_back(c.name.substr(open + 1, close - open - 1));
  }
  return out;
}

}  // namespace dartcheck::cli
