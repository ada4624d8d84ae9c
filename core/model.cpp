#include "core/model.hpp"

#include <charconv>

namespace dartcheck {

DimSet Model::dim_set() const {
  DimSet s = 0;
  for (Dim i : dims) s |= dim_bit(i);
  return s;
}

std::vector<std::pair<Dim, Dim>> pairs_two_apart(const std::vector<Dim>& dims) {
  std::vector<std::pair<Dim, Dim>> pairs;
  for (Dim i : dims)
    for (Dim j : dims)
      if (i + 2 <= j) pairs.emplace_back(i, j);
  return pairs;
}

static std::vector<Dim> range(Dim lo, Dim hi) {
  std::vector<Dim> r;
  for (Dim i = lo; i <= hi; ++i) r.push_back(i);
  return r;
}

Model Model::gmap(int n) {
  Model m;
  m.name = std::to_string(n) + "-gmap";
  m.dims = range(0, n);
  m.non_oriented = m.dim_set();
  m.exchangeable = pairs_two_apart(m.dims);
  return m;
}

Model Model::omap(int n) {
  Model m;
  m.name = std::to_string(n) + "-omap";
  m.dims = range(1, n);
  for (Dim i = 2; i <= n; ++i) m.non_oriented |= dim_bit(i);
  m.exchangeable = pairs_two_apart(m.dims);
  return m;
}

Model Model::closed_gmap(int n) {
  Model m = gmap(n);
  m.name = std::to_string(n) + "-closed-gmap";
  m.loop_free = true;
  return m;
}

Model Model::open_omap(int n) {
  Model m = omap(n);
  m.name = std::to_string(n) + "-open-omap";
  m.partial = dim_bit(n);
  return m;
}

std::string_view Model::known_names() { return "N-gmap, N-omap, N-closed-gmap, N-open-omap (N from 1 to 15 for O-maps, 0 to 15 for G-maps)"; }

std::optional<Model> Model::by_name(std::string_view name) {
  int n = -1;
  auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), n);
  if (ec != std::errc{} || end == name.data() || n < 0 || n > max_dimension) return std::nullopt;
  std::string_view kind(end, static_cast<std::size_t>(name.data() + name.size() - end));
  if (kind == "-gmap") return gmap(n);
  if (kind == "-closed-gmap") return closed_gmap(n);
  if (n >= 1 && kind == "-omap") return omap(n);
  if (n >= 1 && kind == "-open-omap") return open_omap(n);
  return std::nullopt;
}

}  // namespace dartcheck
