#include "reports/words_text.hpp"

#include <fmt/format.h>

#include "io/map_io.hpp"

namespace dartcheck::reports {

std::string normal_forms_text(const Model& model, const ConjWord& w) {
  ConjugateRewriting r(model);
  const auto& nfs = r.normal_forms(w);
  std::string out = fmt::format("{} in R_{{N,E}} of {}: {} normal form{}\n", w.str(), model.name, nfs.size(), nfs.size() == 1 ? "" : "s");
  for (const auto& nf : nfs) fmt::format_to(std::back_inserter(out), "  {}\n", nf.str());
  fmt::format_to(std::back_inserter(out), "reduces to ε: {}\n", r.reduces_to_empty(w) ? "yes" : "no");
  return out;
}

namespace {

std::string solver_line(const Model& model, const analysis::WordComparison& c) {
  if (!c.solver) return "";
  switch (c.solver->answer) {
    case proofs::Answer::sat: {
      const Map& m = *c.solver->map;
      return fmt::format("\nZ3: a {} of {} darts separates them at dart 0 (ends {} and {}):\n{}", model.name, m.size(), follow(m, 0, c.w),
                         follow(m, 0, c.w2), map_to_yaml(m));
    }
    case proofs::Answer::unsat:
      return fmt::format("\nZ3: no {} of up to {} darts separates them", model.name, c.prove_darts);
    case proofs::Answer::unknown:
      return "\nZ3: unknown (rlimit reached)";
  }
  return "";
}

}  // namespace

std::string word_comparison_text(const Model& model, const analysis::WordComparison& c) {
  const std::string w = c.w.str(), w2 = c.w2.str(), probe = c.probe.str(), solver = solver_line(model, c);
  if (c.congruent) return fmt::format("{} <->* {}: congruent ({} ->* ε){}\n", w, w2, probe, solver);
  if (c.solver && c.solver->answer != proofs::Answer::unknown)
    return fmt::format(
        "{} and {}: {} has no rewriting to ε in R_{{N,E}}{}\n{}", w, w2, probe, solver,
        c.solver->answer == proofs::Answer::unsat ? "note: R_{N,E} does not prove them congruent, yet no bounded map separates them\n" : "");
  if (c.random_witness) return fmt::format("{} and {}: not congruent: {}{}\n", w, w2, *c.random_witness, solver);
  return fmt::format("{} and {}: not shown congruent ({} has no rewriting to ε, and no random map separates them){}\n", w, w2, probe, solver);
}

}  // namespace dartcheck::reports
