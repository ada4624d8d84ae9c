#include "core/terminal.hpp"
#include "campaign/detail/shard_stream.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include <fmt/format.h>

#include "campaign/input_run.hpp"
#include "campaign/detail/result_record.hpp"
#include "core/input_error.hpp"
#include "io/input_file.hpp"
#include "reports/querymodify_report.hpp"
#include "reports/rule_result_json.hpp"

namespace dartcheck::campaign {

using reports::Json;

namespace {

Json header_json(const RunHeader& h) {
  return Json{{"command", h.command},
              {"catalog", h.catalog},
              {"catalog_digest", h.catalog_digest},
              {"baseline", h.baseline},
              {"baseline_digest", h.baseline_digest},
              {"rule", h.rule},
              {"shard", h.shard.text()},
              {"parameters", h.parameters}};
}

std::string string_at(const Json& j, const char* key, const std::string& file, int line) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_string())
    throw InputError(file, line, 1, fmt::format("expected a string \"{}\" in this line", key));
  return j[key].get<std::string>();
}

RunHeader read_header(const Json& j, const std::string& file, int line) {
  RunHeader h;
  h.command = string_at(j, "command", file, line);
  static const std::set<std::string> commands{"check", "fuzz", "prove", "report", "events", "recombine", "query"};
  if (!commands.contains(h.command))
    throw InputError(
        file, line, 1,
        fmt::format("a header of command '{}': merge reads check, fuzz, prove, report, events, recombine and query", printable(h.command)));
  h.catalog = string_at(j, "catalog", file, line);
  h.catalog_digest = string_at(j, "catalog_digest", file, line);
  h.baseline = string_at(j, "baseline", file, line);
  h.baseline_digest = string_at(j, "baseline_digest", file, line);
  h.rule = string_at(j, "rule", file, line);
  try {
    h.shard = parse_shard(string_at(j, "shard", file, line), "shard");
  } catch (const InputError& e) {
    throw InputError(file, line, 1, e.message());
  }
  if (!j.contains("parameters") || !j["parameters"].is_object()) throw InputError(file, line, 1, "expected an object \"parameters\" in the header");
  h.parameters = j["parameters"];
  return h;
}

// The first difference between two runs' headers, or "".
std::string difference(const RunHeader& a, const RunHeader& b) {
  const auto field = [](const char* name, const std::string& x, const std::string& y) {
    return x == y ? std::string() : fmt::format("{} '{}' against '{}'", name, printable(x), printable(y));
  };
  for (auto d :
       {field("command", a.command, b.command), field("catalog", a.catalog, b.catalog), field("catalog digest", a.catalog_digest, b.catalog_digest),
        field("baseline", a.baseline, b.baseline), field("baseline digest", a.baseline_digest, b.baseline_digest), field("--rule", a.rule, b.rule)})
    if (!d.empty()) return d;
  if (a.shard.count != b.shard.count) return fmt::format("shard count {} against {}", a.shard.count, b.shard.count);
  if (a.parameters != b.parameters) return fmt::format("options {} against {}", a.parameters.dump(), b.parameters.dump());
  return {};
}

}  // namespace

RunHeader make_header(std::string command, const std::string& catalog, const std::string& baseline, const std::string& rule, Shard shard,
                      const Parameters& parameters) {
  RunHeader h;
  h.command = std::move(command);
  h.catalog = catalog;
  // A per-input command may read a mesh by its stem (x for x.node and x.ele).
  h.catalog_digest = std::filesystem::is_regular_file(catalog) ? file_digest(catalog) : std::string();
  h.baseline = baseline;
  h.baseline_digest = baseline.empty() ? std::string() : file_digest(baseline);
  h.rule = rule;
  h.shard = shard;
  for (const auto& [name, value] : parameters)
    h.parameters[name] = std::visit(
        [](const auto& v) {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>)
            return Json(nullptr);
          else
            return Json(v);
        },
        value);
  return h;
}

Json run_summary(const std::vector<analysis::RuleResult>& results, std::size_t selected, bool interrupted, double seconds,
                 const std::vector<std::string>& baseline_mismatches) {
  return Json{{"rules", selected},
              {"finished", results.size()},
              {"interrupted", interrupted},
              {"seconds", seconds},
              {"counts", reports::counts_json(analysis::count_results(results))},
              {"baseline_mismatches", baseline_mismatches}};
}

bool per_input_command(std::string_view command) { return command == "recombine" || command == "query"; }

ShardWriter::ShardWriter(const RunHeader& header) : command_(header.command) { line("header", header_json(header), std::nullopt); }

void ShardWriter::rule(const analysis::RuleResult& r) { line("rule", reports::rule_result_json(r), result_record(r)); }

void ShardWriter::input(Json document, const std::string& text) {
  line("input", Json{{"document", std::move(document)}, {"text", text}}, std::nullopt);
}

void ShardWriter::fragment(const std::string& rule, Json json, const std::string& text) {
  line("fragment", Json{{"rule", rule}, {"json", std::move(json)}, {"text", text}}, std::nullopt);
}

void ShardWriter::summary(Json summary) { line("summary", std::move(summary), std::nullopt); }

void ShardWriter::line(const char* type, Json payload, std::optional<Json> record) {
  Json j = reports::json_document(command_ + "-jsonl");
  j["type"] = type;
  j[type] = std::move(payload);
  if (record) j["record"] = std::move(*record);
  fmt::print("{}\n", reports::json_text(std::move(j)));
  std::fflush(stdout);  // a shard killed later keeps this line
}

namespace {

// One line of a shard as JSON.
Json parse_shard_line(std::string_view text, const std::string& file, int line) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw InputError(file, line, static_cast<int>(std::min<std::size_t>(e.byte, text.size() + 1)),
                     fmt::format("not a JSON line of --format jsonl: {}", e.what()));
  } catch (const Json::exception& e) {
    // A number out of double's range ("4.61e607", found by fuzz_shard)
    // is nlohmann's out_of_range, not a parse_error.
    throw InputError(file, line, 1, fmt::format("not a JSON line of --format jsonl: {}", e.what()));
  }
  return j;
}

// A line of another version may mean the same keys differently: refused, not guessed.
void check_format_version(const Json& j, const std::string& file, int line) {
  if (!j.contains("format_version") || j["format_version"] != reports::json_format_version)
    throw InputError(
        file, line, 1,
        fmt::format("format_version {}: this dartcheck reads version {} (run the shard again with this version)",
                    j.contains("format_version") ? printable(j["format_version"].dump()) : std::string("missing"), reports::json_format_version));
}

// The summary line: the fields merge reads, of the types it reads them
// as; a run a signal stopped is read only with `incomplete`.
void read_summary(const Json& j, const std::string& file, int line, bool incomplete, ShardFile& out) {
  if (!j.contains("summary") || !j["summary"].is_object()) throw InputError(file, line, 1, "a summary line without a \"summary\" object");
  out.summary = j["summary"];
  // The fields merge reads, of the types it reads them as.
  const Json& sum = out.summary;
  const auto bad = [&](const char* key, const char* what) { throw InputError(file, line, 1, fmt::format("summary \"{}\": expected {}", key, what)); };
  for (const char* key : {"rules", "finished"})
    if (sum.contains(key) && !sum[key].is_number_unsigned()) bad(key, "a count");
  if (sum.contains("seconds") && !sum["seconds"].is_number()) bad("seconds", "a number");
  if (sum.contains("interrupted") && !sum["interrupted"].is_boolean()) bad("interrupted", "true or false");
  if (sum.contains("status") && !(sum["status"] == 0 || sum["status"] == 1 || sum["status"] == 3 || sum["status"] == 130))
    bad("status", "0, 1, 3 or 130");
  // A signal stopped the run: its summary says so, or (recombine, query, events) its status is 130.
  if (out.summary.value("interrupted", false) || out.summary.value("status", 0) == 130) {
    if (!incomplete) throw InputError(file, line, 1, "this shard was interrupted: run it again (its rules are not all there), or merge --incomplete");
    out.finished = false;
  }
}

}  // namespace

ShardFile read_shard_file(const std::string& file, bool incomplete) {
  TextLines lines(read_input(file));
  ShardFile out;
  out.file = file;
  bool header = false;
  int line = 0;
  while (const auto next = lines.next()) {
    line = lines.number();
    const std::string_view text = *next;
    if (text.empty()) continue;
    const Json j = parse_shard_line(text, file, line);
    const std::string type = string_at(j, "type", file, line);
    const std::string format = string_at(j, "format", file, line);
    check_format_version(j, file, line);
    if (!header && type != "header")
      throw InputError(file, line, 1, "the first line is not a header: shards are the output of --format jsonl with this version of dartcheck");
    if (!out.summary.is_null()) throw InputError(file, line, 1, "a line after the summary");
    if (type == "header") {
      if (header) throw InputError(file, line, 1, "a second header: one shard per file");
      out.header = read_header(j.value("header", Json()), file, line);
      if (format != "dartcheck-" + out.header.command + "-jsonl")
        throw InputError(file, line, 1, fmt::format("format '{}' for command '{}'", printable(format), printable(out.header.command)));
      header = true;
    } else if (type == "rule") {
      if (!j.contains("rule") || !j.contains("record")) throw InputError(file, line, 1, "a rule line without \"rule\" and \"record\"");
      out.rules.push_back({string_at(j["rule"], "name", file, line), j["record"], line});
    } else if (type == "fragment") {
      const Json& f = j.value("fragment", Json());
      if (!f.is_object() || !f.contains("json") || !f.contains("text") || !f["text"].is_string())
        throw InputError(file, line, 1, "a fragment line without \"rule\", \"json\" and \"text\"");
      string_at(f, "rule", file, line);
      out.fragments.push_back(f);
    } else if (type == "input") {
      if (!j.contains("input") || !j["input"].is_object() || !j["input"].contains("document") || !j["input"].contains("text") ||
          !j["input"]["text"].is_string() || !out.input.is_null())
        throw InputError(file, line, 1, "an input line without \"document\" and \"text\", or a second one");
      out.input = j["input"];
    } else if (type == "summary") {
      read_summary(j, file, line, incomplete, out);
    } else {
      throw InputError(file, line, 1, fmt::format("unknown line type '{}'", printable(type)));
    }
  }
  if (!header) throw InputError(file, 0, 0, "empty: no header line (did the shard start?)");
  if (out.summary.is_null()) {
    if (!incomplete)
      throw InputError(file, line, 0,
                       fmt::format("no summary line: shard {} did not finish (killed, or out of time?); merge --incomplete reads its finished rules",
                                   out.header.shard.text()));
    out.finished = false;
  }
  return out;
}

std::vector<ShardFile> check_complete(std::vector<ShardFile> files, bool incomplete) {
  if (files.empty()) throw UsageError("merge: no shard files given");
  const RunHeader& first = files.front().header;
  if (per_input_command(first.command)) {
    std::map<std::string, const ShardFile*> by_input;
    for (const auto& f : files) {
      if (f.header.command != first.command || f.header.parameters != first.parameters)
        throw InputError(f.file, 1, 1,
                         fmt::format("not a run of the same campaign as {}: {} {} against {} {}", files.front().file, f.header.command,
                                     f.header.parameters.dump(), first.command, first.parameters.dump()));
      if (f.input.is_null() && !incomplete) throw InputError(f.file, 0, 0, "no input line: the run did not finish");
      const auto [it, fresh] = by_input.emplace(f.header.catalog, &f);
      if (!fresh)
        throw InputError(f.file, 1, 1, fmt::format("{} is also the input of {}: give each run once", printable(f.header.catalog), it->second->file));
    }
    std::sort(files.begin(), files.end(), [](const ShardFile& a, const ShardFile& b) { return a.header.catalog < b.header.catalog; });
    return files;
  }
  std::map<std::size_t, const ShardFile*> by_index;
  for (const auto& f : files) {
    if (const auto d = difference(first, f.header); !d.empty())
      throw InputError(f.file, 1, 1, fmt::format("not a shard of the same run as {}: {}", files.front().file, d));
    const auto [it, fresh] = by_index.emplace(f.header.shard.index, &f);
    if (!fresh) throw InputError(f.file, 1, 1, fmt::format("shard {} is also {}: give each shard once", f.header.shard.text(), it->second->file));
  }
  for (std::size_t k = 0; k < first.shard.count && !incomplete; ++k)
    if (!by_index.contains(k))
      throw UsageError(fmt::format("merge: shard {}/{} is missing ({} of {} given)", k, first.shard.count, files.size(), first.shard.count));
  std::sort(files.begin(), files.end(), [](const ShardFile& a, const ShardFile& b) { return a.header.shard.index < b.header.shard.index; });
  return files;
}

namespace {

void print_input_run(reports::OutputFormat format, const std::string& command, const std::string& input, const Parameters& parameters, Json document,
                     const std::string& text, int status) {
  if (format == reports::OutputFormat::jsonl) {
    ShardWriter lines(make_header(command, input, "", "", {}, parameters));
    lines.input(std::move(document), text);
    lines.summary(Json{{"status", status}});
  } else if (format == reports::OutputFormat::json) {
    fmt::print("{}\n", reports::json_text(std::move(document)));
  } else if (!terminal().quiet) {  // -q: the report is a summary; files and the exit status stay
    fmt::print("{}", text);
  }
}

}  // namespace

void print_input_run(reports::OutputFormat format, const std::string& mesh, const Parameters& parameters, const reports::RecombineRun& run,
                     int status) {
  print_input_run(format, "recombine", mesh, parameters, reports::recombine_document(run), reports::recombine_text(run), status);
}

void print_input_run(reports::OutputFormat format, const std::string& map, const Parameters& parameters, const reports::QueryRun& run, int status) {
  print_input_run(format, "query", map, parameters, reports::query_document(run), reports::query_text(run), status);
}

}  // namespace dartcheck::campaign
