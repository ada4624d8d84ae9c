// The recombination as an HTML page (`dartcheck recombine --report DIR`):
// what the run did, and the quality of the mesh it wrote as a histogram a
// reader takes in at a glance, with the quantiles and the volume shares
// beside it. The histogram is also a file of its own, to put in a paper.
#pragma once

#include <string>

#include "querymodify/recombined_mesh.hpp"

namespace dartcheck::reports {

/// The histogram of the recombined cells' scaled Jacobian (QualitySummary's
/// 11 bins) as a standalone SVG: one bar per bin, its count above it and,
/// in its <title>, "BIN: N cells"; inverted cells red, poor ones (under
/// querymodify::poor_quality) amber, the others blue, named by a legend.
std::string quality_histogram_svg(const querymodify::QualitySummary& s);

/// The page: the run as `recombine` prints it, the histogram inline, the
/// quantiles and the share of the volume per kind of cell in tables.
/// Self-contained and well-formed XML, as html_page.hpp's pages are.
std::string recombine_html(const querymodify::RecombineRun& run);

}  // namespace dartcheck::reports
