// The STEM.counterexample.yaml that a failing rule leaves behind (fuzz and
// prove, docs/fuzz.md): the rule, the host and match, what H breaks and the
// command that replays it. A file format of its own so that YAML stays
// inside io (analysis/counterexample_files.cpp fills it).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

struct CounterexampleFile {
  std::string rule, catalog;
  /// Extra (key, value) lines: seed, class, constraint...
  std::vector<std::pair<std::string, std::string>> fields;
  std::vector<std::string> static_failures;
  std::string host;  // the host map's file
  std::size_t host_darts = 0;
  std::vector<Dart> hooks;
  std::vector<std::pair<std::string, Dart>> match;  // L node -> dart (DPO rules); empty for schemes
  std::string result;                               // H's file; empty when H has no dense form
  std::vector<std::string> broken;                  // "I(1)", "C(0,2)", ...
  std::string not_representable;                    // why H has no dense form, if so
  std::vector<std::string> event_contradictions;
  struct Violation {
    Dart dart;
    std::string constraint, what;
  };
  std::vector<Violation> violations;
  std::string origin;
  bool minimal = false;
  std::string replay;
};

/// The file's YAML text (keys in the order of the struct; empty optional
/// entries left out). Any bytes in names come out as valid YAML.
std::string counterexample_file_text(const CounterexampleFile& file);

}  // namespace dartcheck
