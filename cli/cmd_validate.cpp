#include <optional>

#include <fmt/format.h>

#include "io/jerboa_jba.hpp"
#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "reports/json_document.hpp"
#include "reports/validity_json.hpp"
#include "reports/validity_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"
#include "core/terminal.hpp"

namespace dartcheck::cli {

using reports::print_validity;

using namespace analysis;  // the engines the commands call
int validate_map(const ValidateOptions& o) {
  const Model model = command_model(o.model);
  const bool json = o.format == "json";
  // -q: nothing for a valid map; an invalid one's violations (up to
  // --limit) as diagnostic lines on stderr.
  if (!json && terminal().quiet) {
    const bool jba = o.target.ends_with(".jba");
    const std::optional<JbaFile> f = jba ? std::optional(read_jba(o.target)) : std::nullopt;
    const Map map = jba ? f->map : resolve_map(o.target, model, nullptr);
    const reports::Json doc = reports::validity_document(o.target, "", map, check_map(map), o.limit, jba ? &*f : nullptr);
    for (const auto& v : doc["violations"])
      fmt::print(stderr, "{}: error: dart {}: {}\n", printable(o.target), v["dart"].get<std::size_t>(), v["message"].get<std::string>());
    if (jba)
      for (const auto& e : doc["jerboa"]["embeddings"])
        for (const auto& c : e["conflicts"]) fmt::print(stderr, "{}: error: embedding {}: {}\n", printable(o.target), printable(e["name"].get<std::string>()), printable(c.get<std::string>()));
    const bool good = jba ? doc["jerboa"]["consistently_embedded"].get<bool>() : doc["valid"].get<bool>();
    return good ? ok : violation;
  }
  if (o.target.ends_with(".jba")) {
    const JbaFile f = read_jba(o.target);
    const std::string description = fmt::format("{} (Jerboa, written by {})", describe_target(o.target, f.map), f.name);
    if (json) {
      const reports::Json doc = reports::validity_document(o.target, description, f.map, check_map(f.map), o.limit, &f);
      fmt::print("{}\n", reports::json_text(doc));
      return doc["jerboa"]["consistently_embedded"].get<bool>() ? ok : violation;
    }
    fmt::print("map: {}\n", description);
    return reports::print_jba_validity(stdout, f, o.limit) ? ok : violation;
  }
  const Map map = resolve_map(o.target, model, nullptr);
  const auto report = check_map(map);
  if (json) {
    fmt::print("{}\n", reports::json_text(reports::validity_document(o.target, describe_target(o.target, map), map, report, o.limit)));
  } else {
    fmt::print("map: {}\n", describe_target(o.target, map));
    print_validity(stdout, map, report, o.limit);
  }
  return report.valid() ? ok : violation;
}

}  // namespace dartcheck::cli
