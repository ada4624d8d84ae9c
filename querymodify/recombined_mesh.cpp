#include "querymodify/recombined_mesh.hpp"

#include <sys/resource.h>

#include <chrono>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "querymodify/hex_queries.hpp"
#include "querymodify/map_checks.hpp"
#include "querymodify/tet_input.hpp"

namespace dartcheck::querymodify {

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

Strategy parse_strategy(const std::string& s) {
  if (s == "greedy") return Strategy::greedy;
  if (s == "global") return Strategy::global;
  throw UsageError(fmt::format("--strategy: expected greedy or global, got '{}'", s));
}

Search parse_search(const std::string& s) {
  if (s == "vertices") return Search::vertices;
  if (s == "words") return Search::words;
  throw UsageError(fmt::format("--search: expected vertices or words, got '{}'", s));
}

Cells parse_cells(const std::string& text) {
  Cells c;
  bool hex = false;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string word = text.substr(start, end - start);
    if (word == "hex")
      hex = true;
    else if (word == "prism")
      c.prisms = true;
    else if (word == "pyramid")
      c.pyramids = true;
    else
      throw UsageError(fmt::format("--cells: expected a comma-separated list of hex, prism and pyramid, got '{}' in '{}'", word, text));
    start = end + 1;
  }
  if (!hex) throw UsageError(fmt::format("--cells: the list must name hex (prisms and pyramids fill in around hexes), got '{}'", text));
  return c;
}

void check_contacts(Strategy strategy, Search search, bool conforming) {
  if (conforming && (strategy == Strategy::greedy || search == Search::words))
    throw UsageError("--conforming: only with the global strategy's vertex search (--strategy global --search vertices)");
}

TetMesh recombined_mesh(const TetMesh& input, const Recombination& r) {
  TetMesh out;
  out.points = input.points;
  for (std::size_t k : r.remaining_tets) out.tets.push_back(input.tets[k]);
  for (const auto& c : r.hex_corners) out.hexes.push_back(medit_order(c));
  // cell_subdivisions.hpp's corners are medit's orders already.
  for (const auto& c : r.prisms.cells) out.prisms.push_back({c.corners[0], c.corners[1], c.corners[2], c.corners[3], c.corners[4], c.corners[5]});
  for (const auto& c : r.pyramids.cells) out.pyramids.push_back({c.corners[0], c.corners[1], c.corners[2], c.corners[3], c.corners[4]});
  return out;
}

RecombineRun recombine_mesh(const std::string& mesh, const std::string& strategy, double min_quality, const std::string& output,
                            const std::string& search, bool conforming, const std::string& cells, const Progress& progress, GmshVersion gmsh) {
  const auto stage = [&](std::string_view what) {
    if (progress) progress(what, 0, 0);
  };
  RecombineRun run;
  run.mesh = mesh;
  run.strategy = strategy;
  run.min_quality = min_quality;
  const Strategy chosen = parse_strategy(strategy);
  const Search searched = parse_search(search);
  check_contacts(chosen, searched, conforming);
  const Cells made = parse_cells(cells);
  run.cells = cells;
  const auto start = Clock::now();
  auto t = Clock::now();
  stage("reading the mesh");
  TetInput in = load_tet_input(mesh);
  run.read_seconds = since(t);
  run.points = in.mesh.points.size();
  run.tets = in.mesh.tets.size();
  run.input_darts = in.map.map.size();
  t = Clock::now();
  stage("checking the input map");
  run.input_valid = check_3map(in.map.map).valid();
  run.input_check_seconds = since(t);
  if (!run.input_valid) return run;
  t = Clock::now();
  // The queries only for the word search (greedy, or --search words).
  static const std::vector<HexQuery> none;
  const auto& queries = chosen == Strategy::greedy || searched == Search::words ? hex_queries() : none;
  run.queries = queries.size();
  run.query_seconds = since(t);
  run.result = recombine(in.map, queries, chosen, &in.mesh.points, min_quality, searched, conforming ? Contacts::conforming : Contacts::any,
                         made, progress);
  run.search = run.result.search == Search::words ? "words" : "vertices";
  t = Clock::now();
  stage("checking the recombined map");
  run.valid = check_3map(in.map.map).valid();
  run.output_check_seconds = since(t);
  run.darts = in.map.map.size();
  run.expected_darts = 36 * run.result.hexes + 24 * run.result.prisms.cells.size() + 18 * run.result.pyramids.cells.size() + 12 * run.result.tets;
  const TetMesh result = recombined_mesh(in.mesh, run.result);
  const std::vector<double> quality = cell_qualities(result);
  run.quality = summarize_quality(result, quality);
  if (!output.empty()) {
    stage("writing the mesh");
    std::vector<double> types;
    for (CellKind k : volume_cells(result, CornerConvention::vtk).kind) types.push_back(vtk_type(k));
    write_file(output, volume_mesh_text(result, output, {{"scaled_jacobian", quality, false}, {"vtk_cell_type", types, true}}, gmsh));
    run.output = output;
  }
  run.total_seconds = since(start);
  run.peak_mib = peak_mib();
  return run;
}

}  // namespace dartcheck::querymodify
