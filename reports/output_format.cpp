#include "reports/output_format.hpp"

#include <array>

#include <fmt/format.h>

#include "core/input_error.hpp"

namespace dartcheck::reports {

namespace {

constexpr std::array all{OutputFormat::text, OutputFormat::json, OutputFormat::jsonl, OutputFormat::sarif, OutputFormat::junit, OutputFormat::html};

}  // namespace

std::string_view name_of(OutputFormat f) {
  switch (f) {
    case OutputFormat::text:
      return "text";
    case OutputFormat::json:
      return "json";
    case OutputFormat::jsonl:
      return "jsonl";
    case OutputFormat::sarif:
      return "sarif";
    case OutputFormat::junit:
      return "junit";
    case OutputFormat::html:
      return "html";
  }
  return "?";
}

OutputFormat output_format(std::string_view name) {
  for (OutputFormat f : all)
    if (name_of(f) == name) return f;
  throw UsageError(fmt::format("--format: '{}' is not an output format (text, json, jsonl, sarif, junit, html)", name));
}

}  // namespace dartcheck::reports
