#include "campaign/events_output.hpp"

#include <cstdio>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/input_error.hpp"
#include "core/terminal.hpp"
#include "core/wording.hpp"
#include "campaign/detail/shard_stream.hpp"
#include "reports/events_report.hpp"
#include "reports/json_document.hpp"

namespace dartcheck::campaign {

using reports::Json;

struct EventsOutput::Rules {
  Json array = Json::array();
};

EventsOutput::EventsOutput(reports::OutputFormat format, std::string catalog, const std::string& rule, const Shard& shard,
                           const Parameters& parameters)
    : format_(format), catalog_(std::move(catalog)), rules_(std::make_unique<Rules>()) {
  if (format_ == reports::OutputFormat::jsonl) lines_.emplace(make_header("events", catalog_, "", rule, shard, parameters));
}

EventsOutput::~EventsOutput() = default;

void EventsOutput::analysed(const analysis::RuleEvents& r) {
  const Json json = reports::events_json(r);
  rule(*r.rule, &json, reports::events_text(r));
  if (format_ == reports::OutputFormat::text && terminal().quiet) {
    // -q: what makes the exit status non-zero, one diagnostic line each.
    const std::string where = fmt::format("{}: error: {}", r.rule->location.str(), printable(r.rule->rule.name()));
    if (const auto& a = r.application; a && !a->applied())
      fmt::print(stderr, "{}: does not apply to {} at {}: {} ({})\n", where, a->host, fmt::join(a->hooks, ","), a->refusal, a->why);
    else if (a && !a->validity.valid())
      fmt::print(stderr, "{}: the result of its application to {} is not a valid {}\n", where, a->host, r.rule->rule.model().name);
    for (const auto& k : r.kinds)
      if (k.check)
        for (const auto& c : k.check->contradictions) fmt::print(stderr, "{}: SOUNDNESS BUG: {}\n", where, printable(c));
  }
}

void EventsOutput::not_analysed(const CatalogRule& rule, const std::string& why) {
  ++not_analysed_;
  const Json json{{"rule", rule.rule.name()}, {"model", rule.rule.model().name}, {"analysed", false}, {"why", why}};
  this->rule(rule, &json, hanging(fmt::format("rule {} ({}): not analysed:", rule.rule.name(), rule.rule.model().name), why, 2));
}

void EventsOutput::skipped(const CatalogRule& rule, const std::string& why) {
  ++skipped_;
  this->rule(rule, nullptr, hanging(fmt::format("rule {} ({}): skipped:", rule.rule.name(), rule.rule.model().name), why, 2));
}

void EventsOutput::rule(const CatalogRule& rule, const Json* json, const std::string& text) {
  if (lines_)
    lines_->fragment(rule.rule.name(), json ? *json : Json(nullptr), text);
  else if (format_ == reports::OutputFormat::json && json)
    rules_->array.push_back(*json);
  else if (format_ != reports::OutputFormat::json && !terminal().quiet) {
    fmt::print("{}", text);
    std::fflush(stdout);  // a run ended by a signal inside the next rule keeps this one
  }
}

void EventsOutput::finish(int status, std::size_t analysed, bool interrupted) {
  if (lines_) {
    lines_->summary(
        Json{{"status", status}, {"analysed", analysed}, {"not_analysed", not_analysed_}, {"skipped", skipped_}, {"interrupted", interrupted}});
  } else if (format_ == reports::OutputFormat::text && !terminal().quiet) {
    fmt::print("{}", events_counts_line(analysed, not_analysed_, skipped_));
  } else if (format_ == reports::OutputFormat::json) {
    Json doc = reports::json_document("events");
    doc["catalog"] = catalog_;
    doc["rules"] = std::move(rules_->array);
    fmt::print("{}\n", reports::json_text(std::move(doc)));
  }
}

std::string events_counts_line(std::size_t analysed, std::size_t not_analysed, std::size_t skipped) {
  return fmt::format("\n{}: {} analysed, {} not analysed{}\n", counted(analysed + not_analysed + skipped, "rule"), analysed, not_analysed,
                     skipped ? fmt::format(", {} skipped by --orbit", skipped) : std::string());
}

}  // namespace dartcheck::campaign
