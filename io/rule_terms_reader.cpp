#include "io/rule_terms_reader.hpp"

#include <algorithm>
#include <functional>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "io/detail/yaml_util.hpp"
#include "rewriting/rule.hpp"
#include "rewriting/term_functions.hpp"

namespace dartcheck {

namespace {

// The position of a term's character: a quoted scalar starts one column
// after its mark (yaml-cpp tags non-plain scalars "!").
InputError term_error(const std::string& file, const YAML::Node& n, const TermError& e, const std::string& context) {
  const int quote = n.Tag() == "!" ? 1 : 0;
  return InputError(file, n.Mark().line + 1, n.Mark().column + 1 + quote + static_cast<int>(e.offset()), fmt::format("{}: {}", context, e.what()));
}

Term parse_checked(const std::string& file, const YAML::Node& n, const TermScope& scope, const std::string& context, Sort* sort) {
  const std::string text = yaml::as_string(file, n, "term");
  try {
    Term t = parse_term(text);
    *sort = check_term(t, scope);
    return t;
  } catch (const TermError& e) {
    throw term_error(file, n, e, context);
  }
}

std::vector<std::string> split_names(const std::string& key) {
  std::vector<std::string> r;
  std::string cur;
  for (char c : key) {
    if (c == ',' || c == ' ') {
      if (!cur.empty()) r.push_back(std::move(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) r.push_back(std::move(cur));
  return r;
}

std::vector<NodeTerm> read_side(const std::string& file, const YAML::Node& side, char which, const TopoGraph& graph, const TermScope& scope) {
  std::vector<NodeTerm> out;
  const char* side_name = which == 'L' ? "left" : "right";
  yaml::expect_map(file, side, fmt::format("labels.{}", side_name));
  for (const auto& kv : side) {
    const auto names = split_names(yaml::as_string(file, kv.first, "node names"));
    if (names.empty()) fail_at(file, kv.first, "labels: a key names one or more nodes");
    for (const auto& node : names)
      if (!graph.find(node)) fail_at(file, kv.first, fmt::format("labels.{}: '{}' is not a node of {}", side_name, node, side_name));
    yaml::expect_map(file, kv.second, "terms of a node ({embedding: term})");
    for (const auto& e : kv.second) {
      const auto ebd = yaml::as_string(file, e.first, "embedding name");
      const EmbeddingSignature* sig = scope.find_embedding(ebd);
      if (!sig) fail_at(file, e.first, fmt::format("labels: no embedding named '{}' under 'embeddings'", ebd));
      Sort sort;
      const Term t = parse_checked(file, e.second, scope, fmt::format("term of {} on {}", ebd, names.front()), &sort);
      if (sort != Sort::of(sig->type))
        fail_at(file, e.second,
                fmt::format("the term '{}' is a {}, but {} : <{}> -> {}", t.str(), sort.str(), ebd, fmt::join(sig->orbit, ","), name_of(sig->type)));
      for (const auto& node : names) {
        for (const NodeTerm& o : out)
          if (o.node == node && o.embedding == ebd) fail_at(file, e.first, fmt::format("labels.{}: {} on '{}' is given twice", side_name, ebd, node));
        const int quote = e.second.Tag() == "!" ? 1 : 0;
        out.push_back({node, ebd, t, file, e.second.Mark().line + 1, e.second.Mark().column + 1 + quote});
      }
    }
  }
  return out;
}

}  // namespace

RuleTerms read_rule_terms(const std::string& file, const YAML::Node& rule, const Rule& topology, const std::vector<EmbeddingSignature>& embeddings,
                          const RuleTerms* base) {
  RuleTerms r;
  if (base) r = *base;
  r.embeddings = embeddings;
  if (const auto only = rule["embeddings"]) {
    // The embeddings of the objects this rule transforms (default: all).
    yaml::expect_sequence(file, only, "embeddings");
    r.embeddings.clear();
    for (const auto& n : only) {
      const auto name = yaml::as_string(file, n, "embedding name");
      const auto it = std::find_if(embeddings.begin(), embeddings.end(), [&](const EmbeddingSignature& e) { return e.name == name; });
      if (it == embeddings.end()) fail_at(file, n, fmt::format("embeddings: no embedding named '{}' under the catalog's 'embeddings'", name));
      r.embeddings.push_back(*it);
    }
  } else if (base) {
    r.embeddings = base->embeddings;
  }
  TermScope scope;
  scope.model = &topology.model();
  scope.embeddings = &r.embeddings;
  scope.variables = topology.left().names();
  if (const auto ps = rule["parameters"]) {
    yaml::expect_map(file, ps, "parameters");
    r.parameters.clear();
    for (const auto& kv : ps) {
      const auto name = yaml::as_string(file, kv.first, "parameter name");
      if (topology.left().find(name)) fail_at(file, kv.first, fmt::format("parameter '{}' has the name of a node of left", name));
      Sort sort;
      TermScope closed = scope;
      closed.variables.clear();  // a parameter is a closed term
      closed.parameters = r.parameters;
      const Term t = parse_checked(file, kv.second, closed, fmt::format("parameter '{}'", name), &sort);
      if (sort.kind != Sort::value) fail_at(file, kv.second, fmt::format("parameter '{}' is a {}, not a value", name, sort.str()));
      try {
        r.parameters[name] = std::get<Value>([&] {
          // A closed term needs no map: evaluate its calls directly.
          std::function<Operand(const Term&)> eval = [&](const Term& x) -> Operand {
            if (x.kind == Term::Kind::literal || x.kind == Term::Kind::parameter) return x.literal;
            std::vector<Operand> args;
            for (const Term& a : x.args) args.push_back(eval(a));
            return x.function->apply(args);
          };
          return eval(t);
        }());
      } catch (const EvaluationError& e) {
        fail_at(file, kv.second, fmt::format("parameter '{}': {}", name, e.what()));
      }
    }
  }
  scope.parameters = r.parameters;
  if (const auto in = rule["instantiation"]) {
    const auto s = yaml::as_string(file, in, "instantiation");
    if (s == "direct")
      r.instantiation = Instantiation::direct;
    else if (s == "extended")
      r.instantiation = Instantiation::extended;
    else
      fail_at(file, in, fmt::format("instantiation: expected 'direct' (003 Sec. 5.2, Theorem 2) or 'extended' (Def. 13, Theorem 4), found '{}'", s));
  }
  if (const auto labels = rule["labels"]) {
    yaml::expect_map(file, labels, "labels");
    yaml::allow_keys(file, labels, {"left", "right"});
    if (labels["left"]) r.left = read_side(file, labels["left"], 'L', topology.left(), scope);
    if (labels["right"]) r.right = read_side(file, labels["right"], 'R', topology.right(), scope);
  }
  return r;
}

}  // namespace dartcheck
