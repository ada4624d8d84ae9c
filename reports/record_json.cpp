#include "reports/detail/record_json.hpp"

namespace dartcheck::reports::detail {

namespace {

Json model_json(const Model& m) {
  Json pairs = Json::array();
  for (const auto& [i, j] : m.exchangeable) pairs.push_back(Json::array({i, j}));
  return Json{{"name", m.name},        {"dims", m.dims},       {"non_oriented", m.non_oriented},
              {"exchangeable", pairs}, {"partial", m.partial}, {"loop_free", m.loop_free}};
}

Json pairs_json(const std::vector<std::pair<std::string, Dart>>& pairs) {
  Json out = Json::array();
  for (const auto& [node, dart] : pairs) out.push_back(Json::array({node, dart}));
  return out;
}

}  // namespace

Json map_json(const Map& m) {
  Json dims = Json::array();
  for (Dim i : m.model().dims) {
    std::vector<Dart> links(m.size()), preds;
    for (Dart d = 0; d < m.size(); ++d) links[d] = m.link(i, d);
    Json dim{{"dim", i}, {"links", links}};
    if (m.model().is_oriented(i)) {
      for (Dart d = 0; d < m.size(); ++d) preds.push_back(m.inverse_link(i, d));
      dim["predecessors"] = preds;
    }
    dims.push_back(std::move(dim));
  }
  return Json{{"model", model_json(m.model())}, {"darts", m.size()}, {"dims", std::move(dims)}};
}

Json graph_json(const TopoGraph& g) {
  Json arcs = Json::array();
  for (const auto& a : g.arcs()) arcs.push_back(Json::array({a.source, a.target, a.label}));
  return Json{{"nodes", g.names()}, {"arcs", std::move(arcs)}};
}

Json violations_json(const std::vector<Violation>& vs) {
  Json out = Json::array();
  for (const auto& v : vs)
    out.push_back(Json{{"constraint", static_cast<int>(v.constraint)}, {"i", v.i}, {"j", v.j}, {"element", v.element}, {"count", v.count}});
  return out;
}

Json symbolic_host_json(const proofs::SymbolicHost& h) {
  Json links = Json::array();
  for (const auto& [dim, darts] : h.links) links.push_back(Json{{"dim", dim}, {"links", darts}});
  return Json{{"size", h.size}, {"links", std::move(links)}};
}

void add_counterexample_record(Json& j, const analysis::Counterexample& cx) {
  j["host"] = map_json(cx.host);
  j["hooks"] = cx.hooks;
  j["match"] = pairs_json(cx.match);
  j["result"] = optional_json(cx.result, map_json);
  j["violations"] = violations_json(cx.violations);
  j["unrepresentable"] = cx.unrepresentable;
  j["origin"] = cx.origin;
  j["minimal"] = cx.minimal;
  j["embedding_failures"] = cx.embedding_failures;
  j["broken_embeddings"] = cx.broken_embeddings;
  j["orbit_values"] = cx.orbit_values;
  j["event_contradictions"] = cx.event_contradictions;
  j["comatch"] = pairs_json(cx.comatch);
}

}  // namespace dartcheck::reports::detail
