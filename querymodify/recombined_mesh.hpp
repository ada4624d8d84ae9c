// The recombination of a tetrahedral mesh file (`dartcheck recombine`):
// read, checked, recombined (001 Sec. 7.1), checked again, its quality
// measured and written (medit, VTK or gmsh: io/volume_mesh_writer.hpp)
// with the hexahedra, prisms, pyramids and the tetrahedra left, with the
// time of each phase.
#pragma once

#include <string>

#include "io/tet_mesh_io.hpp"
#include "io/volume_mesh_writer.hpp"
#include "querymodify/mesh_quality.hpp"
#include "querymodify/recombination.hpp"

namespace dartcheck::querymodify {

/// greedy or global (--strategy); InputError otherwise.
Strategy parse_strategy(const std::string& text);
/// vertices or words (--search); InputError otherwise.
Search parse_search(const std::string& text);
/// A comma-separated list of hex, prism, pyramid that names hex (--cells);
/// InputError otherwise.
Cells parse_cells(const std::string& text);
/// InputError when `conforming` is asked of the greedy strategy or the
/// word search.
void check_contacts(Strategy strategy, Search search, bool conforming);

/// One recombination: its input, what the library returned, the checks
/// and the times around it.
struct RecombineRun {
  std::string mesh, strategy, search, output;  // output: the written file, or empty
  std::size_t points = 0, tets = 0, input_darts = 0, queries = 0;
  double min_quality = 0;
  bool input_valid = false;  // the input's map (build_tet_map makes valid maps of every mesh it accepts)
  Recombination result;
  std::string cells = "hex";                  // --cells as given
  std::size_t darts = 0, expected_darts = 0;  // after the merges; 36 per hex, 24 per prism, 18 per pyramid, 12 per tetrahedron
  bool valid = false;
  double read_seconds = 0, input_check_seconds = 0, query_seconds = 0, output_check_seconds = 0, total_seconds = 0;
  double peak_mib = 0;  // the process's peak resident memory
  /// The output mesh's quality (of every cell, hexahedra first as written).
  QualitySummary quality;
  /// The result is a valid map of 36 darts per hex (its 12 boundary
  /// triangles), 24 per prism (8), 18 per pyramid (6) and 12 per
  /// tetrahedron.
  bool sound() const { return input_valid && valid && darts == expected_darts; }
};

/// Recombines the mesh in `mesh` (TetGen .node/.ele, medit .mesh or gmsh
/// .msh) and writes the result to `output` unless it is empty, in the
/// format its extension names (gmsh's version `gmsh` for .msh), with each
/// cell's scaled Jacobian and VTK type as cell data where the format has it. With an invalid input
/// map (a defect of the reader) nothing is recombined.
/// `conforming` (hex_contacts.hpp) needs the global strategy's vertex
/// search; InputError otherwise.
/// `cells` (parse_cells) adds prisms and pyramids after the hexes.
/// `progress` hears each stage (recombination.hpp).
RecombineRun recombine_mesh(const std::string& mesh, const std::string& strategy, double min_quality, const std::string& output,
                            const std::string& search = "vertices", bool conforming = false, const std::string& cells = "hex",
                            const Progress& progress = {}, GmshVersion gmsh = GmshVersion::v41);

/// The hexes, prisms and pyramids of `r` (medit's corner orders) and the
/// tetrahedra it left, on `input`'s points.
TetMesh recombined_mesh(const TetMesh& input, const Recombination& r);

}  // namespace dartcheck::querymodify
