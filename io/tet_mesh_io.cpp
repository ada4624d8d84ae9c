#include "io/tet_mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "io/gmsh_msh.hpp"
#include "io/line_reader.hpp"

namespace dartcheck {
namespace {

using text_mesh::Line;
using text_mesh::LineReader;
using text_mesh::number;

std::string extension(const std::string& file) { return std::filesystem::path(file).extension().string(); }

Line need_line(LineReader& r, const std::string& what) {
  auto l = r.next();
  if (!l) r.fail(r.line(), 0, fmt::format("the file ends before {}", what));
  return *l;
}

// Vertices are named in messages as the file numbers them (from `base`).
void check_tet(const LineReader& r, const Line& l, const std::array<std::uint32_t, 4>& t, long base, int first_column) {
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t j = 0; j < k; ++j)
      if (t[j] == t[k]) r.fail(l.number, first_column, fmt::format("a tetrahedron repeats vertex {}", static_cast<long>(t[k]) + base));
}

// A vertex index of the file (numbered from `base`) as a 0-based point,
// refused out of range before any narrowing (2^32 + 5 is not 5).
std::uint32_t vertex_index(const LineReader& r, const Line& l, std::size_t k, long base, std::size_t points) {
  const auto v = number<long long>(r, l, k, "a vertex index");
  if (v < base || v - base >= static_cast<long long>(points))
    r.fail(l.number, l.tokens[k].second,
           points ? fmt::format("vertex index {} out of range {}..{}", v, base, base + static_cast<long long>(points) - 1)
                  : fmt::format("vertex index {}: there are no points", v));
  return static_cast<std::uint32_t>(v - base);
}

// A coordinate: finite (NaN and infinities would end in the output mesh and
// in JSON).
double coordinate(const LineReader& r, const Line& l, std::size_t k, const char* name) {
  const double x = number<double>(r, l, k, name);
  if (!std::isfinite(x)) r.fail(l.number, l.tokens[k].second, fmt::format("{} is not a finite number ({})", name, l.tokens[k].first));
  return x;
}

// The end of a counted file: a count smaller than the data would drop the
// rest unseen.
void refuse_more(LineReader& r, long count, const char* what, int header_line) {
  if (const auto extra = r.next())
    r.fail(extra->number, extra->tokens[0].second,
           fmt::format("data after the {} {} the header announces (line {}): the count is smaller than the data", count, what, header_line));
}

}  // namespace

bool is_tet_mesh_path(const std::string& file) {
  const auto e = extension(file);
  return e == ".node" || e == ".ele" || e == ".mesh" || e == ".msh";
}

TetMesh read_tetgen(const std::string& file) {
  const std::filesystem::path base = std::filesystem::path(file).replace_extension();
  const std::string node = base.string() + ".node", ele = base.string() + ".ele";
  TetMesh m;
  m.file = file;
  long first_index = 0;
  {
    LineReader r(node);
    const Line h = need_line(r, "the .node header");
    const auto count = number<long>(r, h, 0, "the number of points");
    if (count < 0) r.fail(h.number, h.tokens[0].second, "a negative number of points");
    if (h.tokens.size() > 1 && number<int>(r, h, 1, "the dimension") != 3)
      r.fail(h.number, h.tokens[1].second, "only 3-dimensional .node files are read");
    for (long k = 0; k < count; ++k) {
      const Line l = need_line(r, fmt::format("point {} of {}", k + 1, count));
      const auto index = number<long>(r, l, 0, "a point index");
      if (k == 0) first_index = index;
      if (k == 0 && index != 0 && index != 1)
        r.fail(l.number, l.tokens[0].second, fmt::format("point index {}: point indices start at 0 or 1", index));
      if (index != first_index + k)
        r.fail(l.number, l.tokens[0].second, fmt::format("point index {} out of sequence (expected {})", index, first_index + k));
      m.points.push_back({coordinate(r, l, 1, "x"), coordinate(r, l, 2, "y"), coordinate(r, l, 3, "z")});
    }
    refuse_more(r, count, "points", h.number);
  }
  m.numbered_from = static_cast<std::uint32_t>(first_index);
  LineReader r(ele);
  const Line h = need_line(r, "the .ele header");
  const auto count = number<long>(r, h, 0, "the number of tetrahedra");
  if (count < 0) r.fail(h.number, h.tokens[0].second, "a negative number of tetrahedra");
  const int per = h.tokens.size() > 1 ? number<int>(r, h, 1, "the nodes per tetrahedron") : 4;
  if (per != 4 && per != 10) r.fail(h.number, h.tokens[1].second, fmt::format("{} nodes per tetrahedron (expected 4 or 10)", per));
  for (long k = 0; k < count; ++k) {
    const Line l = need_line(r, fmt::format("tetrahedron {} of {}", k + 1, count));
    std::array<std::uint32_t, 4> t{};
    for (std::size_t j = 0; j < 4; ++j) t[j] = vertex_index(r, l, j + 1, first_index, m.points.size());
    check_tet(r, l, t, first_index, l.tokens[1].second);
    m.tets.push_back(t);
    m.tet_lines.push_back(l.number);
  }
  refuse_more(r, count, "tetrahedra", h.number);
  return m;
}

TetMesh read_medit(const std::string& file) {
  LineReader r(file);
  TetMesh m;
  m.file = file;
  m.numbered_from = 1;
  bool vertices = false;
  // A cell of N vertices (hexahedron, prism, pyramid), 1-based.
  auto cell = [&]<std::size_t N>(const Line& e, std::vector<std::array<std::uint32_t, N>>& into) {
    if (!vertices) r.fail(e.number, 1, "cells before Vertices");
    std::array<std::uint32_t, N> c{};
    for (std::size_t j = 0; j < N; ++j) c[j] = vertex_index(r, e, j, 1, m.points.size());
    into.push_back(c);
  };
  while (auto l = r.next()) {
    const std::string key(l->tokens[0].first);  // a copy: the next line overwrites the reader's buffer
    if (key == "End") break;
    // Sections are named by words; a number here is an entry beyond its section's count.
    if (!std::isalpha(static_cast<unsigned char>(key[0])))
      r.fail(l->number, l->tokens[0].second,
             fmt::format("'{}' where a section name (Vertices, Tetrahedra, ...) or End was expected: the previous section has more "
                         "entries than its count",
                         printable(key)));
    if (key == "MeshVersionFormatted" || key == "Dimension") {
      if (key == "Dimension") {
        const Line& d = l->tokens.size() > 1 ? *l : need_line(r, "the dimension");
        const std::size_t k = l->tokens.size() > 1 ? 1 : 0;
        if (number<int>(r, d, k, "the dimension") != 3) r.fail(d.number, d.tokens[k].second, "only 3-dimensional meshes are read");
      }
      continue;
    }
    // A section: its count, then that many lines.
    const Line c = need_line(r, fmt::format("the size of section {}", key));
    const auto count = number<long>(r, c, 0, fmt::format("the size of section {}", key));
    if (count < 0) r.fail(c.number, c.tokens[0].second, "a negative section size");
    for (long k = 0; k < count; ++k) {
      const Line e = need_line(r, fmt::format("entry {} of {} in {}", k + 1, count, key));
      if (key == "Vertices") {
        m.points.push_back({coordinate(r, e, 0, "x"), coordinate(r, e, 1, "y"), coordinate(r, e, 2, "z")});
      } else if (key == "Tetrahedra") {
        if (!vertices) r.fail(e.number, 1, "Tetrahedra before Vertices");
        std::array<std::uint32_t, 4> t{};
        for (std::size_t j = 0; j < 4; ++j) t[j] = vertex_index(r, e, j, 1, m.points.size());
        check_tet(r, e, t, 1, e.tokens[0].second);
        m.tets.push_back(t);
        m.tet_lines.push_back(e.number);
      } else if (key == "Hexahedra") {
        cell(e, m.hexes);
      } else if (key == "Prisms") {
        cell(e, m.prisms);
      } else if (key == "Pyramids") {
        cell(e, m.pyramids);
      }
    }
    if (key == "Vertices") vertices = true;
  }
  if (m.tets.empty() && m.hexes.empty() && m.prisms.empty() && m.pyramids.empty())
    r.fail(r.line(), 0, "no Tetrahedra, Hexahedra, Prisms or Pyramids section");
  return m;
}

void write_medit(std::ostream& out, const TetMesh& m) {
  out << "MeshVersionFormatted 1\nDimension 3\n";
  out << fmt::format("Vertices\n{}\n", m.points.size());
  for (const auto& p : m.points) out << fmt::format("{} {} {} 0\n", p[0], p[1], p[2]);
  if (!m.tets.empty()) {
    out << fmt::format("Tetrahedra\n{}\n", m.tets.size());
    for (const auto& t : m.tets) out << fmt::format("{} {} {} {} 0\n", t[0] + 1, t[1] + 1, t[2] + 1, t[3] + 1);
  }
  // Each cell's vertices 1-based, then the reference 0.
  auto section = [&](const char* name, const auto& cells) {
    if (cells.empty()) return;
    out << fmt::format("{}\n{}\n", name, cells.size());
    for (const auto& c : cells) {
      for (auto v : c) out << v + 1 << ' ';
      out << "0\n";
    }
  };
  section("Hexahedra", m.hexes);
  section("Prisms", m.prisms);
  section("Pyramids", m.pyramids);
  out << "End\n";
}

TetMesh read_tet_mesh(const std::string& file) {
  const auto e = extension(file);
  if (e == ".mesh") return read_medit(file);
  if (e == ".node" || e == ".ele") return read_tetgen(file);
  if (e == ".msh") return read_gmsh(file);
  throw InputError(file, 0, 0, "unknown tetrahedral mesh type (expected .node, .ele, .mesh or .msh)");
}

}  // namespace dartcheck
