#include "io/baseline.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/detail/yaml_util.hpp"

namespace dartcheck {

const BaselineEntry* Baseline::find(const std::string& rule) const {
  for (const auto& e : entries)
    if (e.rule == rule) return &e;
  return nullptr;
}

const std::vector<std::string>& solver_class_names() {
  static const std::vector<std::string> names{"holds", "breaks", "false alarm", "other algebra", "unknown"};
  return names;
}

Baseline read_baseline(const std::string& file) {
  const YAML::Node root = load_yaml_file(file);
  try {
    yaml::expect_map(file, root, "a baseline");
    yaml::allow_keys(file, root, {"verdicts", "solver"});
    const YAML::Node verdicts = yaml::require(file, root, "verdicts");
    yaml::expect_map(file, verdicts, "verdicts");
    Baseline b{file, {}};
    for (const auto& kv : verdicts) {
      BaselineEntry e;
      e.rule = yaml::as_string(file, kv.first, "a rule name");
      e.location = {file, kv.first.Mark().line + 1, kv.first.Mark().column + 1};
      if (b.find(e.rule)) fail_at(file, kv.first, fmt::format("rule '{}' appears twice", e.rule));
      const YAML::Node& v = kv.second;
      if (v.IsScalar() && v.Scalar() == "consistent") {
        e.failures.emplace();
      } else if (v.IsScalar() && v.Scalar() == "not checked") {
        // no verdict: dartcheck could not read the rule
      } else if (v.IsSequence()) {
        e.failures.emplace();
        for (const auto& f : v) e.failures->push_back(yaml::as_string(file, f, "a condition name such as I(1)"));
      } else {
        fail_at(file, v, fmt::format("verdict of '{}': expected consistent, not checked or a list such as [\"I(1)\"]", e.rule));
      }
      b.entries.push_back(std::move(e));
    }
    if (const YAML::Node solver = root["solver"]) {
      yaml::expect_map(file, solver, "solver");
      for (const auto& kv : solver) {
        const std::string rule = yaml::as_string(file, kv.first, "a rule name");
        auto it = std::find_if(b.entries.begin(), b.entries.end(), [&](const BaselineEntry& x) { return x.rule == rule; });
        if (it == b.entries.end()) fail_at(file, kv.first, fmt::format("solver: rule '{}' has no verdict in verdicts", rule));
        if (it->solver) fail_at(file, kv.first, fmt::format("solver: rule '{}' appears twice", rule));
        yaml::expect_map(file, kv.second, fmt::format("the solver classes of '{}'", rule));
        it->solver.emplace();
        it->solver_location = {file, kv.first.Mark().line + 1, kv.first.Mark().column + 1};
        for (const auto& c : kv.second) {
          const std::string embedding = yaml::as_string(file, c.first, "an embedding name");
          const std::string cls = yaml::as_string(file, c.second, "a solver class");
          const auto& names = solver_class_names();
          if (std::find(names.begin(), names.end(), cls) == names.end())
            fail_at(file, c.second, fmt::format("solver class of '{}' {}: expected one of {}", rule, embedding, fmt::join(names, ", ")));
          it->solver->emplace_back(embedding, cls);
        }
      }
    }
    return b;
  } catch (const YAML::Exception& e) {
    throw yaml_input_error(file, e);
  }
}

void write_baseline(std::ostream& out, const std::string& source, const std::vector<BaselineEntry>& entries) {
  // Rule names and condition names are quoted: Jerboa names may hold
  // anything YAML would read otherwise.
  // Control characters are written as YAML escapes; other bytes (even
  // invalid UTF-8, which yaml-cpp reads back as is) stay.
  auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
      const auto u = static_cast<unsigned char>(c);
      if (c == '"' || c == '\\')
        q += '\\', q += c;
      else if (u < 0x20 || u == 0x7F)
        q += fmt::format("\\x{:02x}", u);
      else
        q += c;
    }
    return q + '"';
  };
  auto comment = [](std::string s) {
    for (char& c : s)
      if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    return s;
  };
  out << "# dartcheck baseline of " << comment(source) << " (dartcheck check --baseline)\nverdicts:\n";
  for (const auto& e : entries) {
    out << "  " << quoted(e.rule) << ": ";
    if (!e.failures) {
      out << "not checked\n";
    } else if (e.failures->empty()) {
      out << "consistent\n";
    } else {
      out << '[';
      for (std::size_t k = 0; k < e.failures->size(); ++k) out << (k ? ", " : "") << quoted((*e.failures)[k]);
      out << "]\n";
    }
  }
  if (std::none_of(entries.begin(), entries.end(), [](const BaselineEntry& e) { return e.solver.has_value(); })) return;
  out << "solver:\n";
  for (const auto& e : entries) {
    if (!e.solver) continue;
    out << "  " << quoted(e.rule) << ": {";
    for (std::size_t k = 0; k < e.solver->size(); ++k) out << (k ? ", " : "") << quoted((*e.solver)[k].first) << ": " << quoted((*e.solver)[k].second);
    out << "}\n";
  }
}

}  // namespace dartcheck
