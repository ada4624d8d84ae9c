#include "checkers/violation.hpp"

#include <fmt/format.h>

namespace dartcheck {

std::string constraint_name(const Violation& v) {
  switch (v.constraint) {
    case Constraint::incident_out:
    case Constraint::incident_in:
    case Constraint::predecessor:
      return fmt::format("I({})", v.i);
    case Constraint::non_orientation:
      return fmt::format("O({})", v.i);
    case Constraint::cycle:
      return fmt::format("C({},{})", v.i, v.j);
    case Constraint::loop:
      return fmt::format("no-loop({})", v.i);
    case Constraint::foreign_label:
      return fmt::format("D({})", v.i);
  }
  return "?";
}

std::string describe(const Violation& v, const std::string& e) {
  switch (v.constraint) {
    case Constraint::incident_out:
      return fmt::format("{}: {} is the source of {} {}-arcs (expected exactly one)", constraint_name(v), e, v.count, v.i);
    case Constraint::incident_in:
      return fmt::format("{}: {} is the target of {} {}-arcs (expected exactly one)", constraint_name(v), e, v.count, v.i);
    case Constraint::non_orientation:
      return fmt::format("{}: a {}-arc incident to {} has no reverse arc", constraint_name(v), v.i, e);
    case Constraint::cycle:
      return fmt::format("{}: {} is not the source of a {}{}{}{}-cycle", constraint_name(v), e, v.i, v.j, v.i, v.j);
    case Constraint::loop:
      return fmt::format("{}: the {}-arc of {} is a loop", constraint_name(v), v.i, e);
    case Constraint::predecessor:
      return v.j < 0 ? fmt::format("{}: the {}-predecessor recorded at {} is {}, but no {}-arc comes from there", constraint_name(v), v.i, e, v.count,
                                   v.i)
                     : fmt::format("{}: the {}-predecessor recorded at {} is {}, but the {}-arc into it comes from dart {}", constraint_name(v), v.i,
                                   e, v.count == no_element ? std::string("none") : std::to_string(v.count), v.i, v.j);
    case Constraint::foreign_label:
      return fmt::format("{}: {} is the source of an arc labeled {}, which is not a dimension of the model", constraint_name(v), e, v.i);
  }
  return "?";
}

}  // namespace dartcheck
