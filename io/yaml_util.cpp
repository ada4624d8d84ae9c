#include "io/detail/yaml_util.hpp"

#include "core/closest_name.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <optional>
#include <string_view>
#include <set>
#include <utility>
#include <vector>
#include <yaml-cpp/depthguard.h>

#include "io/input_file.hpp"

namespace dartcheck {

void fail_at(const std::string& file, const YAML::Node& node, const std::string& message) {
  const YAML::Mark m = node.Mark();
  throw InputError(file, m.line + 1, m.column + 1, message);
}

namespace {

// What yaml-cpp accepts and a reader must not: a key given twice in one
// mapping (yaml-cpp keeps both, lookups find the first), and a NUL
// character written as an escape ("\0") in a string. Each collection is
// visited once, aliases included (a chain of aliases shares its nodes).
void check_tree(const std::string& file, const YAML::Node& root) {
  std::set<std::pair<int, int>> visited;  // a collection's position and type: its identity
  std::vector<YAML::Node> stack{root};
  while (!stack.empty()) {
    const YAML::Node n = stack.back();
    stack.pop_back();
    if (n.IsScalar()) {
      if (n.Scalar().find('\0') != std::string::npos) fail_at(file, n, "a NUL character (\\0) in a string");
      continue;
    }
    if (!n.IsMap() && !n.IsSequence()) continue;
    if (!visited.emplace(n.Mark().pos, static_cast<int>(n.Type())).second) continue;
    if (n.IsSequence()) {
      for (const auto& item : n) stack.push_back(item);
      continue;
    }
    std::map<std::string, YAML::Mark> keys;
    for (const auto& kv : n) {
      if (kv.first.IsScalar()) {
        const auto [at, fresh] = keys.emplace(kv.first.Scalar(), kv.first.Mark());
        if (!fresh)
          fail_at(file, kv.first,
                  fmt::format("duplicate key '{}' (first at line {}, column {}): a mapping names each key once", printable(kv.first.Scalar()),
                              at->second.line + 1, at->second.column + 1));
      }
      stack.push_back(kv.first);
      stack.push_back(kv.second);
    }
  }
}

// The 1-based line and column of the innermost flow bracket `open` ('[' or
// '{') still open at byte `end` of `text`: brackets inside quoted scalars
// and comments are skipped. Nullopt when there is none (the caller keeps
// yaml-cpp's position).
std::optional<std::pair<int, int>> unclosed_bracket(std::string_view text, char open, int end) {
  struct Open {
    char c;
    int line, column;
  };
  std::vector<Open> stack;
  int line = 1, column = 1;
  char quote = 0;
  bool comment = false;
  const auto stop = static_cast<std::size_t>(std::clamp(end, 0, static_cast<int>(text.size())));
  for (std::size_t k = 0; k < stop; ++k) {
    const char c = text[k];
    if (c == '\n') {
      ++line;
      column = 1;
      comment = false;
      continue;
    }
    if (comment) {
    } else if (quote) {
      if (c == '\\' && quote == '"') {
        ++k;
        ++column;
      } else if (c == quote) {
        quote = 0;
      }
    } else if (c == '#' && (k == 0 || text[k - 1] == ' ' || text[k - 1] == '\t')) {
      comment = true;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      stack.push_back({c, line, column});
    } else if ((c == ']' || c == '}') && !stack.empty()) {
      stack.pop_back();
    }
    ++column;
  }
  for (auto it = stack.rbegin(); it != stack.rend(); ++it)
    if (it->c == open) return std::pair{it->line, it->column};
  return std::nullopt;
}

}  // namespace

YAML::Node load_yaml_file(const std::string& file) {
  const std::string text = read_input(file);
  refuse_nul_bytes(file, text, "a YAML file");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp 0.7 words this "bad file".
    throw InputError(file, e.mark.line + 1, e.mark.column + 1,
                     fmt::format("malformed YAML: collections nested deeper than {} levels, the most yaml-cpp reads", e.depth()));
  } catch (const YAML::ParserException& e) {
    // yaml-cpp places an unclosed [ or { where it gave up (the end of the
    // file, often): the bracket is what the user has to find.
    const bool sequence = e.msg.find("end of sequence flow not found") != std::string::npos;
    if (sequence || e.msg.find("end of map flow not found") != std::string::npos)
      if (const auto at = unclosed_bracket(text, sequence ? '[' : '{', e.mark.pos))
        throw InputError(file, at->first, at->second,
                         fmt::format("malformed YAML: this '{}' is never closed (yaml-cpp stopped at line {}, column {})", sequence ? '[' : '{',
                                     e.mark.line + 1, e.mark.column + 1));
    throw InputError(file, e.mark.line + 1, e.mark.column + 1, "malformed YAML: " + e.msg);
  }
  check_tree(file, root);
  return root;
}

InputError yaml_input_error(const std::string& file, const YAML::Exception& e) {
  return InputError(file, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1, e.msg);
}

}  // namespace dartcheck

namespace dartcheck::yaml {

YAML::Node require(const std::string& file, const YAML::Node& map, const char* key) {
  YAML::Node n = map[key];
  if (!n) fail_at(file, map, fmt::format("missing key '{}'", key));
  return n;
}

void expect_map(const std::string& file, const YAML::Node& n, std::string_view what) {
  if (!n.IsMap()) fail_at(file, n, fmt::format("{}: expected a mapping", what));
}

void expect_sequence(const std::string& file, const YAML::Node& n, std::string_view what) {
  if (!n.IsSequence()) fail_at(file, n, fmt::format("{}: expected a list", what));
}

void allow_keys(const std::string& file, const YAML::Node& map, std::initializer_list<std::string_view> allowed) {
  for (const auto& kv : map) {
    const auto key = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    const std::string near = closest_name(key, std::vector<std::string>(allowed.begin(), allowed.end()));
    fail_at(file, kv.first,
            fmt::format("unknown key '{}' ({}expected one of: {})", key, near.empty() ? "" : fmt::format("did you mean '{}'? ", near),
                        fmt::join(allowed, ", ")));
  }
}

long long as_int(const std::string& file, const YAML::Node& n, std::string_view what, long long lo, long long hi) {
  long long v = 0;
  if (!n.IsScalar() || !YAML::convert<long long>::decode(n, v))
    fail_at(file, n,
            n.IsScalar() ? fmt::format("{}: expected an integer, got '{}'", what, printable(n.Scalar()))
                         : fmt::format("{}: expected an integer, got {}", what, n.IsNull() || !n.IsDefined() ? "nothing (a null)" : "a collection"));
  if (v < lo || v > hi) fail_at(file, n, fmt::format("{}: {} is out of range [{}, {}]", what, v, lo, hi));
  return v;
}

std::string as_string(const std::string& file, const YAML::Node& n, std::string_view what) {
  if (!n.IsScalar())
    fail_at(file, n, fmt::format("{}: expected a string, got {}", what, n.IsNull() || !n.IsDefined() ? "nothing (a null)" : "a collection"));
  return n.Scalar();
}

std::vector<Dim> read_dims(const std::string& file, const YAML::Node& n, const char* what) {
  expect_sequence(file, n, what);
  std::vector<Dim> dims;
  for (const auto& d : n) dims.push_back(static_cast<Dim>(as_int(file, d, what, 0, max_dimension)));
  return dims;
}

Model custom_model(const std::string& file, const std::string& name, const YAML::Node& n, bool named) {
  expect_map(file, n, "model");
  if (named)
    allow_keys(file, n, {"name", "dims", "non_oriented", "exchangeable", "partial", "loop_free"});
  else
    allow_keys(file, n, {"dims", "non_oriented", "exchangeable", "partial", "loop_free"});
  Model m;
  m.name = name;
  m.dims = read_dims(file, require(file, n, "dims"), "dims");
  std::sort(m.dims.begin(), m.dims.end());
  if (m.dims.empty() || std::adjacent_find(m.dims.begin(), m.dims.end()) != m.dims.end())
    fail_at(file, n["dims"], "dims: expected a non-empty list of distinct dimensions");
  auto subset = [&](const char* key) {
    DimSet s = 0;
    if (auto v = n[key]) {
      const auto dims = read_dims(file, v, key);
      for (std::size_t k = 0; k < dims.size(); ++k) {
        if (!m.contains(dims[k])) fail_at(file, v[k], fmt::format("{}: {} is not in dims", key, dims[k]));
        s |= dim_bit(dims[k]);
      }
    }
    return s;
  };
  m.non_oriented = subset("non_oriented");
  m.partial = subset("partial");
  if (auto e = n["exchangeable"]) {
    expect_sequence(file, e, "exchangeable");
    for (const auto& p : e) {
      const auto pair = read_dims(file, p, "exchangeable pair");
      if (pair.size() != 2 || !m.contains(pair[0]) || !m.contains(pair[1])) fail_at(file, p, "exchangeable: expected a pair [i, j] of dims");
      m.exchangeable.emplace_back(pair[0], pair[1]);
    }
  }
  if (auto l = n["loop_free"]) {
    if (!l.IsScalar() || (l.Scalar() != "true" && l.Scalar() != "false")) fail_at(file, l, "loop_free: expected true or false");
    m.loop_free = l.Scalar() == "true";
  }
  return m;
}

Model as_model(const std::string& file, const YAML::Node& n) {
  if (n.IsMap()) return custom_model(file, as_string(file, require(file, n, "name"), "model name"), n, true);
  const std::string name = as_string(file, n, "model");
  auto m = Model::by_name(name);
  if (!m) fail_at(file, n, fmt::format("unknown model '{}' (expected {})", name, Model::known_names()));
  return *m;
}

}  // namespace dartcheck::yaml
