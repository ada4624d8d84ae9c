// validate-map --format json: the facts the text prints (links, cells,
// every violation up to --limit, a .jba's embeddings), as one document
// (docs/schema/validate-map.schema.json).
#pragma once

#include <cstddef>
#include <string>

#include "checkers/violation.hpp"
#include "core/map.hpp"
#include "io/jerboa_jba.hpp"
#include "reports/json_fwd.hpp"

namespace dartcheck::reports {

/// The document of one map: `target` as given, `description` as the text's
/// first line says it; `jba` adds the embeddings' consistency (003 Def. 6).
Json validity_document(const std::string& target, const std::string& description, const Map& map, const ValidityReport& report,
                       std::size_t limit, const JbaFile* jba = nullptr);
/// The same document as one line of text (what validate-map prints).
std::string validity_json_text(const std::string& target, const std::string& description, const Map& map, const ValidityReport& report,
                               std::size_t limit, const JbaFile* jba = nullptr);

}  // namespace dartcheck::reports
