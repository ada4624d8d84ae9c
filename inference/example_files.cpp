#include "inference/example_files.hpp"

#include <filesystem>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/catalog_writer.hpp"
#include "io/jerboa_jba.hpp"
#include "io/jerboa_modeler_writer.hpp"
#include "io/kappa_file.hpp"

namespace dartcheck::inference {

std::pair<KappaSpec, std::string> example_kappa(const std::string& kappa, const std::string& before_file, const std::string& after_file,
                                                const Map& before, const Map& after) {
  if (kappa != "identity") return {read_kappa_file(kappa, before.model()), kappa};
  KappaSpec spec;
  if (before_file.ends_with(".jba") && after_file.ends_with(".jba")) {
    const auto g = read_jba(before_file).ids, h = read_jba(after_file).ids;
    std::unordered_map<std::string, Dart> index;
    for (Dart d = 0; d < h.size(); ++d) index.emplace(h[d], d);
    for (Dart d = 0; d < g.size(); ++d)
      if (const auto it = index.find(g[d]); it != index.end()) spec.pairs.emplace_back(d, it->second);
    return {spec, "identity by the .jba files' dart ids"};
  }
  // A result of `dartcheck apply -o` that deleted darts records which darts it kept.
  if (const std::filesystem::path a(after_file); (a.extension() == ".yaml" || a.extension() == ".yml") && std::filesystem::is_regular_file(a))
    if (auto recorded = read_recorded_kappa(after_file)) return {std::move(*recorded), fmt::format("apply's record in {}, key preserved", after_file)};
  if (after.size() < before.size())
    throw InputError(
        "<command line>", 0, 0,
        fmt::format("--kappa identity: the after map has fewer darts ({}) than the before map ({}), so the operation deleted darts, and "
                    "dartcheck's maps number darts densely: ids moved, and identity would pair the wrong darts. Write the correspondence with "
                    "`dartcheck apply ... --kappa-out KAPPA.yaml` and pass --kappa KAPPA.yaml (or give Jerboa .jba snapshots, whose ids are kept)",
                    after.size(), before.size()));
  spec.identity = true;
  return {spec, "identity: same dart index"};
}

UndecidedPolicy parse_undecided(const std::string& text) {
  if (text == "keep") return UndecidedPolicy::keep;
  if (text == "free") return UndecidedPolicy::free;
  if (text == "fail") return UndecidedPolicy::fail;
  throw UsageError(fmt::format("--undecided: expected keep, free or fail, got '{}'", text));
}

void write_inferred(const std::string& file, const std::string& modeler, const KappaGraph& graph, const std::vector<Attempt>& attempts,
                    const ExampleLabels& labels) {
  std::vector<const Attempt*> found;
  for (const auto& a : attempts)
    if (a.inferred()) found.push_back(&a);
  if (std::filesystem::path(file).extension() == ".jme") {
    std::vector<const Operation*> ops;
    for (const auto* a : found) ops.push_back(&a->rule->operation);
    std::ostringstream out;
    write_jme(out, modeler, graph.model().dimension(), ops);
    write_file(file, out.str());
    return;
  }
  Catalog c;
  c.file = file;
  c.maps.push_back({"before", graph.model(), graph.before(), {}, {}, {}});
  c.maps.push_back({"after", graph.model(), graph.after(), {}, {}, {}});
  for (const auto* a : found) {
    CatalogRule r{a->rule->operation,
                  fmt::format("inferred by dartcheck infer from dart {} of {} on {}", a->start, labels.before,
                              orbit_type_str(a->rule->operation.jerboa->parameter)),
                  {},
                  {},
                  std::vector<std::string>{},
                  {},
                  std::nullopt,
                  {}};
    Example e;
    e.map = "before";
    e.hooks = {a->start};
    e.expect = "valid";
    e.isomorphic_to = "after";
    r.examples.push_back(e);
    c.rules.push_back(std::move(r));
  }
  write_file(file,
             catalog_yaml(c, fmt::format("inferred by dartcheck infer: before {}, after {}, orbit {}", labels.before, labels.after, labels.orbit)));
}

}  // namespace dartcheck::inference
