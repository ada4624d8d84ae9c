// `dartcheck report`: one self-contained HTML page for a catalog. A verdict
// table (rules x conditions, each failing cell linked to its witnesses),
// then a section per rule: its picture with the witnesses highlighted, the
// static verdict against the recorded one, and, when asked, what the fuzzer
// and the solver found, each counterexample drawn as G, H and the rule.
// The pictures are also written as SVG files beside the page, and each
// counterexample as the files `dartcheck apply` replays.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <random>

#include <fmt/format.h>

#include "analysis/interrupt.hpp"
#include "analysis/map_sources.hpp"
#include "analysis/rule_result.hpp"
#include "analysis/verdict_record.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "reports/html_page.hpp"
#include "reports/report_page.hpp"
#include "reports/rule_result_json.hpp"
#include "reports/rule_result_text.hpp"

namespace dartcheck::cli {

using namespace analysis;  // the engines the commands call
namespace fs = std::filesystem;
using reports::html_text;

namespace {

// Fuzzes every rule within `seconds` (shared) and adds each outcome; the
// page's sentence about it.
std::string fuzz_stage(std::vector<RuleResult>& rows, const Catalog& catalog, const ReportOptions& o, double seconds, const std::string& cx_dir) {
  FuzzOptions fo;
  fo.seed = o.seed ? *o.seed : std::random_device{}();
  fo.runs = SIZE_MAX;
  std::vector<Map> seeds;
  for (const auto& s : catalog.maps) seeds.push_back(build_source(s));
  std::vector<const Operation*> rules;
  for (const auto& r : rows) rules.push_back(r.entry);
  fmt::print(stderr, "dartcheck report: fuzzing {} rule{} for {} s, seed {}\n", rules.size(), rules.size() == 1 ? "" : "s", seconds, fo.seed);
  auto found = fuzz_rules(rules, seeds, fo, seconds, isatty(fileno(stderr)) != 0);
  std::size_t applications = 0;
  for (std::size_t k = 0; k < found.size(); ++k) {  // fewer than rows if interrupted
    applications += found[k].applications;
    add_fuzz(rows[k], std::move(found[k]), fo.seed, cx_dir, o.catalog, ".fuzz");
  }
  return fmt::format("<p>Fuzz: {} s, seed {} (<code>--seed {}</code> replays it), {} application{}.</p>\n", seconds, fo.seed, fo.seed, applications,
                     applications == 1 ? "" : "s");
}

// Asks Z3 about every rule (until a signal) and adds each proof; the
// page's sentence about it.
std::string prove_stage(std::vector<RuleResult>& rows, const ReportOptions& o, const std::string& cx_dir) {
  proofs::ProveOptions po;
  po.max_darts = o.prove_darts;
  po.scheme_darts = std::min<std::size_t>(po.scheme_darts, o.prove_darts);
  fmt::print(stderr, "dartcheck report: proving {} rule{} up to {} darts (schemes {})\n", rows.size(), rows.size() == 1 ? "" : "s", po.max_darts,
             po.scheme_darts);
  for (auto& r : rows) {
    if (interrupted()) break;
    run_proof(r, po, cx_dir, o.catalog, ".prove");
  }
  return fmt::format("<p>Prove: Z3 on hosts of up to {} darts (rule schemes {}).</p>\n", po.max_darts, po.scheme_darts);
}

}  // namespace

int report(const ReportOptions& o) {
  Catalog catalog = read_command_catalog(o.catalog, o.rule, "text");
  const auto baseline_mismatches = o.baseline.empty() ? std::vector<std::string>{} : apply_baseline(catalog, o.baseline);
  const RecordSource source = o.baseline.empty() ? RecordSource::catalog : RecordSource::baseline;
  catch_interrupts();
  std::optional<double> seconds;
  if (!o.fuzz.empty()) seconds = parse_duration(o.fuzz, "--fuzz");
  if (o.prove_darts > 256) throw InputError("<command line>", 0, 0, "--prove: expected 0 (no proof) to 256 darts");
  ensure_directory(o.output);  // before the work, not after it
  const fs::path dir(o.output);
  const std::string cx_dir = (dir / "counterexamples").string();

  std::vector<RuleResult> rows;
  for (const auto& e : catalog.rules)
    if (o.rule.empty() || e.rule.name() == o.rule) rows.push_back(analyse_static(catalog, e, 0, {}, source));
  const auto static_counts = count_results(rows);
  std::string summary = fmt::format("<p>{} rule{}: {} consistent, {} with failing conditions; {} static verdicts differ from the {}.</p>\n",
                                    rows.size(), rows.size() == 1 ? "" : "s", static_counts.consistent, static_counts.failing,
                                    static_counts.mismatches, o.baseline.empty() ? "catalog" : "baseline");
  if (seconds) summary += fuzz_stage(rows, catalog, o, *seconds, cx_dir);
  if (o.prove_darts > 0) summary += prove_stage(rows, o, cx_dir);
  for (const auto& sk : catalog.skipped)
    summary += fmt::format("<p class=\"mismatch\">Skipped {} ({}): {}</p>\n", html_text(sk.name), html_text(sk.location.str()), html_text(sk.why));
  const auto counts = count_results(rows);
  if (counts.unsound)
    summary +=
        fmt::format("<p class=\"mismatch\">{} rule{} with a SOUNDNESS BUG or a disagreement.</p>\n", counts.unsound, counts.unsound == 1 ? "" : "s");

  reports::Pictures pictures(dir.string(), o.engine);
  std::string body = fmt::format("<h1>dartcheck report: {}</h1>\n", html_text(o.catalog)) + summary;
  body +=
      "<p class=\"note\">Pictures: L and R side by side; preserved black, deleted red, added green; hooks with a double border; "
      "filled nodes and doubled arcs are the witnesses of a failed condition. Links: 0 black, 1 red, 2 blue, 3 green.</p>\n";
  body += reports::verdict_table_html(rows, seconds.has_value(), o.prove_darts > 0);
  for (const auto& r : rows) body += reports::rule_section_html(r, pictures);
  const std::string index = (dir / "index.html").string(), data = (dir / "results.json").string();
  const std::string page = reports::html_document("dartcheck report: " + o.catalog, body);
  write_file(index, page);
  // The same results as data, in check's JSON form, beside the page.
  write_file(data, reports::json_text(reports::results_document("report", o.catalog, catalog, rows, baseline_mismatches)) + "\n");
  fmt::print("wrote {} ({} rule{}, {} pictures, {} bytes) and {}\n", index, rows.size(), rows.size() == 1 ? "" : "s", pictures.count(), page.size(),
             data);
  return finish_run(rows, baseline_mismatches, rows.size());
}

}  // namespace dartcheck::cli
