// The renderers of `dartcheck events` (004): a rule's events per orbit
// type and, for one application, the event logs, the dynamic check and
// whether H is a map of the model at all.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/rule_events.hpp"
#include "reports/json_fwd.hpp"

namespace dartcheck::reports {

using analysis::EventsApplication;
using analysis::KindEventsResult;
using analysis::RuleEvents;

std::string events_text(const RuleEvents& r);
Json events_json(const RuleEvents& r);

}  // namespace dartcheck::reports
