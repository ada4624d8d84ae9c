// Jerboa's embedding expressions read as dartcheck's terms (003 Sec. 6.3,
// extended as rewriting/term.hpp says): the part of Java that real
// modelers write in <expr> (grammar and semantics: docs/jerboa-expressions.md).
//
// An expression is Java statements ending in `return e;`. The reader
// executes them symbolically: each local variable holds a term (or a node,
// a list, a collection of darts), a loop over an orbit's darts becomes an
// `each` term, and the returned term is type-checked against the
// embedding's value type. What lies outside the part is **opaque**, with
// the reason and its offset (`calls Vec3.rotate`); what no Java compiler
// or Jerboa editor would accept (unbalanced brackets, an embedding or a
// name the modeler does not declare, a dimension past the model's) is an
// error, since the modeler itself could not be built.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/model.hpp"
#include "rewriting/term.hpp"

namespace dartcheck {

/// The value type Jerboa's embedding class `java_type` stands for
/// (fr....Vec3 and Point3: point3; Normal3, Vector3: vector3; Color,
/// Color3, Color4: color; Boolean, Float, Double, Integer, String), or
/// nullopt for a class dartcheck does not know.
std::optional<ValueType> jerboa_value_type(const std::string& java_type);

/// What an expression may refer to: the model, the modeler's embeddings
/// (typed), the rule's left nodes and its parameters (values from the
/// .jme, or Java's default).
struct JerboaScope {
  const Model* model = nullptr;
  std::vector<EmbeddingSignature> embeddings;
  std::vector<std::string> nodes;
  std::map<std::string, Value> parameters;
  /// Declared parameters whose type or value is not read: an expression
  /// that reads one is opaque.
  std::vector<std::string> opaque_parameters;
};

/// The reading of one expression: a checked term, or why it is opaque.
struct ReadExpression {
  std::optional<Term> term;
  std::string reason;      // opaque: "calls Vec3.rotate"
  std::size_t offset = 0;  // opaque: where in the code
};

/// Java that the modeler could not have been built with; `offset` is a
/// 0-based position in the code.
class JerboaCodeError : public AtOffset<Error> {
 public:
  using AtOffset::AtOffset;
};

/// Reads the code of an <expr> for an embedding of type `result`. Throws
/// JerboaCodeError for code no Jerboa editor accepts; returns an opaque
/// reading for code outside the part dartcheck reads.
ReadExpression read_jerboa_expression(const std::string& code, const JerboaScope& scope, ValueType result);

/// A parameter's value from its <paramebd> text ("0.3f", "new Vec3(1,0,0)"),
/// or Java's default for a field of that type when the text is empty
/// (0, false, the zero vector). nullopt when the type or text is not read.
std::optional<Value> jerboa_parameter_value(const std::string& java_type, const std::string& text);

}  // namespace dartcheck
