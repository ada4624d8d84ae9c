#include "inference/infer.hpp"

#include "core/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include <chrono>
#include <map>
#include <stdexcept>

namespace dartcheck::inference {

std::vector<Dim> parse_inference_orbit(const std::string& text, const Model& model) {
  const OrbitType t = parse_orbit_type(text);
  std::vector<Dim> out;
  for (const auto& d : t) {
    if (!d) throw ValueError(fmt::format("the inference orbit type {} contains '_'", text));
    if (!model.contains(*d)) throw ValueError(fmt::format("dimension {} of {} is not a dimension of {}", *d, text, model.name));
    out.push_back(*d);
  }
  return out;
}

namespace {

// The proof obligation of a generalisation is the static checker's (a
// dropped loop on a deleted or created node would dangle or leave a link
// undefined; only preserved nodes qualify, and the check decides) and the
// example's (App. A verification).
void generalize(const KappaGraph& graph, Attempt& a, const std::string& name) {
  GraphScheme g = *a.scheme;
  std::vector<int> partner(g.nodes.size(), -1);  // a preserved node's L and R copies
  for (const SchemeArc& e : g.arcs)
    if (e.d == kappa_arc) partner[static_cast<std::size_t>(e.a)] = e.b, partner[static_cast<std::size_t>(e.b)] = e.a;
  auto has_loop = [&](int node, Dim d) {
    return std::any_of(g.arcs.begin(), g.arcs.end(), [&](const SchemeArc& e) { return e.a == node && e.b == node && e.d == d; });
  };
  std::vector<SchemeArc> kept;
  std::vector<std::string> dropped;
  for (const SchemeArc& e : g.arcs) {
    const int p = e.a >= 0 ? partner[static_cast<std::size_t>(e.a)] : -1;
    if (e.a == e.b && e.d != kappa_arc && p >= 0 && has_loop(p, e.d)) {
      if (!g.nodes[static_cast<std::size_t>(e.a)].after)
        dropped.push_back(fmt::format("{} -{}- {}", a.rule->names[static_cast<std::size_t>(e.a)], e.d, a.rule->names[static_cast<std::size_t>(e.a)]));
      continue;
    }
    kept.push_back(e);
  }
  if (dropped.empty()) return;
  g.arcs = std::move(kept);
  auto rule = to_rule(g, graph.model(), name);
  if (!rule.rule) {
    a.not_generalized = rule.why;
    return;
  }
  const auto verdict = check_rule(rule.rule->operation.rule, rule.rule->operation.words);
  std::vector<std::string> failing;
  for (const auto& c : verdict.conditions)
    if (!c.holds && c.skipped.empty()) failing.push_back(c.name());
  if (!failing.empty()) {
    a.not_generalized = fmt::format("without the loops the rule fails {}", fmt::join(failing, ", "));
    return;
  }
  auto check = verify(graph, g, *rule.rule, a.start);
  if (!check.holds) {
    a.not_generalized = fmt::format("without the loops the rule does not give the example back: {}", check.why);
    return;
  }
  a.scheme = std::move(g);
  a.rule = std::move(rule.rule);
  a.verification = std::move(check);
  a.generalized = std::move(dropped);
}

// The darts of `a` that are also in `b` (both hook-like sets of one κ graph).
std::vector<Dart> common(const std::vector<Dart>& a, const std::vector<Dart>& b, std::size_t darts) {
  std::vector<bool> in(darts, false);
  for (Dart x : b) in[x] = true;
  std::vector<Dart> out;
  for (Dart x : a)
    if (in[x]) out.push_back(x);
  return out;
}

// `covers` receives the darts from which the attempt is the same (every
// folding it made labelled their node as the hook), and whether its own
// folding failed.
Attempt attempt(const KappaGraph& graph, const std::vector<Dim>& orbit, Dart start, const InferOptions& options, const std::string& name,
                FoldScratch& scratch, std::vector<Dart>& covers, bool& fold_failed) {
  const auto t0 = std::chrono::steady_clock::now();
  Attempt a;
  a.start = start;
  auto folded = fold(graph, orbit, start, options.fold, scratch);
  covers = std::move(folded.hook_like);
  fold_failed = folded.failure.has_value();
  if (folded.failure) {
    a.failure = std::move(folded.failure);
  } else {
    a.scheme = std::move(folded.scheme);
    auto rule = to_rule(*a.scheme, graph.model(), name);
    if (!rule.rule) {
      a.not_a_rule = rule.why;
    } else {
      a.rule = std::move(rule.rule);
      const auto verdict = check_rule(a.rule->operation.rule, a.rule->operation.words);
      for (const auto& c : verdict.conditions)
        if (!c.holds && c.skipped.empty()) a.ill_formed.push_back(c.name());
      if (a.ill_formed.empty() && options.verify) a.verification = verify(graph, *a.scheme, *a.rule, start);
    }
  }
  a.does_nothing = a.rule && does_nothing(a.rule->operation);
  // Keeping undecided positions (the paper's relabeling) on an example
  // whose i-links are all loops can give the identity: an isolated square
  // "unsewn" along 2 is the same square. Freeing them gives the rule a
  // Jerboa user means (its unsew: i -> _ with an explicit i-loop).
  if (a.does_nothing && a.scheme && !a.scheme->undecided.empty() && options.fold.undecided == UndecidedPolicy::keep && !options.fold.strict) {
    InferOptions freed = options;
    freed.fold.undecided = UndecidedPolicy::free;
    // The marks of failed foldings hold for the caller's policy only.
    std::vector<Dart> marks;
    std::swap(marks, scratch.failed_from);
    std::vector<Dart> freed_covers;
    bool freed_failed = false;
    Attempt b = attempt(graph, orbit, start, freed, name, scratch, freed_covers, freed_failed);
    std::swap(marks, scratch.failed_from);
    covers = common(covers, freed_covers, graph.before().size());
    if (b.inferred()) {
      b.freed_undecided = true;
      a = std::move(b);
    }
  }
  if (options.generalize && a.inferred()) generalize(graph, a, name);
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return a;
}

}  // namespace

std::vector<Attempt> infer(const KappaGraph& graph, const std::vector<Dim>& orbit, const InferOptions& options) {
  std::vector<Attempt> out;
  if (options.start) {
    if (*options.start >= graph.before().size())
      throw ValueError(fmt::format("start dart {} is not a dart of the before map ({} darts)", *options.start, graph.before().size()));
    FoldScratch scratch(graph);
    std::vector<Dart> covers;
    bool failed = false;
    out.push_back(attempt(graph, orbit, *options.start, options, options.name, scratch, covers, failed));
    return out;
  }
  // One start per orbit of G (000 Sec. 10.3); the tables are shared. A
  // start is skipped when an earlier folding built its orbit as a node
  // labelled as the hook (the same folding re-rooted), and a folding that
  // builds such a node of a failed folding stops there.
  const std::size_t darts = graph.before().size();
  FoldScratch scratch(graph);
  if (!options.fold.strict) scratch.failed_from.assign(darts, no_dart);
  OrbitWalker walker(graph.before());
  std::vector<bool> marked(darts, false);
  std::map<std::string, int> seen;
  int rules = 0;
  for (Dart a = 0; a < darts; ++a) {
    if (marked[a]) continue;
    const auto& own = orbit_darts(walker, orbit, a);
    const std::size_t k = own.size();
    for (Dart b : own) marked[b] = true;
    std::vector<Dart> covers;
    bool failed = false;
    Attempt t = attempt(graph, orbit, a, options, rules ? fmt::format("{}-{}", options.name, rules) : options.name, scratch, covers, failed);
    // Hook-like nodes are <o>-orbits of k darts, listed node by node.
    for (std::size_t i = 0; i < covers.size(); i += k)
      if (!marked[covers[i]]) {
        t.same_starts.push_back(covers[i]);
        for (std::size_t j = i; j < i + k; ++j) marked[covers[j]] = true;
      }
    if (failed)
      for (Dart b : covers) scratch.failed_from[b] = a;
    if (t.scheme) {
      // Without keep_rejected only rules are remembered: a scheme equal to
      // a rejected one is rejected for the same reason, said again.
      std::string form = canonical_form(*t.scheme);
      if (const auto it = seen.find(form); it != seen.end())
        t.duplicate_of = it->second;
      else if (options.keep_rejected || t.inferred())
        seen.emplace(std::move(form), static_cast<int>(out.size()));
    }
    const bool found = t.inferred();
    if (!found && !options.keep_rejected && (t.scheme || t.rule)) {
      t.scheme.reset();
      t.rule.reset();
      t.verification.reset();
      t.details_dropped = true;
    }
    rules += found;
    out.push_back(std::move(t));
    if (found && !options.all) break;
  }
  return out;
}

}  // namespace dartcheck::inference
