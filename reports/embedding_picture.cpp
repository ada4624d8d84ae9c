#include "reports/embedding_picture.hpp"

namespace dartcheck::reports {

EmbeddingPicture embedding_picture(const Operation& entry, const std::vector<analysis::EmbeddingCheck>& checks) {
  EmbeddingPicture out;
  out.terms.terms = entry.terms ? &*entry.terms : nullptr;
  for (const auto& c : checks) {
    if (c.holds) continue;
    out.witnesses.insert(out.witnesses.end(), c.witnesses.begin(), c.witnesses.end());
    out.captions.push_back(failure_caption(c.required ? "fails " + c.name : c.name + " does not hold (not required)", c.witnesses));
    const std::size_t open = c.name.find('('), close = c.name.rfind(')');
    if (open != std::string::npos && close > open) out.terms.failing.push_back(c.name.substr(open + 1, close - open - 1));
  }
  return out;
}

}  // namespace dartcheck::reports
