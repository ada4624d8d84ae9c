// What each condition a verdict names means, and where docs/conditions.md
// explains it: one entry per family of names ("I(1)", "C(0,2)", "A(pos)",
// "merge(pos)", "mismatch", ...), shared by SARIF's reportingDescriptors and
// anything else that links a failure to its definition.
#pragma once

#include <string>
#include <string_view>

namespace dartcheck::reports {

struct ConditionHelp {
  std::string_view anchor;   // the id of its section in docs/conditions.md
  std::string_view summary;  // one sentence
  std::string_view source;   // where the seed papers define it
};

/// The family of a condition name as verdicts, baselines and SARIF write
/// it; an unknown name gets the generic embedding entry (Jerboa checks).
const ConditionHelp& condition_help(std::string_view name);

/// The address of its section: DARTCHECK_DOCS_URL (a CMake cache variable,
/// an http or https address where the docs are published) followed by
/// conditions.md#anchor; empty when the variable is not set (a file:// link
/// would be dead wherever the SARIF is read).
std::string condition_help_uri(std::string_view name);

/// Its section of docs/conditions.md, as Markdown (built in at compile
/// time); the summary and source when the page has no such section.
std::string condition_help_markdown(std::string_view name);

}  // namespace dartcheck::reports
