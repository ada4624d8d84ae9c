#include "io/mesh_io.hpp"

#include <cmath>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <fmt/format.h>
#include <fstream>
#include <optional>
#include <string_view>

#include "core/input_error.hpp"
#include "io/input_file.hpp"
#include "io/line_reader.hpp"

namespace dartcheck {
namespace {

using text_mesh::Line;
using text_mesh::LineReader;
using text_mesh::number;

std::string lower_extension(const std::string& file) {
  auto dot = file.rfind('.');
  std::string ext = dot == std::string::npos ? "" : file.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void check_face(const LineReader& r, const Line& l, const std::vector<std::uint32_t>& f) {
  if (f.size() < 3) r.fail(l.number, l.tokens[0].second, fmt::format("a face needs at least 3 vertices, this one has {}", f.size()));
}

}  // namespace

bool is_mesh_path(const std::string& file) {
  const auto ext = lower_extension(file);
  return ext == "off" || ext == "obj";
}

Mesh read_mesh(const std::string& file) {
  const auto ext = lower_extension(file);
  if (ext == "off") return read_off(file);
  if (ext == "obj") return read_obj(file);
  throw InputError(file, 0, 0, "unknown mesh format (expected a .off or .obj file)");
}

Mesh read_off(const std::string& file) {
  LineReader r(file);
  Mesh mesh{file, {}, {}, {}};
  auto first = r.next();
  if (!first) r.fail(0, 0, "empty file: expected an OFF header or the counts 'vertices faces edges'");
  Line counts = *first;
  std::size_t skip = 0;
  int coords = 3;
  const std::string_view head = counts.tokens[0].first;
  if (head.size() >= 3 && head.substr(head.size() - 3) == "OFF") {
    // OFF, COFF, NOFF, CNOFF, STOFF ...; 4OFF has four coordinates.
    if (head.find("4") != std::string_view::npos) coords = 4;
    if (head.find("n") != std::string_view::npos) r.fail(counts.number, 1, "nOFF (arbitrary dimension) is not supported");
    skip = 1;
    if (counts.tokens.size() == 1) {
      auto next = r.next();
      if (!next) r.fail(r.line(), 0, "expected the counts 'vertices faces edges' after the header");
      counts = *next;
      skip = 0;
    }
  }
  const auto nv = number<long long>(r, counts, skip, "the number of vertices");
  const auto nf = number<long long>(r, counts, skip + 1, "the number of faces");
  if (nv < 0 || nf < 0 || nv > (1LL << 30) || nf > (1LL << 30))
    r.fail(counts.number, counts.tokens[skip].second, "vertex or face count out of range");
  for (long long v = 0; v < nv; ++v) {
    auto l = r.next();
    if (!l) r.fail(r.line(), 0, fmt::format("expected {} vertices, the file ends after {}", nv, v));
    std::array<double, 3> p{};
    for (int c = 0; c < coords; ++c) {
      const double x = number<double>(r, *l, static_cast<std::size_t>(c), "a vertex coordinate");
      // NaN and infinities would end in positions, outputs and JSON.
      if (!std::isfinite(x))
        r.fail(l->number, l->tokens[static_cast<std::size_t>(c)].second,
               fmt::format("a vertex coordinate is not a finite number ({})", l->tokens[static_cast<std::size_t>(c)].first));
      if (c < 3) p[static_cast<std::size_t>(c)] = x;
    }
    mesh.positions.push_back(p);
  }
  for (long long f = 0; f < nf; ++f) {
    auto l = r.next();
    if (!l) r.fail(r.line(), 0, fmt::format("expected {} faces, the file ends after {}", nf, f));
    const auto k = number<long long>(r, *l, 0, "the number of vertices of a face");
    if (k < 0 || static_cast<std::size_t>(k) + 1 > l->tokens.size())
      r.fail(l->number, l->tokens[0].second, fmt::format("the face announces {} vertices but the line has {} indices", k, l->tokens.size() - 1));
    std::vector<std::uint32_t> face;
    for (long long j = 1; j <= k; ++j) {
      const auto v = number<long long>(r, *l, static_cast<std::size_t>(j), "a vertex index");
      if (v < 0 || v >= nv)
        r.fail(l->number, l->tokens[static_cast<std::size_t>(j)].second, fmt::format("vertex index {} is out of range [0, {})", v, nv));
      face.push_back(static_cast<std::uint32_t>(v));
    }
    check_face(r, *l, face);
    mesh.faces.push_back(std::move(face));
    mesh.face_lines.push_back(l->number);
  }
  if (mesh.faces.empty()) r.fail(counts.number, 0, "the mesh has no face");
  // A count smaller than the data would drop the rest of the mesh unseen.
  if (const auto extra = r.next())
    r.fail(extra->number, extra->tokens[0].second,
           fmt::format("data after the {} vertices and {} faces the counts announce (line {}): a count is smaller than the data", nv, nf,
                       counts.number));
  return mesh;
}

Mesh read_obj(const std::string& file) {
  LineReader r(file);
  Mesh mesh{file, {}, {}, {}};
  while (auto l = r.next()) {
    const std::string_view kw = l->tokens[0].first;
    if (kw == "v") {
      std::array<double, 3> p{};
      for (std::size_t c = 0; c < 3; ++c) p[c] = number<double>(r, *l, c + 1, "a vertex coordinate");
      mesh.positions.push_back(p);
    } else if (kw == "f" || kw == "fo") {
      std::vector<std::uint32_t> face;
      for (std::size_t j = 1; j < l->tokens.size(); ++j) {
        auto [tok, col] = l->tokens[j];
        const std::string_view index = tok.substr(0, tok.find('/'));
        long long v = 0;
        auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), v);
        if (ec != std::errc{} || end != index.data() + index.size() || v == 0)
          r.fail(l->number, col, fmt::format("expected a vertex reference (1-based or negative index), got '{}'", tok));
        const long long n = static_cast<long long>(mesh.positions.size());
        const long long resolved = v > 0 ? v - 1 : n + v;
        if (resolved < 0 || resolved >= n) r.fail(l->number, col, fmt::format("vertex {} does not exist ({} vertices defined so far)", v, n));
        face.push_back(static_cast<std::uint32_t>(resolved));
      }
      check_face(r, *l, face);
      mesh.faces.push_back(std::move(face));
      mesh.face_lines.push_back(l->number);
    } else if (kw.size() > 0 && !std::isalpha(static_cast<unsigned char>(kw[0]))) {
      r.fail(l->number, 1, fmt::format("unexpected '{}' at the start of a line (expected a keyword such as v or f)", kw.substr(0, 16)));
    }
    // Other keywords (vt, vn, g, o, s, usemtl, mtllib, l, p) carry no faces.
  }
  if (mesh.faces.empty()) throw InputError(file, r.line(), 0, "the mesh has no face");
  return mesh;
}

}  // namespace dartcheck
