#include "reports/run_output.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "analysis/exit_status.hpp"
#include "analysis/interrupt.hpp"
#include "analysis/verdict_record.hpp"
#include "core/output_file.hpp"
#include "core/terminal.hpp"
#include "core/wording.hpp"
#include "reports/ci_formats.hpp"
#include "reports/html_page.hpp"
#include "reports/json_document.hpp"
#include "reports/report_page.hpp"
#include "reports/rule_result_json.hpp"
#include "reports/rule_result_text.hpp"
#include "reports/versions.hpp"

namespace dartcheck::reports {

using namespace analysis;

void print_check(OutputFormat format, const std::string& catalog_file, const Catalog& catalog, const Results& results,
                 const std::vector<std::string>& baseline_mismatches, bool explain) {
  if (format == OutputFormat::sarif || format == OutputFormat::junit) {
    print_ci_format(format, "check", catalog_file, results, baseline_mismatches);
  } else if (format == OutputFormat::json) {
    const auto doc = results_document("check", catalog_file, catalog, results, baseline_mismatches);
    fmt::print("{}\n", json_text(doc));
  } else if (!terminal().quiet) {
    fmt::print("{}", check_table(catalog, results, baseline_mismatches.size(), {explain, catalog_file}));
  }
}

void print_ci_format(OutputFormat format, const std::string& command, const std::string& catalog_file, const Results& results,
                     const std::vector<std::string>& baseline_mismatches) {
  if (format == OutputFormat::sarif)
    fmt::print("{}\n", sarif_document(catalog_file, results, dartcheck_version()));
  else
    fmt::print("{}", junit_document(command, catalog_file, results, baseline_mismatches));
}

void print_fuzz(OutputFormat format, const FuzzRun& run, const Results& results) {
  if (format == OutputFormat::json) {
    Json doc = json_document("fuzz");
    Json rows = Json::array();
    for (const auto& r : results) rows.push_back(rule_result_json(r));
    doc["rules"] = std::move(rows);
    doc["summary"] = fuzz_summary_json(run, results);
    fmt::print("{}\n", json_text(std::move(doc)));
  } else if (!terminal().quiet) {
    fmt::print("{}", fuzz_table(run, results));
  }
}

void print_prove(OutputFormat format, const ProveRun& run, const Results& results) {
  if (format == OutputFormat::json)
    fmt::print("{}\n", json_text(prove_document(run, results)));
  else if (!terminal().quiet)
    fmt::print("{}", prove_text(run, results));
}

namespace {

// The page's sentences about the run: counts, then each stage that ran.
std::string summary_html(const Results& rows, const Catalog& catalog, const ReportStages& stages) {
  std::size_t consistent = 0, static_mismatches = 0, applications = 0;
  for (const auto& r : rows) {
    consistent += r.consistent();
    static_mismatches += !matches_record(*r.entry, r.verdict, r.embedding);
    if (r.fuzz) applications += r.fuzz->applications;
  }
  std::string s =
      fmt::format("<p>{}: {} consistent, {} with failing conditions; {} static verdicts differ from the {}.</p>\n", counted(rows.size(), "rule"),
                  consistent, rows.size() - consistent, static_mismatches, stages.baseline ? "baseline" : "catalog");
  if (stages.fuzz_seconds)
    s += fmt::format("<p>Fuzz: {} s, seed {} (<code>--seed {}</code> replays it), {}.</p>\n", *stages.fuzz_seconds, stages.seed, stages.seed,
                     counted(applications, "application"));
  if (stages.prove_darts > 0)
    s += fmt::format("<p>Prove: Z3 on hosts of up to {} darts (rule schemes {}).</p>\n", stages.prove_darts, stages.scheme_darts);
  for (const auto& sk : catalog.skipped)
    s += fmt::format("<p class=\"mismatch\">Skipped {} ({}): {}</p>\n", html_text(sk.name), html_text(sk.location.str()), html_text(sk.why));
  if (const auto unsound = count_results(rows).unsound)
    s += fmt::format("<p class=\"mismatch\">{} with a SOUNDNESS BUG or a disagreement.</p>\n", counted(unsound, "rule"));
  return s;
}

}  // namespace

void write_report(const std::string& dir_name, const std::string& engine, const std::string& catalog_file, const Catalog& catalog,
                  const Results& rows, const std::vector<std::string>& baseline_mismatches, const ReportStages& stages) {
  namespace fs = std::filesystem;
  const fs::path dir(dir_name);
  Pictures pictures(dir.string(), engine);
  std::string body = fmt::format("<h1>dartcheck report: {}</h1>\n", html_text(catalog_file)) + summary_html(rows, catalog, stages);
  body +=
      "<p class=\"note\">Pictures: L and R side by side; lines say what the rule does (solid preserved, dashed deleted, bold added), "
      "an arc's colour its dimension (0 black, 1 red, 2 blue, 3 green), each picture's legend says both; hooks with a double border; "
      "filled nodes and doubled arcs are the witnesses of a failed condition, named in the caption.</p>\n";
  body += verdict_table_html(rows, stages.fuzz_seconds.has_value(), stages.prove_darts > 0);
  for (const auto& r : rows) body += rule_section_html(r, pictures);
  const std::string index = (dir / "index.html").string(), data = (dir / "results.json").string();
  const std::string page = html_document("dartcheck report: " + catalog_file, body);
  write_file(index, page);
  // The same results as data, in check's JSON form, beside the page.
  write_file(data, json_text(results_document("report", catalog_file, catalog, rows, baseline_mismatches)) + "\n");
  if (!terminal().quiet)
    fmt::print("wrote {} ({}, {} pictures, {} bytes) and {}\n", index, counted(rows.size(), "rule"), pictures.count(), page.size(), data);
}

int finish_run(const std::vector<analysis::RuleResult>& results, const std::vector<std::string>& baseline_mismatches, std::size_t selected,
               bool interrupted, bool recording) {
  for (const auto& m : baseline_mismatches) fmt::print(stderr, "baseline: {}\n", printable(m));
  for (const auto& line : mismatch_lines(results, recording)) fmt::print(stderr, "{}\n", painted_diagnostic(line));
  if (const std::string hint = first_run_hint(results); !hint.empty() && !recording && !terminal().quiet) fmt::print(stderr, "{}\n", hint);
  const auto counts = analysis::count_results(results);
  if (interrupted)
    fmt::print(stderr, "interrupted: {} of {} rule{} finished; the results above are theirs\n", results.size(), selected, selected == 1 ? "" : "s");
  if (counts.unsound || counts.events_contradicted) return exit_status::soundness_bug;
  if (interrupted) return analysis::interrupted_exit;
  return counts.mismatches + baseline_mismatches.size() > 0 ? exit_status::violation : exit_status::ok;
}

}  // namespace dartcheck::reports
