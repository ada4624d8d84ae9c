#include "reports/ci_formats.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pugixml.hpp>

#include "reports/condition_help.hpp"
#include "reports/json_document.hpp"

namespace dartcheck::reports {

using namespace analysis;

namespace {

// Where SARIF's paths start: the repository (the nearest folder with a
// .git above the catalog) whose root %SRCROOT% names, so that code scanning
// finds the files in its checkout; without one, the directory dartcheck
// ran in. A file outside that root gets an absolute file:// URI.
struct SourceRoot {
  std::filesystem::path root;
  bool repository = false;

  explicit SourceRoot(const std::string& catalog) {
    std::error_code ec;
    const auto cwd = std::filesystem::current_path(ec);
    root = cwd;
    for (auto dir = std::filesystem::absolute(catalog, ec).parent_path(); !ec && !dir.empty(); dir = dir.parent_path()) {
      if (std::filesystem::exists(dir / ".git", ec)) {
        root = dir;
        repository = true;
        break;
      }
      if (dir == dir.root_path()) break;
    }
  }

  Json artifact(const std::string& path) const {
    std::error_code ec;
    const auto absolute = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
    const auto relative = absolute.lexically_relative(std::filesystem::weakly_canonical(root, ec));
    const std::string text = relative.generic_string();
    if (!path.empty() && !ec && !relative.empty() && !text.starts_with(".."))
      return Json{{"uri", uri_path(text)}, {"uriBaseId", "%SRCROOT%"}};
    return Json{{"uri", "file://" + uri_path(absolute.generic_string())}};
  }

  Json base_ids() const {
    std::error_code ec;
    std::string uri = "file://" + uri_path(std::filesystem::weakly_canonical(root, ec).generic_string());
    if (uri.back() != '/') uri += '/';
    return Json{{"%SRCROOT%", Json{{"uri", uri},
                                   {"description", Json{{"text", repository ? "the root of the repository that holds the catalog"
                                                                            : "the directory dartcheck ran in (the catalog is in no git repository)"}}}}}};
  }
};

Json sarif_location(const SourceRoot& root, const std::string& file, const SourceLocation& at) {
  const std::string path = at.file.empty() ? file : at.file;
  Json artifact = root.artifact(path);
  return Json::array(
      {Json{{"physicalLocation", Json{{"artifactLocation", std::move(artifact)},
                                      {"region", Json{{"startLine", std::max(at.line, 1)}, {"startColumn", std::max(at.column, 1)}}}}}}});
}

// The code point at s[k] of valid UTF-8, and its length.
std::pair<unsigned, std::size_t> decode(const std::string& s, std::size_t k) {
  const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned c = b(k);
  if (c < 0x80) return {c, 1};
  if (c < 0xE0) return {((c & 0x1F) << 6) | (b(k + 1) & 0x3F), 2};
  if (c < 0xF0) return {((c & 0x0F) << 12) | ((b(k + 1) & 0x3F) << 6) | (b(k + 2) & 0x3F), 3};
  return {((c & 0x07) << 18) | ((b(k + 1) & 0x3F) << 12) | ((b(k + 2) & 0x3F) << 6) | (b(k + 3) & 0x3F), 4};
}

}  // namespace

std::string xml_safe(const std::string& text) {
  const std::string s = valid_utf8(text) ? text : replace_invalid_utf8(text);
  std::string out;
  out.reserve(s.size());
  for (std::size_t k = 0; k < s.size();) {
    const auto [cp, n] = decode(s, k);
    const bool allowed = cp == 0x9 || cp == 0xA || cp == 0xD || (cp >= 0x20 && cp <= 0xD7FF) || (cp >= 0xE000 && cp <= 0xFFFD) || cp >= 0x10000;
    if (allowed)
      out.append(s, k, n);
    else
      out += "\xEF\xBF\xBD";
    k += n;
  }
  return out;
}

std::string uri_path(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/')
      out += static_cast<char>(c);
    else
      out += fmt::format("%{:02X}", c);
  }
  return out;
}

std::string sarif_document(const std::string& catalog, const std::vector<RuleResult>& results, const std::string& version) {
  Json sarif_results = Json::array();
  std::vector<std::string> ids;
  const SourceRoot root(catalog);
  // A failure the catalog (or baseline) records is expected: a suppressed
  // result, which code scanning does not open as an alert.
  auto add = [&](const std::string& id, bool unexpected, const std::string& text, const RuleResult& r) {
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
    Json result{{"ruleId", id},
                {"level", "error"},
                {"message", Json{{"text", text}}},
                {"locations", sarif_location(root, catalog, r.entry->location)},
                {"properties", Json{{"rule", r.name()}, {"recorded", r.recorded_text()}, {"solver", r.solver_lines()}}}};
    if (!unexpected)
      result["suppressions"] = Json::array({Json{{"kind", "external"},
                                                 {"status", "accepted"},
                                                 {"justification", fmt::format("the {} records this failure: an expected verdict", r.record_source_name())}}});
    sarif_results.push_back(std::move(result));
  };
  for (const RuleResult& r : results) {
    const auto& recorded = r.entry->expected_failures;
    const auto is_recorded = [&](const std::string& name) {
      return recorded && std::find(recorded->begin(), recorded->end(), name) != recorded->end();
    };
    for (const auto& v : r.verdict.conditions) {
      if (v.holds) continue;
      std::vector<std::string> texts;
      for (const auto& w : v.witnesses) texts.push_back(w.text);
      add(v.name(), !is_recorded(v.name()), fmt::format("rule {}: {} fails: {}", r.name(), v.name(), fmt::join(texts, "; ")), r);
    }
    for (const auto& name : failing_names(r.embedding)) add(name, !is_recorded(name), fmt::format("rule {}: {} fails", r.name(), name), r);
    for (const auto& m : r.mismatches)
      add(r.unsound() && m.rfind("SOUNDNESS", 0) == 0 ? "soundness" : "mismatch", true, fmt::format("rule {}: {}", r.name(), m), r);
  }
  Json rules = Json::array();
  // One reportingDescriptor per condition met, linked to its definition.
  for (const auto& id : ids) {
    const ConditionHelp& help = condition_help(id);
    const std::string markdown = condition_help_markdown(id);
    Json rule{{"id", id},
              {"shortDescription", Json{{"text", std::string(help.summary)}}},
              {"fullDescription", Json{{"text", fmt::format("{} ({})", help.summary, help.source)}}},
              {"help", Json{{"text", markdown}, {"markdown", markdown}}}};
    if (const std::string uri = condition_help_uri(id); !uri.empty()) rule["helpUri"] = uri;
    rules.push_back(std::move(rule));
  }
  Json run{{"tool", Json{{"driver", Json{{"name", "dartcheck"}, {"version", version}, {"rules", std::move(rules)}}}}},
           {"originalUriBaseIds", root.base_ids()},
           {"results", std::move(sarif_results)}};
  Json doc{{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"}, {"version", "2.1.0"}, {"runs", Json::array({std::move(run)})}};
  return json_text(std::move(doc));
}

std::string junit_document(const std::string& command, const std::string& catalog, const std::vector<RuleResult>& results,
                           const std::vector<std::string>& extra_failures) {
  double total_ms = 0;
  std::size_t failures = extra_failures.size();
  for (const auto& r : results) total_ms += r.static_ms, failures += !r.matches_record();
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  auto suites = doc.append_child("testsuites");
  suites.append_attribute("name") = xml_safe("dartcheck " + command).c_str();
  suites.append_attribute("tests") = static_cast<unsigned long long>(results.size() + extra_failures.size());
  suites.append_attribute("failures") = static_cast<unsigned long long>(failures);
  suites.append_attribute("time") = fmt::format("{:.3f}", total_ms / 1000).c_str();
  auto suite = suites.append_child("testsuite");
  suite.append_attribute("name") = xml_safe(catalog).c_str();
  suite.append_attribute("tests") = static_cast<unsigned long long>(results.size() + extra_failures.size());
  suite.append_attribute("failures") = static_cast<unsigned long long>(failures);
  suite.append_attribute("errors") = 0;
  suite.append_attribute("time") = fmt::format("{:.3f}", total_ms / 1000).c_str();
  for (const auto& r : results) {
    const CatalogRule& e = *r.entry;
    auto tc = suite.append_child("testcase");
    tc.append_attribute("name") = xml_safe(r.name()).c_str();
    tc.append_attribute("classname") = xml_safe(e.rule.model().name).c_str();
    tc.append_attribute("file") = xml_safe(e.location.file.empty() ? catalog : e.location.file).c_str();
    tc.append_attribute("line") = e.location.line;
    tc.append_attribute("time") = fmt::format("{:.6f}", r.static_ms / 1000).c_str();
    if (!r.matches_record()) {
      auto f = tc.append_child("failure");
      const std::string recorded = e.expected_failures ? fmt::format("records '{}'", r.recorded_text()) : "records no verdict";
      f.append_attribute("message") = xml_safe(fmt::format("{}, the {} {}", r.verdict_text(), r.record_source_name(), recorded)).c_str();
      f.append_attribute("type") = r.unsound() ? "soundness" : "verdict";
      f.text() = xml_safe(fmt::format("{}: {}", e.location.str(), fmt::join(r.mismatches, "; "))).c_str();
    }
    const std::string confirmation = r.confirmation_text();
    std::string solver;
    for (const auto& line : r.solver_lines()) solver += "; " + line;
    tc.append_child("system-out").text() = xml_safe(r.verdict_text() + (confirmation.empty() ? "" : "; " + confirmation) + solver).c_str();
  }
  for (std::size_t k = 0; k < extra_failures.size(); ++k) {
    auto tc = suite.append_child("testcase");
    tc.append_attribute("name") = fmt::format("baseline-{}", k + 1).c_str();
    tc.append_attribute("classname") = "baseline";
    auto f = tc.append_child("failure");
    f.append_attribute("message") = xml_safe(extra_failures[k]).c_str();
    f.append_attribute("type") = "baseline";
  }
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

}  // namespace dartcheck::reports
