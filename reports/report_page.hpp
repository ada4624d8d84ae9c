// The pieces of `dartcheck report`'s HTML page, rendered from the result
// model: the verdict table (rules x conditions, fuzz and solver columns)
// and a section per rule (its picture with the witnesses, each failing
// condition, its events, and each counterexample drawn as G, H and the rule).
#pragma once

#include <string>
#include <vector>

#include "analysis/rule_result.hpp"
#include "reports/counterexample_dot.hpp"

namespace dartcheck::reports {

/// The page's pictures: each written as an SVG file below `dir` and
/// returned as inline SVG with a link to its file.
class Pictures {
 public:
  Pictures(std::string dir, std::string engine);
  /// Renders `dot`, writes it to dir/file (OutputError if it cannot) and
  /// returns the HTML that shows it.
  std::string add(const std::string& dot, const std::string& file);
  /// A counterexample: its head and panels rendered, written to dir/file
  /// as one SVG (svg_figure), and shown as the head above a row of panels
  /// that wraps when the page is narrow.
  std::string add(const CounterexampleFigure& figure, const std::string& file);
  std::size_t count() const { return count_; }

 private:
  void write(const std::string& svg, const std::string& file);  // below dir_; counts the picture
  static std::string link(const std::string& file);             // the note that links the file
  std::string dir_;
  std::string engine_;
  std::size_t count_ = 0;
};

/// Rules x conditions, the static verdict, the record, and the fuzz and
/// solver columns when those stages ran; each failing cell links to its witnesses.
std::string verdict_table_html(const std::vector<analysis::RuleResult>& rows, bool fuzzed, bool proved);

/// One rule's section: kind, model, source line, note, picture, failing
/// conditions with witnesses, embedding expressions, events, fuzz and
/// solver findings with their counterexamples drawn.
std::string rule_section_html(const analysis::RuleResult& r, Pictures& pictures);

}  // namespace dartcheck::reports
