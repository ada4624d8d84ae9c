#include "io/gmsh_msh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "core/error.hpp"
#include "io/line_reader.hpp"
#include "io/volume_cells.hpp"

namespace dartcheck {
namespace {

using text_mesh::Line;
using text_mesh::LineReader;
using text_mesh::number;

// The nodes of gmsh's element types up to 19 (0: not one of them), and the
// volume cell a type is read as: its first 4, 5, 6 or 8 nodes.
int element_nodes(long type) {
  static constexpr int nodes[] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13};
  return type >= 0 && type < 20 ? nodes[type] : 0;
}
enum class Volume { none, tet, hex, prism, pyramid };
Volume volume_of(long type) {
  switch (type) {
    case 4: case 11: return Volume::tet;
    case 5: case 12: case 17: return Volume::hex;
    case 6: case 13: case 18: return Volume::prism;
    case 7: case 14: case 19: return Volume::pyramid;
    default: return Volume::none;
  }
}

class Reader {
 public:
  explicit Reader(const std::string& file) : r_(file) { m_.file = file; }

  TetMesh read() {
    bool format = false, nodes = false;
    while (auto l = r_.next()) {
      const std::string name(l->tokens[0].first);
      if (name.empty() || name[0] != '$')
        r_.fail(l->number, l->tokens[0].second, fmt::format("'{}' where a section ($MeshFormat, $Nodes, $Elements, ...) was expected", printable(name)));
      if (!format && name != "$MeshFormat") r_.fail(l->number, l->tokens[0].second, "a .msh file starts with $MeshFormat");
      if (name == "$MeshFormat") {
        mesh_format();
        format = true;
      } else if (name == "$Nodes") {
        v4_ ? nodes_v4() : nodes_v2();
        nodes = true;
      } else if (name == "$Elements") {
        if (!nodes) r_.fail(l->number, l->tokens[0].second, "$Elements before $Nodes");
        v4_ ? elements_v4() : elements_v2();
      } else {
        skip_section(name, *l);
      }
    }
    if (!format) r_.fail(r_.line(), 0, "no $MeshFormat: not a gmsh .msh file");
    if (m_.tets.empty() && m_.hexes.empty() && m_.prisms.empty() && m_.pyramids.empty())
      r_.fail(r_.line(), 0, "no tetrahedra, hexahedra, prisms or pyramids (gmsh element types 4 to 7, 11 to 14, 17 to 19)");
    return std::move(m_);
  }

 private:
  Line need(const std::string& what) {
    auto l = r_.next();
    if (!l) r_.fail(r_.line(), 0, fmt::format("the file ends before {}", what));
    return *l;
  }
  // The section's end line; anything else there is data beyond its counts.
  void end(const std::string& section, long count, const char* what, int header) {
    const Line l = need("$End" + section);
    if (l.tokens[0].first != "$End" + section)
      r_.fail(l.number, l.tokens[0].second,
              fmt::format("'{}' where $End{} was expected: the section has more data than the {} {} its header announces (line {})",
                          printable(std::string(l.tokens[0].first)), section, count, what, header));
  }
  void skip_section(const std::string& name, const Line& start) {
    const std::string closing = "$End" + name.substr(1);
    while (auto l = r_.next())
      if (l->tokens[0].first == closing) return;
    r_.fail(r_.line(), 0, fmt::format("section {} (line {}) has no {}", name, start.number, closing));
  }
  long count(const Line& l, std::size_t k, const std::string& what) {
    const auto n = number<long long>(r_, l, k, what);
    if (n < 0 || n > std::numeric_limits<std::uint32_t>::max()) r_.fail(l.number, l.tokens[k].second, fmt::format("{} {} out of range", what, n));
    return static_cast<long>(n);
  }

  void mesh_format() {
    const Line l = need("the format's version");
    const std::string version(l.tokens[0].first);
    if (version.starts_with("4")) {
      if (version != "4.1") r_.fail(l.number, l.tokens[0].second, fmt::format("gmsh format {}: only 4.1 and 2.2 are read", version));
      v4_ = true;
    } else if (!version.starts_with("2.")) {
      r_.fail(l.number, l.tokens[0].second, fmt::format("gmsh format {}: only 4.1 and 2.2 are read", printable(version)));
    }
    if (number<int>(r_, l, 1, "the file type (0 for ASCII)") != 0)
      r_.fail(l.number, l.tokens[1].second, "a binary .msh file: save it as ASCII (gmsh -save -format msh4 or Mesh.Binary = 0)");
    end("MeshFormat", 1, "line", l.number);
  }

  void add_node(const Line& tag_line, std::size_t k, std::uint64_t tag) {
    if (!index_.emplace(tag, static_cast<std::uint32_t>(index_.size())).second)
      r_.fail(tag_line.number, tag_line.tokens[k].second, fmt::format("node tag {} given twice", tag));
  }
  std::array<double, 3> coordinates(const Line& l, std::size_t first) {
    std::array<double, 3> p{};
    for (std::size_t c = 0; c < 3; ++c) {
      p[c] = number<double>(r_, l, first + c, "a coordinate");
      if (!std::isfinite(p[c])) r_.fail(l.number, l.tokens[first + c].second, fmt::format("a coordinate is not a finite number ({})", l.tokens[first + c].first));
    }
    return p;
  }

  void nodes_v2() {
    const Line h = need("the number of nodes");
    const long n = count(h, 0, "the number of nodes");
    for (long k = 0; k < n; ++k) {
      const Line l = need(fmt::format("node {} of {}", k + 1, n));
      add_node(l, 0, number<std::uint64_t>(r_, l, 0, "a node tag"));
      m_.points.push_back(coordinates(l, 1));
    }
    end("Nodes", n, "nodes", h.number);
  }

  // A 4.1 section: a header "blocks total min max", then blocks whose
  // header line gives at token 3 how many entries follow it; `read` reads
  // a block's entries from its header line. The totals must agree.
  template <class Read>
  void blocks_v4(const std::string& section, const char* entries, const Read& read) {
    const Line h = need(fmt::format("the ${} header", section));
    const long blocks = count(h, 0, "the number of entity blocks"), n = count(h, 1, fmt::format("the number of {}", entries));
    long seen = 0;
    for (long b = 0; b < blocks; ++b) {
      const Line bl = need(fmt::format("entity block {} of {} in ${}", b + 1, blocks, section));
      const long in_block = count(bl, 3, fmt::format("the number of {} in the block", entries));
      if (seen + in_block > n)
        r_.fail(bl.number, bl.tokens[3].second, fmt::format("the blocks hold more than the {} {} the header announces (line {})", n, entries, h.number));
      read(bl, b, in_block);
      seen += in_block;
    }
    if (seen != n) r_.fail(h.number, h.tokens[1].second, fmt::format("the header announces {} {}, the blocks hold {}", n, entries, seen));
    end(section, blocks, "entity blocks", h.number);
  }

  void nodes_v4() {
    blocks_v4("Nodes", "nodes", [&](const Line& bl, long b, long in_block) {
      const int dim = number<int>(r_, bl, 0, "the entity's dimension");
      if (dim < 0 || dim > 3) r_.fail(bl.number, bl.tokens[0].second, fmt::format("an entity of dimension {} (0 to 3)", dim));
      const bool parametric = number<int>(r_, bl, 2, "the parametric flag") != 0;
      for (long k = 0; k < in_block; ++k) {
        const Line l = need(fmt::format("node tag {} of block {}", k + 1, b + 1));
        add_node(l, 0, number<std::uint64_t>(r_, l, 0, "a node tag"));
      }
      for (long k = 0; k < in_block; ++k) {
        const Line l = need(fmt::format("the coordinates of node {} of block {}", k + 1, b + 1));
        if (l.tokens.size() != 3 + (parametric ? static_cast<std::size_t>(dim) : 0))
          r_.fail(l.number, l.tokens[0].second, fmt::format("expected {} numbers (x y z{}), got {}", 3 + (parametric ? dim : 0), parametric ? " and the parameters" : "", l.tokens.size()));
        m_.points.push_back(coordinates(l, 0));
      }
    });
  }

  // One element line: its nodes from token `first` on, read as a cell of
  // `type` when it is a volume (other types are skipped unread).
  void element(const Line& l, long type, std::size_t first) {
    const Volume v = volume_of(type);
    if (v == Volume::none) return;
    const auto nodes = static_cast<std::size_t>(element_nodes(type));
    if (l.tokens.size() != first + nodes)
      r_.fail(l.number, l.tokens[0].second, fmt::format("an element of type {} has {} nodes, the line gives {}", type, nodes, l.tokens.size() - first));
    auto corner = [&](std::size_t j) {
      const auto tag = number<std::uint64_t>(r_, l, first + j, "a node tag");
      const auto it = index_.find(tag);
      if (it == index_.end()) r_.fail(l.number, l.tokens[first + j].second, fmt::format("node tag {} is not in $Nodes", tag));
      return it->second;
    };
    auto cell = [&]<std::size_t N>(std::vector<std::array<std::uint32_t, N>>& into) {
      std::array<std::uint32_t, N> c{};
      for (std::size_t j = 0; j < N; ++j) c[j] = corner(j);
      for (std::size_t j = 0; j < N; ++j)
        for (std::size_t i = 0; i < j; ++i)
          if (c[i] == c[j]) r_.fail(l.number, l.tokens[first + j].second, fmt::format("an element repeats node {}", l.tokens[first + j].first));
      into.push_back(c);
    };
    switch (v) {
      case Volume::tet:
        cell(m_.tets);
        m_.tet_lines.push_back(l.number);
        break;
      case Volume::hex: cell(m_.hexes); break;
      case Volume::prism: cell(m_.prisms); break;
      case Volume::pyramid: cell(m_.pyramids); break;
      case Volume::none: break;
    }
  }

  void elements_v2() {
    const Line h = need("the number of elements");
    const long n = count(h, 0, "the number of elements");
    for (long k = 0; k < n; ++k) {
      const Line l = need(fmt::format("element {} of {}", k + 1, n));
      const long type = number<long>(r_, l, 1, "the element type");
      const long tags = count(l, 2, "the number of tags");
      element(l, type, 3 + static_cast<std::size_t>(tags));
    }
    end("Elements", n, "elements", h.number);
  }

  void elements_v4() {
    blocks_v4("Elements", "elements", [&](const Line& bl, long b, long in_block) {
      const long type = number<long>(r_, bl, 2, "the element type");
      for (long k = 0; k < in_block; ++k) element(need(fmt::format("element {} of block {}", k + 1, b + 1)), type, 1);
    });
  }

  LineReader r_;
  TetMesh m_;
  bool v4_ = false;
  std::unordered_map<std::uint64_t, std::uint32_t> index_;  // node tag -> point
};

// Each field as a view of one value per element (the same in 2.2 and 4.1):
// one string tag (its name), one real tag (time 0), three integer tags
// (time step 0, 1 component, the number of values).
void element_data(std::ostream& out, const std::vector<CellField>& fields, std::size_t elements) {
  for (const CellField& f : fields) {
    if (f.values.size() != elements) throw InternalError(fmt::format("cell field {} has {} values for {} cells", f.name, f.values.size(), elements));
    out << fmt::format("$ElementData\n1\n\"{}\"\n1\n0\n3\n0\n1\n{}\n", f.name, elements);
    for (std::size_t k = 0; k < elements; ++k)
      out << k + 1 << ' ' << (f.integer ? fmt::format("{}", static_cast<long long>(f.values[k])) : fmt::format("{}", f.values[k])) << '\n';
    out << "$EndElementData\n";
  }
}

}  // namespace

TetMesh read_gmsh(const std::string& file) {
  TetMesh m = Reader(file).read();
  m.numbered_from = 1;  // a node's position in $Nodes, from 1
  return m;
}

void write_gmsh(std::ostream& out, const TetMesh& m, GmshVersion version, const std::vector<CellField>& fields) {
  write_gmsh(out, m.points, volume_cells(m, CornerConvention::gmsh), 3, version, fields);
}

void write_gmsh(std::ostream& out, const Points& points, const VolumeCells& cells, int dimension, GmshVersion version,
                const std::vector<CellField>& fields) {
  for (CellKind k : cells.kind)
    if (gmsh_type(k) == 0) throw InternalError(fmt::format("gmsh has no element for a {}", k));
  const std::size_t n = points.size(), e = cells.size();
  if (version == GmshVersion::v22) {
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
    out << fmt::format("$Nodes\n{}\n", n);
    for (std::size_t k = 0; k < n; ++k) out << fmt::format("{} {} {} {}\n", k + 1, points[k][0], points[k][1], points[k][2]);
    out << fmt::format("$EndNodes\n$Elements\n{}\n", e);
    for (std::size_t k = 0; k < e; ++k) {
      // Two tags: physical group 0, elementary entity 1.
      out << fmt::format("{} {} 2 0 1", k + 1, gmsh_type(cells.kind[k]));
      for (std::uint32_t v : cells.corners(k)) out << ' ' << v + 1;
      out << '\n';
    }
    out << "$EndElements\n";
    element_data(out, fields, e);
    return;
  }
  // 4.1: one entity of the mesh's dimension (tag 1) holding every node
  // and element.
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) {
      lo[c] = k ? std::min(lo[c], points[k][c]) : points[k][c];
      hi[c] = k ? std::max(hi[c], points[k][c]) : points[k][c];
    }
  std::array<int, 4> entities{0, 0, 0, 0};
  entities[static_cast<std::size_t>(dimension)] = 1;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << fmt::format("$Entities\n{} {} {} {}\n1 {} {} {} {} {} {} 0 0\n$EndEntities\n", entities[0], entities[1], entities[2], entities[3], lo[0],
                     lo[1], lo[2], hi[0], hi[1], hi[2]);
  out << fmt::format("$Nodes\n1 {} {} {}\n{} 1 0 {}\n", n, n ? 1 : 0, n, dimension, n);
  for (std::size_t k = 0; k < n; ++k) out << k + 1 << '\n';
  for (const auto& p : points) out << fmt::format("{} {} {}\n", p[0], p[1], p[2]);
  out << "$EndNodes\n";
  std::size_t blocks = 0;
  for (std::size_t k = 0; k < e; ++k) blocks += k == 0 || cells.kind[k] != cells.kind[k - 1];
  out << fmt::format("$Elements\n{} {} {} {}\n", blocks, e, e ? 1 : 0, e);
  for (std::size_t k = 0; k < e;) {
    std::size_t j = k;
    while (j < e && cells.kind[j] == cells.kind[k]) ++j;
    out << fmt::format("{} 1 {} {}\n", dimension, gmsh_type(cells.kind[k]), j - k);
    for (; k < j; ++k) {
      out << k + 1;
      for (std::uint32_t v : cells.corners(k)) out << ' ' << v + 1;
      out << '\n';
    }
  }
  out << "$EndElements\n";
  element_data(out, fields, e);
}

}  // namespace dartcheck
