#include "io/vtk_writer.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/volume_cells.hpp"

namespace dartcheck {
namespace {

void check_fields(const VolumeCells& cells, const std::vector<CellField>& fields) {
  for (const CellField& f : fields)
    if (f.values.size() != cells.size())
      throw InternalError(fmt::format("cell field {} has {} values for {} cells", f.name, f.values.size(), cells.size()));
}

// A value as text: integers without a point, doubles in their shortest
// round-trip form (VTK reads both with strtod).
std::string value_text(const CellField& f, double v) { return f.integer ? fmt::format("{}", static_cast<long long>(v)) : fmt::format("{}", v); }

}  // namespace

void write_vtu(std::ostream& out, const TetMesh& m, const std::vector<CellField>& fields) {
  write_vtu(out, m.points, volume_cells(m, CornerConvention::vtk), fields);
}

void write_legacy_vtk(std::ostream& out, const TetMesh& m, const std::vector<CellField>& fields) {
  write_legacy_vtk(out, m.points, volume_cells(m, CornerConvention::vtk), fields);
}

void write_vtu(std::ostream& out, const Points& points, const VolumeCells& cells, const std::vector<CellField>& fields) {
  check_fields(cells, fields);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n";
  out << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", points.size(), cells.size());
  out << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : points) out << fmt::format("          {} {} {}\n", p[0], p[1], p[2]);
  out << "        </DataArray>\n      </Points>\n      <Cells>\n";
  out << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < cells.size(); ++k) {
    out << "         ";
    for (std::uint32_t v : cells.corners(k)) out << ' ' << v;
    out << '\n';
  }
  out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < cells.size(); ++k) out << "          " << cells.offset[k + 1] << '\n';
  out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < cells.size(); ++k) out << "          " << vtk_type(cells.kind[k]) << '\n';
  out << "        </DataArray>\n      </Cells>\n";
  if (!fields.empty()) {
    out << fmt::format("      <CellData Scalars=\"{}\">\n", fields.front().name);
    for (const CellField& f : fields) {
      out << fmt::format("        <DataArray type=\"{}\" Name=\"{}\" format=\"ascii\">\n", f.integer ? "Int32" : "Float64", f.name);
      for (double v : f.values) out << "          " << value_text(f, v) << '\n';
      out << "        </DataArray>\n";
    }
    out << "      </CellData>\n";
  }
  out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

void write_legacy_vtk(std::ostream& out, const Points& points, const VolumeCells& cells, const std::vector<CellField>& fields) {
  check_fields(cells, fields);
  out << "# vtk DataFile Version 3.0\ndartcheck mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << fmt::format("POINTS {} double\n", points.size());
  for (const auto& p : points) out << fmt::format("{} {} {}\n", p[0], p[1], p[2]);
  out << fmt::format("CELLS {} {}\n", cells.size(), cells.size() + cells.connectivity.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    out << cells.corners(k).size();
    for (std::uint32_t v : cells.corners(k)) out << ' ' << v;
    out << '\n';
  }
  out << fmt::format("CELL_TYPES {}\n", cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) out << vtk_type(cells.kind[k]) << '\n';
  if (fields.empty()) return;
  out << fmt::format("CELL_DATA {}\n", cells.size());
  for (const CellField& f : fields) {
    out << fmt::format("SCALARS {} {} 1\nLOOKUP_TABLE default\n", f.name, f.integer ? "int" : "double");
    for (double v : f.values) out << value_text(f, v) << '\n';
  }
}

}  // namespace dartcheck
