// `dartcheck convert`: a catalog (a Jerboa .jme modeler, or YAML) written
// as a YAML catalog that checks identically (core/catalog_writer).

#include <fmt/format.h>

#include "core/wording.hpp"
#include "cli/commands.hpp"
#include "core/terminal.hpp"
#include "cli/options.hpp"
#include "analysis/map_sources.hpp"
#include "io/catalog_writer.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"

namespace dartcheck::cli {

using namespace analysis;  // the engines the commands call

int convert(const ConvertOptions& o) {
  const Catalog catalog = read_catalog(o.input);
  if (!o.output.ends_with(".yaml") && !o.output.ends_with(".yml"))
    throw UsageError(fmt::format("-o: '{}': expected a file name ending in .yaml or .yml", o.output));
  const std::string text = catalog_yaml(catalog);
  write_file(o.output, text);
  if (!terminal().quiet)
    fmt::print("wrote {}: {}, {} skipped, {}\n", o.output, counted(catalog.rules.size(), "rule"), catalog.skipped.size(),
             counted(catalog.embeddings.size(), "embedding"));
  return ok;
}

}  // namespace dartcheck::cli
