#include "reports/infer_report.hpp"
#include "reports/json_document.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>

namespace dartcheck::reports {

using namespace inference;

namespace {

std::string side_text(const TopoGraph& g, const std::vector<ConjWord>& words, const std::vector<OrbitType>& labels) {
  std::vector<std::string> nodes, arcs;
  for (NodeId v = 0; v < g.node_count(); ++v) nodes.push_back(fmt::format("{} {}", g.name(v), orbit_type_str(labels[v])));
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    const auto& a = g.arc(e);
    if (!arc_word(words, e).empty() || a.source > a.target) continue;
    arcs.push_back(fmt::format("{} -{}- {}", g.name(a.source), a.label, g.name(a.target)));
  }
  return fmt::format("{}{}", fmt::join(nodes, ", "), arcs.empty() ? "" : fmt::format("; arcs {}", fmt::join(arcs, ", ")));
}

std::string node_name(const Attempt& a, int node) {
  return a.rule ? a.rule->names[static_cast<std::size_t>(node)] : fmt::format("folding node n{}", node);
}

std::string chosen_text(const UndecidedPosition& u) { return u.chosen ? std::to_string(*u.chosen) : std::string("_ with explicit loops"); }

std::string undecided_text(const Attempt& a) {
  std::vector<std::string> out;
  std::set<std::pair<std::string, std::size_t>> said;  // a preserved node's two folding nodes share its name
  for (const auto& u : a.scheme->undecided)
    if (said.emplace(node_name(a, u.node), u.position).second)
      out.push_back(
          fmt::format("{} position {} (dimension {}) -> {}", node_name(a, u.node), u.position, a.scheme->orbit[u.position], chosen_text(u)));
  return fmt::format("{}", fmt::join(out, "; "));
}

}  // namespace

std::string attempt_outcome(const Attempt& a) {
  if (a.failure) return fmt::format("{}: {}", name_of(a.failure->kind), a.failure->text);
  if (!a.not_a_rule.empty()) return a.not_a_rule;
  if (!a.ill_formed.empty()) return fmt::format("ill-formed, discarded (Sec. 8.2): {} fail", fmt::join(a.ill_formed, ", "));
  if (a.duplicate_of >= 0) return "the same scheme as an earlier start";
  if (a.verification && !a.verification->holds) return fmt::format("VERIFICATION FAILED (App. A): {}", a.verification->why);
  if (a.does_nothing) return "not inferred: the rule does nothing (L = R): the example does not show what the operation changes";
  return "inferred, well-formed, verified on the example (App. A)";
}

std::string infer_text(const InferRun& run, const std::vector<Attempt>& attempts) {
  std::string out = fmt::format("infer {} from {} ({} darts) to {} ({} darts), {} preserved darts ({})\n", run.orbit, run.before, run.before_darts,
                                run.after, run.after_darts, run.preserved, run.kappa);
  std::size_t inferred = 0;
  for (const auto& a : attempts) {
    out += fmt::format("  start {}: {} ({:.3f} ms)\n", a.start, attempt_outcome(a), a.seconds * 1e3);
    if (a.details_dropped) out += fmt::format("    (its rule is not kept with --all; --start {} shows it)\n", a.start);
    if (!a.same_starts.empty())
      out += fmt::format(
          "    and {} other start(s) with the same outcome, not folded: their {}-orbits are nodes of this folding labelled as the hook, "
          "so from them it is this folding re-rooted (Sec. 10.3)\n",
          a.same_starts.size(), run.orbit);
    if (a.rule && (a.inferred() || a.does_nothing)) {
      const auto& op = a.rule->operation;
      out += fmt::format("    rule {}: |L| = {}, |R| = {}, {} preserved\n", op.rule.name(), op.rule.left().node_count(), op.rule.right().node_count(),
                         a.rule->preserved);
      out += fmt::format("    L: {}\n    R: {}\n", side_text(op.rule.left(), op.words.left, op.jerboa->left),
                         side_text(op.rule.right(), op.words.right, op.jerboa->right));
    }
    // Every position the example does not decide is said, whatever became of it.
    if (a.scheme && !a.scheme->undecided.empty())
      out += fmt::format("    undecided (every link of that dimension in the hook orbit is a loop): {}\n", undecided_text(a));
    if (!a.generalized.empty())
      out += fmt::format("    generalised: dropped {} (the example's free links are kept as the host has them; the paper keeps explicit loops)\n",
                         fmt::join(a.generalized, ", "));
    if (!a.not_generalized.empty()) out += fmt::format("    not generalised: {}\n", a.not_generalized);
    if (a.freed_undecided)
      out +=
          "    freed: keeping the undecided positions gives a rule that does nothing, so they are i -> _ with explicit loops "
          "(Jerboa's unsew; --undecided keep|free|fail decides instead)\n";
    inferred += a.inferred();
  }
  std::size_t starts = attempts.size();
  for (const auto& a : attempts) starts += a.same_starts.size();
  out += fmt::format("{} rule(s) inferred from {} start(s){}\n", inferred, attempts.size(),
                     starts > attempts.size() ? fmt::format(" ({} start(s) in all)", starts) : std::string());
  return out;
}

std::string infer_json(const InferRun& run, const KappaGraph& graph, const std::vector<Attempt>& attempts) {
  Json rows = Json::array();
  std::size_t inferred = 0;
  for (const auto& a : attempts) {
    Json row{{"start", a.start},
             {"outcome", attempt_outcome(a)},
             {"inferred", a.inferred()},
             {"does_nothing", a.does_nothing},
             {"freed_undecided", a.freed_undecided},
             {"generalized", a.generalized},
             {"not_generalized", a.not_generalized},
             {"same_starts", a.same_starts},
             {"seconds", a.seconds}};
    if (a.failure)
      row["failure"] = Json{{"kind", name_of(a.failure->kind)},
                            {"node", fmt::format("n{}", a.failure->node)},
                            {"dimension", a.failure->dim == kappa_arc ? std::string("kappa") : std::to_string(a.failure->dim)},
                            {"dart", graph.name(a.failure->dart)}};
    if (a.rule) {
      const auto& op = a.rule->operation;
      row["rule"] = op.rule.name();
      row["left_nodes"] = op.rule.left().node_count();
      row["right_nodes"] = op.rule.right().node_count();
      row["preserved"] = a.rule->preserved;
      row["left"] = side_text(op.rule.left(), op.words.left, op.jerboa->left);
      row["right"] = side_text(op.rule.right(), op.words.right, op.jerboa->right);
    }
    Json undecided = Json::array();
    if (a.scheme)
      for (const auto& u : a.scheme->undecided)
        undecided.push_back(Json{{"node", node_name(a, u.node)},
                                 {"position", u.position},
                                 {"dimension", a.scheme->orbit[u.position]},
                                 {"chosen", u.chosen ? Json(*u.chosen) : Json(nullptr)}});
    row["undecided"] = std::move(undecided);
    inferred += a.inferred();
    rows.push_back(std::move(row));
  }
  Json doc = json_document("infer");
  doc["orbit"] = run.orbit;
  doc["before"] = run.before;
  doc["after"] = run.after;
  doc["kappa"] = run.kappa;
  doc["before_darts"] = run.before_darts;
  doc["after_darts"] = run.after_darts;
  doc["preserved_darts"] = run.preserved;
  doc["inferred"] = inferred;
  doc["attempts"] = std::move(rows);
  return json_text(std::move(doc));
}

}  // namespace dartcheck::reports
