// Embedding terms (rewriting/term): parsing, then type checking against a
// scope like a catalog rule's (nodes a, b; pos and col; a parameter v).
#include "fuzz/harness.hpp"
#include "rewriting/term.hpp"
#include "rewriting/term_functions.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  static const Model model = Model::gmap(2);
  static const std::vector<EmbeddingSignature> embeddings = {{"pos", ValueType::point2, {1, 2}}, {"col", ValueType::color, {0, 1}}};
  try {
    Term t = parse_term(std::string(fuzzing::as_text(data, size)));
    (void)t.str();
    TermScope scope;
    scope.model = &model;
    scope.embeddings = &embeddings;
    scope.variables = {"a", "b"};
    scope.parameters["v"] = Value::coords(ValueType::vector2, {1, 0, 0});
    (void)check_term(t, scope);
    (void)t.str();
  } catch (const TermError&) {
  }
  return 0;
}
