// JSON documents of every command, built with nlohmann::json (never with
// format strings), so that any name, in any bytes, gives valid JSON.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "reports/json_fwd.hpp"

namespace dartcheck::reports {

/// The version of dartcheck's JSON and JSONL formats: documents carry it
/// as "format_version"; docs/schema/ holds one JSON Schema per document.
inline constexpr int json_format_version = 4;  // 4: fuzz "checked"

/// An object that starts a document of `command` ("check", "fuzz", ...):
/// {"format": "dartcheck-check", "format_version": 4}.
Json json_document(std::string_view command);

/// The document as text, on one line (indent < 0) or indented. Strings that
/// are not valid UTF-8 have each invalid sequence replaced by U+FFFD; an
/// object document then says so in "replaced_invalid_utf8" (the number of
/// strings changed), so a reader knows a name is not exactly the input's.
std::string json_text(Json document, int indent = -1);

/// Whether `s` is well-formed UTF-8 (no overlong forms, no surrogates).
bool valid_utf8(std::string_view s);

/// `s` with each maximal invalid UTF-8 sequence replaced by U+FFFD.
std::string replace_invalid_utf8(std::string_view s);

}  // namespace dartcheck::reports
