// The output formats of the commands (--format), resolved once where the
// command line is read: the libraries take this type, never the option's
// text.
#pragma once

#include <cstdint>
#include <string_view>

namespace dartcheck::reports {

enum class OutputFormat : std::uint8_t {
  text,   // tables and sentences for a reader
  json,   // one document (docs/schema/)
  jsonl,  // a shard's lines, for merge
  sarif,  // SARIF 2.1.0, for code-scanning tools
  junit,  // JUnit XML, for CI test reports
  html,   // report's page (in a directory)
};

std::string_view name_of(OutputFormat f);

/// The format `name` spells (as --format does); UsageError otherwise.
OutputFormat output_format(std::string_view name);

}  // namespace dartcheck::reports
