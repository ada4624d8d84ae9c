// The formats CI systems read, rendered from analysis::RuleResult: SARIF
// 2.1.0 (code scanning) and JUnit XML (test reports). Both are built with
// libraries (nlohmann::json, pugixml), so any rule or model name gives a
// valid document.
#pragma once

#include <string>
#include <vector>

#include "analysis/rule_result.hpp"

namespace dartcheck::reports {

/// One SARIF result per failing condition (witness sentences as the
/// message) at the rule's line: "error" when the record does not name the
/// failure, "note" when it does; plus an error per mismatch with the
/// record and per soundness bug. `catalog` is the file the rules come from.
std::string sarif_document(const std::string& catalog, const std::vector<analysis::RuleResult>& results, const std::string& version);

/// One test case per rule, failing when the rule does not match its
/// recorded verdict; `extra_failures` are run-level mismatches (a
/// baseline that disagrees with the catalog), one failing case each.
std::string junit_document(const std::string& command, const std::string& catalog, const std::vector<analysis::RuleResult>& results,
                           const std::vector<std::string>& extra_failures = {});

/// `s` as XML 1.0 character data allows it: invalid UTF-8 and the code
/// points XML forbids (controls other than tab, newline and carriage
/// return; U+FFFE, U+FFFF) replaced by U+FFFD.
std::string xml_safe(const std::string& s);

/// A relative path as a URI reference: every byte outside RFC 3986's
/// unreserved set and '/' percent-encoded.
std::string uri_path(const std::string& path);

}  // namespace dartcheck::reports
