#include "reports/querymodify_report.hpp"
#include "reports/json_document.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace dartcheck::reports {

namespace {

struct Quality {
  double min = NAN, median = NAN;
};
Quality quality_of(std::vector<double> q) {
  std::sort(q.begin(), q.end());
  if (q.empty()) return {};
  return {q.front(), q[q.size() / 2]};
}

std::vector<double> qualities(const querymodify::CellSelection& s) {
  std::vector<double> q;
  for (const auto& c : s.cells) q.push_back(c.quality);
  return q;
}

bool with_prisms(const RecombineRun& run) { return run.cells.find("prism") != std::string::npos; }
bool with_pyramids(const RecombineRun& run) { return run.cells.find("pyramid") != std::string::npos; }

// A line of the prisms or pyramids found and selected.
std::string cells_line(const char* heading, const char* where, const querymodify::CellSelection& s, double min_quality, bool conforming) {
  std::string out = fmt::format("{:<12}{} candidates {}, {} with scaled Jacobian above {}; ", heading, s.candidates, where, s.acceptable, min_quality);
  if (conforming) out += fmt::format("{} passed over as not conforming, ", s.nonconforming);
  out += fmt::format("{} selected", s.cells.size());
  const Quality q = quality_of(qualities(s));
  if (std::isfinite(q.min)) out += fmt::format(", quality min {:.3f}, median {:.3f}", q.min, q.median);
  return out + fmt::format(" ({:.3f} s)\n", s.seconds);
}

double tets_per_second(const RecombineRun& run) { return run.total_seconds > 0 ? static_cast<double>(run.tets) / run.total_seconds : 0; }

Json number_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

// The output's quality: quantiles and a histogram of the recombined
// cells' scaled Jacobian, and the share of the volume per kind of cell.
std::string quality_text(const querymodify::QualitySummary& s) {
  std::string out;
  if (s.cells > 0) {
    out += fmt::format("cells       scaled Jacobian of the {} recombined cells:", s.cells);
    for (std::size_t k = 0; k < s.quantiles.size(); ++k) out += fmt::format("{} {} {:.3f}", k ? "," : "", querymodify::quantile_names[k], s.quantiles[k]);
    out += "\n";
    const std::size_t most = *std::max_element(s.histogram.begin(), s.histogram.end());
    for (std::size_t k = 0; k < s.histogram.size(); ++k) {
      const std::size_t bar = most ? (s.histogram[k] * 40 + most - 1) / most : 0;  // rounded up: a bin with cells shows
      out += fmt::format("            {:<11} {:>8} {}\n", querymodify::histogram_labels[k], s.histogram[k], std::string(bar, '#'));
    }
  }
  out += fmt::format("volume      hexahedra {:.1f}%, prisms {:.1f}%, pyramids {:.1f}%, tetrahedra {:.1f}% of the mesh's volume\n",
                     100 * s.volume_share[0], 100 * s.volume_share[1], 100 * s.volume_share[2], 100 * s.volume_share[3]);
  return out;
}

Json quality_document(const querymodify::QualitySummary& s) {
  Json quantiles = Json::object();
  for (std::size_t k = 0; k < s.quantiles.size(); ++k) quantiles[querymodify::quantile_names[k]] = number_or_null(s.quantiles[k]);
  Json bins = Json::array();
  for (std::size_t k = 0; k < s.histogram.size(); ++k) bins.push_back(Json{{"bin", querymodify::histogram_labels[k]}, {"cells", s.histogram[k]}});
  return Json{{"recombined_cells", s.cells},
              {"quantiles", quantiles},
              {"histogram", bins},
              {"poor_threshold", querymodify::poor_quality},
              {"poor_cells", s.poor},
              {"volume_share", Json{{"hexahedra", s.volume_share[0]}, {"prisms", s.volume_share[1]}, {"pyramids", s.volume_share[2]},
                                    {"tetrahedra", s.volume_share[3]}}}};
}

}  // namespace

std::string recombine_text(const RecombineRun& run) {
  const auto& r = run.result;
  const Quality q = quality_of(r.quality);
  std::string out;
  out += fmt::format("mesh        {}: {} points, {} tetrahedra ({:.3f} s)\n", run.mesh, run.points, run.tets, run.read_seconds);
  out += fmt::format("input map   {} darts (12 per tetrahedron), a valid open 3-O-map ({:.3f} s)\n", run.input_darts, run.input_check_seconds);
  if (run.queries > 0)
    out += fmt::format("queries     {} hex patterns, both hands of the 174 classes ({:.3f} s)\n", run.queries, run.query_seconds);
  else
    out += "queries     none built: the vertex search looks hexes up among the labeled subdivisions\n";
  if (r.search == querymodify::Search::words)
    out += fmt::format("matches     word search: {} raw, {} distinct, {} with 8 distinct corners and scaled Jacobian above {} ({:.3f} s)\n",
                       r.raw_matches, r.distinct_matches, r.acceptable, run.min_quality, r.match_seconds);
  else
    out += fmt::format("candidates  vertex search: {} hexes on 8 distinct vertices ({} readings), {} with scaled Jacobian above {} ({:.3f} s)\n",
                       r.candidates, r.readings, r.acceptable, run.min_quality, r.match_seconds);
  out += fmt::format("selection   {} hexes, {} ({:.3f} s)\n", r.hexes,
                     run.strategy == "greedy" ? "greedy: the first match from each dart in order" : "global: by scaled Jacobian, best first",
                     r.select_seconds);
  const bool conforming = r.contacts == querymodify::Contacts::conforming;
  if (conforming)
    out += with_prisms(run) || with_pyramids(run)
               ? fmt::format("conforming  cells meet only in a vertex, an edge or a face of both; {} hex candidates passed over\n", r.nonconforming)
               : fmt::format("conforming  hexes meet only in a vertex, an edge or a face of both; {} candidates passed over\n", r.nonconforming);
  if (!r.quality.empty()) out += fmt::format("quality     scaled Jacobian of the hexes: min {:.3f}, median {:.3f}\n", q.min, q.median);
  if (with_prisms(run)) out += cells_line("prisms", "among the tetrahedra left", r.prisms, run.min_quality, conforming);
  if (with_pyramids(run)) out += cells_line("pyramids", "on quads facing two tetrahedra", r.pyramids, run.min_quality, conforming);
  out += fmt::format("conformity  {} quad faces of cells face triangles", r.quads_facing_triangles);
  if (with_pyramids(run)) out += fmt::format(" ({} with the pyramids left as tetrahedra)", r.quads_facing_triangles_before_pyramids);
  out += "\n";
  out += fmt::format("merge       {:.3f} s\n", r.merge_seconds);
  out += quality_text(run.quality);
  if (with_prisms(run) || with_pyramids(run))
    out += fmt::format(
        "result      {} hexes, {} prisms, {} pyramids, {} tetrahedra; {} darts ({} expected: 36 per hex + 24 per prism + 18 per pyramid + 12 per "
        "tetrahedron), {} ({:.3f} s)\n",
        r.hexes, r.prisms.cells.size(), r.pyramids.cells.size(), r.tets, run.darts, run.expected_darts, run.valid ? "valid" : "INVALID",
        run.output_check_seconds);
  else
    out += fmt::format("result      {} hexes, {} tetrahedra; {} darts ({} expected: 36 per hex + 12 per tetrahedron), {} ({:.3f} s)\n", r.hexes, r.tets,
                       run.darts, run.expected_darts, run.valid ? "valid" : "INVALID", run.output_check_seconds);
  out += fmt::format("time        {:.3f} s, {:.0f} tetrahedra per second; peak memory {:.1f} MiB\n", run.total_seconds, tets_per_second(run),
                     run.peak_mib);
  if (!run.output.empty()) out += fmt::format("written     {}\n", run.output);
  return out;
}

Json recombine_document(const RecombineRun& run) {
  const auto& r = run.result;
  const Quality q = quality_of(r.quality);
  Json doc = json_document("recombine");
  doc["mesh"] = run.mesh;
  doc["points"] = run.points;
  doc["tetrahedra"] = run.tets;
  doc["input_darts"] = run.input_darts;
  doc["strategy"] = run.strategy;
  doc["queries"] = run.queries;
  const bool words = r.search == querymodify::Search::words;
  doc["search"] = words ? "words" : "vertices";
  // Each search's own counts; null for the search that did not run.
  doc["raw_matches"] = words ? Json(r.raw_matches) : Json(nullptr);
  doc["distinct_matches"] = words ? Json(r.distinct_matches) : Json(nullptr);
  doc["candidates"] = words ? Json(nullptr) : Json(r.candidates);
  doc["readings"] = words ? Json(nullptr) : Json(r.readings);
  doc["acceptable_matches"] = r.acceptable;
  doc["min_quality"] = number_or_null(run.min_quality);
  const bool conforming = r.contacts == querymodify::Contacts::conforming;
  doc["conforming"] = conforming;
  // Candidates passed over for a non-conforming contact; null without --conforming.
  doc["nonconforming_candidates"] = conforming ? Json(r.nonconforming) : Json(nullptr);
  doc["hexes"] = r.hexes;
  doc["remaining_tetrahedra"] = r.tets;
  doc["darts"] = run.darts;
  doc["expected_darts"] = run.expected_darts;
  doc["valid"] = run.valid;
  doc["cells"] = run.cells;
  // The prisms' and pyramids' counts; null when --cells did not ask for them.
  auto cells = [&](bool asked, const querymodify::CellSelection& c) {
    if (!asked) return Json(nullptr);
    const Quality cq = quality_of(qualities(c));
    return Json{{"candidates", c.candidates},
                {"acceptable", c.acceptable},
                {"nonconforming", conforming ? Json(c.nonconforming) : Json(nullptr)},
                {"selected", c.cells.size()},
                {"quality_min", number_or_null(cq.min)},
                {"quality_median", number_or_null(cq.median)},
                {"seconds", c.seconds}};
  };
  doc["prisms"] = cells(with_prisms(run), r.prisms);
  doc["pyramids"] = cells(with_pyramids(run), r.pyramids);
  doc["quads_facing_triangles"] = r.quads_facing_triangles;
  doc["quads_facing_triangles_before_pyramids"] = with_pyramids(run) ? Json(r.quads_facing_triangles_before_pyramids) : Json(nullptr);
  doc["quality_min"] = number_or_null(q.min);
  doc["quality_median"] = number_or_null(q.median);
  doc["quality"] = quality_document(run.quality);
  doc["seconds"] = Json{{"read", run.read_seconds},
                        {"check_input", run.input_check_seconds},
                        {"queries", run.query_seconds},
                        {"match", r.match_seconds},
                        {"select", r.select_seconds},
                        {"merge", r.merge_seconds},
                        {"check_output", run.output_check_seconds},
                        {"total", run.total_seconds}};
  doc["tets_per_second"] = tets_per_second(run);
  doc["peak_mib"] = run.peak_mib;
  return doc;
}

namespace {

std::vector<std::size_t> per_query(const QueryRun& run) {
  std::vector<std::size_t> n(run.names.size(), 0);
  for (const auto& m : run.all->distinct) ++n[static_cast<std::size_t>(m.query)];
  return n;
}

}  // namespace

std::string query_text(const QueryRun& run) {
  const auto counts = per_query(run);
  const auto& shown = *run.shown;
  std::string out = fmt::format("map       {}: {} darts ({})\n", run.map, run.darts, run.model);
  out += fmt::format("queries   {} ({}prefix tree of {} nodes)\n", run.names.size(),
                     run.named_queries ? fmt::format("free links of the --query maps {}; ", run.free_symbol) : "", run.trie_nodes);
  for (std::size_t k = 0; k < run.names.size(); ++k)
    if (!run.hex || k < run.named_queries || counts[k] > 0)
      out += fmt::format("  {:<24} {:>4} darts  {} distinct matches\n", run.names[k], run.query_darts[k], counts[k]);
  out += fmt::format("matches   {} raw (found from every start dart), {} distinct ({:.3f} s)\n", run.all->raw, run.all->distinct.size(), run.seconds);
  if (run.strategy != "all")
    out += fmt::format("selected  {} without overlap ({})\n", shown.size(),
                       run.strategy == "greedy" ? "greedy: from each dart in order" : "global: largest first");
  const std::size_t listed = std::min(run.limit, shown.size());
  for (std::size_t k = 0; k < listed; ++k)
    out += fmt::format("  {}: darts {}\n", run.names[static_cast<std::size_t>(shown[k].query)], fmt::join(shown[k].darts, " "));
  if (listed < shown.size()) out += fmt::format("  ... {} more (--limit)\n", shown.size() - listed);
  return out;
}

Json query_document(const QueryRun& run) {
  const auto counts = per_query(run);
  const auto& shown = *run.shown;
  Json qs = Json::array(), ms = Json::array();
  for (std::size_t k = 0; k < run.names.size(); ++k)
    qs.push_back(Json{{"name", run.names[k]}, {"darts", run.query_darts[k]}, {"distinct_matches", counts[k]}});
  for (std::size_t k = 0; k < std::min(run.limit, shown.size()); ++k)
    ms.push_back(Json{{"query", run.names[static_cast<std::size_t>(shown[k].query)]}, {"darts", shown[k].darts}});
  Json doc = json_document("query");
  doc["map"] = run.map;
  doc["model"] = run.model;
  doc["darts"] = run.darts;
  doc["free"] = run.free;
  doc["strategy"] = run.strategy;
  doc["raw_matches"] = run.all->raw;
  doc["distinct_matches"] = run.all->distinct.size();
  doc["selected"] = shown.size();
  doc["seconds"] = run.seconds;
  doc["queries"] = std::move(qs);
  doc["matches"] = std::move(ms);
  return doc;
}

}  // namespace dartcheck::reports
