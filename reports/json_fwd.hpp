// reports::Json declared, not defined: for the headers that only name it in
// declarations, so that their includers do not compile nlohmann/json.hpp
// (reports/json_document.hpp has the whole type).
#pragma once

#include <nlohmann/json_fwd.hpp>

namespace dartcheck::reports {

/// Objects keep the order their keys were added in (readable output).
using Json = nlohmann::ordered_json;

}  // namespace dartcheck::reports
