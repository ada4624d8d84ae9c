// dartcheck recombine: tetrahedra -> hexahedra by query-modify (001 Sec.
// 7.1): every match of the 322 hex queries, a selection (greedy or global
// by scaled Jacobian), each selected match merged into one volume, the
// result checked and optionally written as a medit mesh of hexes and
// tetrahedra.
#include <sstream>

#include <fmt/format.h>

#include <sys/resource.h>

#include <chrono>
#include <filesystem>

#include "campaign/shard_stream.hpp"
#include "cli/commands.hpp"
#include "reports/querymodify_report.hpp"
#include "querymodify/tet_input.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "querymodify/map_checks.hpp"
#include "querymodify/recombination.hpp"

namespace dartcheck::cli {

using querymodify::load_tet_input;
using querymodify::TetInput;

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

Strategy parse_strategy(const std::string& s) {
  if (s == "greedy") return Strategy::greedy;
  if (s == "global") return Strategy::global;
  throw InputError("<command line>", 0, 0, fmt::format("--strategy: expected greedy or global, got '{}'", s));
}

// The hexes (medit order) and the tetrahedra left, on the input's points.
void write_hexes(const std::string& file, const TetMesh& input, const Recombination& r) {
  TetMesh out;
  out.points = input.points;
  for (std::size_t k : r.remaining_tets) out.tets.push_back(input.tets[k]);
  for (const auto& c : r.hex_corners) out.hexes.push_back(medit_order(c));
  std::ostringstream text;
  write_medit(text, out);
  write_file(file, text.str());
}

}  // namespace

int recombine(const RecombineOptions& o) {
  if (o.format != "text" && o.format != "json" && o.format != "jsonl")
    throw InputError("<command line>", 0, 0, fmt::format("--format: expected text, json or jsonl, got '{}'", o.format));
  if (!o.output.empty()) check_writable(o.output);  // before the work, not after it
  const Strategy strategy = parse_strategy(o.strategy);
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
  if (!o.output.empty()) write_hexes(o.output, in.mesh, r);
  const reports::RecombineRun run{o.mesh,
                                  o.strategy,
                                  o.output,
                                  in.mesh.points.size(),
                                  tets_in,
                                  darts_in,
                                  queries.size(),
                                  o.min_quality,
                                  &r,
                                  in.map.map.size(),
                                  expected_darts,
                                  output_check.valid(),
                                  read_seconds,
                                  input_check_seconds,
                                  query_seconds,
                                  output_check_seconds,
                                  since(start),
                                  peak_mib()};
  const int status = output_check.valid() && darts_ok ? ok : soundness_bug;
  if (o.format == "jsonl") {
    // One run of a campaign over many meshes (docs/scale.md): merge gathers them.
    campaign::ShardWriter lines(
        campaign::make_header("recombine", o.mesh, "", "", {}, reports::Json{{"strategy", o.strategy}, {"min_quality", o.min_quality}}));
    lines.input(reports::recombine_document(run), reports::recombine_text(run));
    lines.summary(reports::Json{{"status", status}});
  } else if (o.format == "json") {
    fmt::print("{}\n", reports::json_text(reports::recombine_document(run)));
  } else {
    fmt::print("{}", reports::recombine_text(run));
  }
  if (status != ok) {
    fmt::print(stderr, "BUG: the recombined map is {} ({} darts, {} expected)\n", output_check.valid() ? "valid" : "invalid", in.map.map.size(),
               expected_darts);
  }
  return status;
}

}  // namespace dartcheck::cli
