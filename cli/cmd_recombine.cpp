// dartcheck recombine: tetrahedra -> hexahedra by query-modify (001 Sec.
// 7.1): every match of the 322 hex queries, a selection (greedy or global
// by scaled Jacobian), each selected match merged into one volume, the
// result checked and optionally written as a medit mesh of hexes and
// tetrahedra.
#include <sstream>

#include <fmt/format.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/report_text.hpp"
#include "reports/json_document.hpp"
#include "cli/tet_input.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "querymodify/map_checks.hpp"
#include "querymodify/recombination.hpp"

namespace dartcheck::cli {

using namespace querymodify;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double peak_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // KiB on Linux
}

// medit's hexahedron order: the bottom quad (z = 0) as a cycle, then the
// top quad above it. Corner v = x + 2y + 4z.
std::array<std::uint32_t, 8> medit_order(const std::array<std::uint32_t, 8>& c) { return {c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6]}; }

}  // namespace

int recombine(const RecombineOptions& o) {
  if (o.format != "text" && o.format != "json")
    throw InputError("<command line>", 0, 0, fmt::format("--format: expected text or json, got '{}'", o.format));
  if (!o.output.empty()) check_writable(o.output);  // before the work, not after it
  Strategy strategy;
  if (o.strategy == "greedy")
    strategy = Strategy::greedy;
  else if (o.strategy == "global")
    strategy = Strategy::global;
  else
    throw InputError("<command line>", 0, 0, fmt::format("--strategy: expected greedy or global, got '{}'", o.strategy));
  if (!o.output.empty() && std::filesystem::path(o.output).extension() != ".mesh")
    throw InputError("<command line>", 0, 0, fmt::format("-o: expected a medit .mesh file, got '{}'", o.output));
  const auto start = Clock::now();
  auto t = Clock::now();
  TetInput in = load_tet_input(o.mesh);
  const double read_seconds = since(t);
  const std::size_t tets_in = in.mesh.tets.size(), darts_in = in.map.map.size();
  t = Clock::now();
  const ValidityReport input_check = check_3map(in.map.map);
  const double input_check_seconds = since(t);
  if (!input_check.valid()) {
    // build_tet_map makes valid maps of every mesh it accepts.
    fmt::print(stderr, "BUG: the map of {} is not a valid open 3-O-map ({} violations)\n", o.mesh, input_check.violations.size());
    return soundness_bug;
  }
  t = Clock::now();
  const auto& queries = hex_queries();
  const double query_seconds = since(t);
  const Recombination r = querymodify::recombine(in.map, queries, strategy, &in.mesh.points, o.min_quality);
  t = Clock::now();
  const ValidityReport output_check = check_3map(in.map.map);
  const double output_check_seconds = since(t);
  const std::size_t expected_darts = 36 * r.hexes + 12 * r.tets;
  const bool darts_ok = in.map.map.size() == expected_darts;
  std::vector<double> q = r.quality;
  std::sort(q.begin(), q.end());
  const double q_min = q.empty() ? NAN : q.front(), q_median = q.empty() ? NAN : q[q.size() / 2];
  if (!o.output.empty()) {
    TetMesh out;
    out.points = in.mesh.points;
    for (std::size_t k : r.remaining_tets) out.tets.push_back(in.mesh.tets[k]);
    for (const auto& c : r.hex_corners) out.hexes.push_back(medit_order(c));
    std::ostringstream text;
    write_medit(text, out);
    write_file(o.output, text.str());
  }
  const double total = since(start);
  const double tets_per_second = total > 0 ? static_cast<double>(tets_in) / total : 0;
  if (o.format == "json") {
    using reports::Json;
    const auto number_or_null = [](double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); };
    Json doc = reports::json_document("recombine");
    doc["mesh"] = o.mesh;
    doc["points"] = in.mesh.points.size();
    doc["tetrahedra"] = tets_in;
    doc["input_darts"] = darts_in;
    doc["strategy"] = o.strategy;
    doc["queries"] = queries.size();
    doc["raw_matches"] = r.raw_matches;
    doc["distinct_matches"] = r.distinct_matches;
    doc["acceptable_matches"] = r.acceptable;
    doc["min_quality"] = number_or_null(o.min_quality);
    doc["hexes"] = r.hexes;
    doc["remaining_tetrahedra"] = r.tets;
    doc["darts"] = in.map.map.size();
    doc["expected_darts"] = expected_darts;
    doc["valid"] = output_check.valid();
    doc["quality_min"] = number_or_null(q_min);
    doc["quality_median"] = number_or_null(q_median);
    doc["seconds"] = Json{{"read", read_seconds},
                          {"check_input", input_check_seconds},
                          {"queries", query_seconds},
                          {"match", r.match_seconds},
                          {"select", r.select_seconds},
                          {"merge", r.merge_seconds},
                          {"check_output", output_check_seconds},
                          {"total", total}};
    doc["tets_per_second"] = tets_per_second;
    doc["peak_mib"] = peak_mib();
    fmt::print("{}\n", reports::json_text(std::move(doc)));
  } else {
    fmt::print("mesh        {}: {} points, {} tetrahedra ({:.3f} s)\n", o.mesh, in.mesh.points.size(), tets_in, read_seconds);
    fmt::print("input map   {} darts (12 per tetrahedron), a valid open 3-O-map ({:.3f} s)\n", darts_in, input_check_seconds);
    fmt::print("queries     {} hex patterns, both hands of the 174 classes ({:.3f} s)\n", queries.size(), query_seconds);
    fmt::print("matches     {} raw, {} distinct, {} with 8 distinct corners and scaled Jacobian above {} ({:.3f} s)\n", r.raw_matches,
               r.distinct_matches, r.acceptable, o.min_quality, r.match_seconds);
    fmt::print("selection   {} hexes, {} ({:.3f} s)\n", r.hexes,
               strategy == Strategy::greedy ? "greedy: the first match from each dart in order" : "global: by scaled Jacobian, best first",
               r.select_seconds);
    if (!q.empty()) fmt::print("quality     scaled Jacobian of the hexes: min {:.3f}, median {:.3f}\n", q_min, q_median);
    fmt::print("merge       {:.3f} s\n", r.merge_seconds);
    fmt::print("result      {} hexes, {} tetrahedra; {} darts ({} expected: 36 per hex + 12 per tetrahedron), {} ({:.3f} s)\n", r.hexes, r.tets,
               in.map.map.size(), expected_darts, output_check.valid() ? "valid" : "INVALID", output_check_seconds);
    fmt::print("time        {:.3f} s, {:.0f} tetrahedra per second; peak memory {:.1f} MiB\n", total, tets_per_second, peak_mib());
    if (!o.output.empty()) fmt::print("written     {}\n", o.output);
  }
  if (!output_check.valid() || !darts_ok) {
    fmt::print(stderr, "BUG: the recombined map is {} ({} darts, {} expected)\n", output_check.valid() ? "valid" : "invalid", in.map.map.size(),
               expected_darts);
    return soundness_bug;
  }
  return ok;
}

}  // namespace dartcheck::cli
