// Jerboa's embedding expressions (io/jerboa_expression): the Java read
// against a rule's scope (a 3-G-map modeler with pos, color and norm; L
// nodes n0, n1; a parameter weight, one unread, ctl), then a read term
// evaluated at every dart of a small embedded map (loops over orbits,
// lists, collects). Errors and opaque readings are the expected outcomes;
// a crash, a sanitizer report or an exception of another type is a bug.
#include <random>

#include "fuzz/harness.hpp"
#include "generators/random_embedding.hpp"
#include "generators/random_maps.hpp"
#include "io/jerboa_expression.hpp"
#include "rewriting/term_eval.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  static const Model model = Model::gmap(3);
  static const JerboaScope scope{&model,
                                 {{"pos", ValueType::point3, {1, 2, 3}}, {"color", ValueType::color, {0, 1}}, {"norm", ValueType::vector3, {}}},
                                 {"n0", "n1"},
                                 {{"weight", Value::real(0.25)}},
                                 {"ctl"}};
  static const EmbeddedMap host = [] {
    std::mt19937 rng(1);
    return embed_randomly(build_random_map(model, draw_recipe(rng, 3, 3)), scope.embeddings, rng);
  }();
  try {
    const ReadExpression r = read_jerboa_expression(std::string(fuzzing::as_text(data, size)), scope, ValueType::point3);
    if (!r.term) return 0;
    (void)r.term->str();
    TermEvaluator ev(host);
    const std::vector<std::string> names = scope.nodes;
    for (Dart d = 0; d < host.map.size(); ++d) {
      const std::vector<Dart> darts{d, host.map.link(0, d)};
      try {
        (void)ev.value(*r.term, names, darts);
      } catch (const EvaluationError&) {
      }
    }
  } catch (const JerboaCodeError&) {
  }
  return 0;
}
