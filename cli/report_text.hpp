// Plain-text rendering of validity reports and cell counts for the CLI.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "checkers/rule_conditions.hpp"
#include "checkers/violation.hpp"
#include "core/map.hpp"

namespace dartcheck::cli {

/// Prints cells and every violation (up to `limit`, 0 = all, saying how
/// many were left out).
void print_validity(std::FILE* out, const Map& map, const ValidityReport& report, std::size_t limit);

/// "8 vertices, 12 edges, 6 faces"
std::string cells_sentence(const Map& map);

/// A JSON string body: quotes, backslashes and control characters escaped.
std::string json_escape(std::string_view s);
/// ["a", "b"]
std::string json_strings(const std::vector<std::string>& v);

/// The conditions of one kind, as a table cell: "ok", "fails 1,2",
/// "skipped" or "-" (the model has none of that kind).
std::string cell(const RuleVerdict& v, RuleCondition kind);

}  // namespace dartcheck::cli
