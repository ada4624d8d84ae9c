#include "io/jerboa_jba.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/limits.hpp"
#include "core/orbit.hpp"
#include "io/input_file.hpp"

namespace dartcheck {
namespace {

// Lines of the file with their numbers; every error names file:line.
class Lines {
 public:
  explicit Lines(const std::string& file) : file_(file), lines_(text(file)) {}
  // The next line (without '\r'); `what` names what was expected at the end.
  std::string next(std::string_view what) {
    const auto line = lines_.next();
    if (!line) throw InputError(file_, lines_.number() + 1, 1, fmt::format("the file ends where {} was expected", what));
    return std::string(*line);
  }
  bool done() const { return lines_.done(); }
  [[noreturn]] void fail(const std::string& message) const { throw InputError(file_, lines_.number(), 1, message); }
  int number() const { return lines_.number(); }

 private:
  static std::string text(const std::string& file) {
    std::string t = read_input(file);
    refuse_nul_bytes(file, t, "a .jba file");
    return t;
  }

  std::string file_;
  TextLines lines_;
};

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

long long number(const Lines& lines, const std::string& text, std::string_view what) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) lines.fail(fmt::format("{}: expected an integer, got '{}'", what, text));
  return v;
}

// "key value": the value, after checking the key.
std::string keyed(Lines& lines, std::string_view key) {
  const std::string line = lines.next(fmt::format("'{} ...'", key));
  if (line.rfind(std::string(key) + " ", 0) != 0 && line != key) lines.fail(fmt::format("expected '{} ...', got '{}'", key, line));
  return line.size() > key.size() ? line.substr(key.size() + 1) : "";
}

// "<a1, a2, a3>" -> {1, 2, 3}.
std::vector<Dim> orbit_of(const Lines& lines, const std::string& text, int dimension) {
  if (text.size() < 2 || text.front() != '<' || text.back() != '>') lines.fail(fmt::format("orbit '{}': expected <a1, a2, ...>", text));
  std::vector<Dim> out;
  std::stringstream in(text.substr(1, text.size() - 2));
  for (std::string entry; std::getline(in, entry, ',');) {
    const auto b = entry.find_first_not_of(' '), e = entry.find_last_not_of(' ');
    if (b == std::string::npos) continue;
    const std::string a = entry.substr(b, e - b + 1);
    if (a.size() < 2 || a[0] != 'a') lines.fail(fmt::format("orbit '{}': unknown entry '{}' (expected a0 to a{})", text, a, dimension));
    const long long d = number(lines, a.substr(1), "orbit entry");
    if (d < 0 || d > dimension) lines.fail(fmt::format("orbit '{}': dimension {} is out of range (0 to {})", text, d, dimension));
    out.push_back(static_cast<Dim>(d));
  }
  return out;
}

// The header's embeddings: "ebdid <index> <name> <orbit, may hold spaces> <type>".
void read_embedding_ids(Lines& lines, long long count, int n, JbaFile& out) {
  for (long long k = 0; k < count; ++k) {
    const std::string line = keyed(lines, "ebdid");
    const auto open = line.find('<'), close = line.find('>');
    if (open == std::string::npos || close == std::string::npos || close < open) lines.fail(fmt::format("ebdid: no orbit <...> in '{}'", line));
    const auto head = words(line.substr(0, open)), tail = words(line.substr(close + 1));
    if (head.size() != 2 || tail.size() != 1) lines.fail(fmt::format("ebdid: expected 'ebdid <index> <name> <orbit> <type>', got 'ebdid {}'", line));
    MapEmbedding e{head[1], tail[0], orbit_of(lines, line.substr(open, close - open + 1), n), {}, {}};
    out.embeddings.push_back(std::move(e));
  }
}

// The dart lines: "<id> <alpha_0> ... <alpha_n>", ids resolved once all
// are read; returns the dart of each id.
std::unordered_map<std::string, Dart> read_darts(Lines& lines, const std::string& file, int n, JbaFile& out) {
  const auto sizes = words(lines.next("the dart count"));
  if (sizes.empty()) lines.fail("expected the dart count");
  const long long darts = number(lines, sizes[0], "dart count");
  if (darts < 0) lines.fail("dart count: expected a count");
  if (static_cast<unsigned long long>(darts) > limits().darts)
    lines.fail(over_limit("dart count", static_cast<std::size_t>(darts), limits().darts, "--limit-darts"));
  Map& map = out.map;
  std::unordered_map<std::string, Dart> index;
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  for (long long d = 0; d < darts; ++d) {
    auto w = words(lines.next(fmt::format("dart {} of {}", d + 1, darts)));
    if (w.size() != static_cast<std::size_t>(n) + 2)
      lines.fail(
          fmt::format("a dart line holds the dart's id and its {} links alpha_0..alpha_{}: expected {} numbers, got {}", n + 1, n, n + 2, w.size()));
    if (!index.emplace(w[0], static_cast<Dart>(d)).second) lines.fail(fmt::format("dart {} is declared twice", w[0]));
    out.ids.push_back(w[0]);
    rows.emplace_back(lines.number(), std::move(w));
  }
  // Allocated once every dart line is read: a count the file does not back
  // with lines costs nothing.
  map.add_darts(static_cast<std::size_t>(darts));
  for (const auto& [line, w] : rows)
    for (int i = 0; i <= n; ++i) {
      const auto it = index.find(w[static_cast<std::size_t>(i) + 1]);
      if (it == index.end())
        throw InputError(file, line, 1, fmt::format("dart {}: alpha_{} names dart {}, which the file does not declare", w[0], i, w[i + 1]));
      map.set_link(static_cast<Dim>(i), index.at(w[0]), it->second);
    }
  return index;
}

// The embedding sections: "<name> <record count>", then per record the
// line of its darts' ids and the line of its value.
void read_values(Lines& lines, const std::string& file, int n, long long darts, const std::unordered_map<std::string, Dart>& index, JbaFile& out) {
  for (auto& e : out.embeddings) e.values.assign(out.map.size(), std::nullopt);
  while (!lines.done()) {
    const auto head = words(lines.next("an embedding section"));
    if (head.empty()) continue;
    if (head.size() == static_cast<std::size_t>(n) + 2 && std::all_of(head.begin(), head.end(), [](const std::string& w) {
          return std::all_of(w.begin(), w.end(), [](char c) { return c >= '0' && c <= '9'; });
        }))
      lines.fail(fmt::format("a dart line after the {} darts the dart count announces: the count is smaller than the data", darts));
    if (head.size() != 2) lines.fail("expected '<embedding name> <record count>'");
    MapEmbedding* e = nullptr;
    for (auto& x : out.embeddings)
      if (x.name == head[0]) e = &x;
    if (!e) lines.fail(fmt::format("section '{}': no embedding of that name in the header", head[0]));
    const long long records = number(lines, head[1], "record count");
    for (long long r = 0; r < records; ++r) {
      const auto ids = words(lines.next(fmt::format("the darts of {} record {}", e->name, r + 1)));
      const int ids_line = lines.number();
      std::string value = lines.next(fmt::format("the value of {} record {}", e->name, r + 1));
      while (!value.empty() && value.back() == ' ') value.pop_back();
      for (const auto& id : ids) {
        const auto it = index.find(id);
        if (it == index.end()) throw InputError(file, ids_line, 1, fmt::format("{} record {}: dart {} is not declared", e->name, r + 1, id));
        auto& slot = e->values[it->second];
        if (slot && *slot != value)
          e->reassigned.emplace_back(it->second, value);
        else
          slot = value;
      }
    }
  }
}

}  // namespace

JbaFile read_jba(const std::string& file) {
  Lines lines(file);
  if (lines.next("the header") != "Jerboa JBA Generic Format")
    lines.fail("not a Jerboa G-map file: the first line must be 'Jerboa JBA Generic Format'");
  keyed(lines, "version");
  std::string name = keyed(lines, "name");
  const long long dimension = number(lines, keyed(lines, "dimension"), "dimension");
  if (dimension < 0 || dimension > max_dimension) lines.fail(fmt::format("dimension {} is out of range (0 to {})", dimension, max_dimension));
  const int n = static_cast<int>(dimension);
  const long long count = number(lines, keyed(lines, "nbebd"), "nbebd");
  if (count < 0) lines.fail("nbebd: expected a count");

  JbaFile out{std::move(name), Map(Model::gmap(n)), {}, {}};
  read_embedding_ids(lines, count, n, out);
  const auto index = read_darts(lines, file, n, out);
  read_values(lines, file, n, static_cast<long long>(out.map.size()), index, out);
  return out;
}

void write_jba(std::ostream& out, const JbaFile& f, const std::string& path) {
  const Map& m = f.map;
  if (!m.model().is_generalized() || m.model() != Model::gmap(m.model().dimension()))
    throw InputError(path, 0, 0, fmt::format("a .jba holds n-G-maps; this map is a {}", m.model().name));
  const int n = m.model().dimension();
  for (Dart d = 0; d < m.size(); ++d)
    for (int i = 0; i <= n; ++i)
      if (m.link(i, d) == no_dart) throw InputError(path, 0, 0, fmt::format("a .jba map has every link: dart {} has no alpha_{}", d, i));
  out << "Jerboa JBA Generic Format\nversion 1\nname " << (f.name.empty() ? "dartcheck" : f.name) << "\ndimension " << n << "\nnbebd "
      << f.embeddings.size() << '\n';
  for (std::size_t k = 0; k < f.embeddings.size(); ++k) {
    const auto& e = f.embeddings[k];
    std::string orbit;
    for (std::size_t j = 0; j < e.orbit.size(); ++j) orbit += fmt::format("{}a{}", j ? ", " : "", e.orbit[j]);
    out << "ebdid " << k << ' ' << e.name << " <" << orbit << "> " << e.type << '\n';
  }
  out << m.size() << ' ' << m.size() << '\n';
  for (Dart d = 0; d < m.size(); ++d) {
    out << d;
    for (int i = 0; i <= n; ++i) out << ' ' << m.link(i, d);
    out << '\n';
  }
  // One record per (orbit, value): an orbit whose darts disagree keeps
  // every value it had, as the reader found it.
  OrbitWalker walker(m);
  for (const auto& e : f.embeddings) {
    std::vector<std::pair<std::string, std::vector<Dart>>> records;
    for_each_orbit(walker, m, dims_generators(e.orbit), [&](Dart, const std::vector<Dart>& orbit) {
      std::vector<std::pair<std::string, std::vector<Dart>>> by_value;
      for (Dart x : orbit) {
        if (x >= e.values.size() || !e.values[x]) continue;
        auto it = std::find_if(by_value.begin(), by_value.end(), [&](const auto& r) { return r.first == *e.values[x]; });
        if (it == by_value.end())
          by_value.push_back({*e.values[x], {x}});
        else
          it->second.push_back(x);
      }
      records.insert(records.end(), by_value.begin(), by_value.end());
    });
    out << e.name << ' ' << records.size() << '\n';
    for (const auto& [value, darts] : records) {
      for (Dart x : darts) out << x << ' ';
      out << '\n' << value << '\n';
    }
  }
}

std::string jba_value(const Value& v) {
  switch (v.type) {
    case ValueType::point2:
    case ValueType::vector2:
      return fmt::format("{} {}", v.x[0], v.x[1]);
    case ValueType::point3:
    case ValueType::vector3:
    case ValueType::color:
      return fmt::format("{} {} {}", v.x[0], v.x[1], v.x[2]);
    case ValueType::real:
      return fmt::format("{}", v.x[0]);
    case ValueType::string:
      return v.string();
    default:
      return v.str();
  }
}

}  // namespace dartcheck
