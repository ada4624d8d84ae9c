#include "reports/recombine_report.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "reports/html_page.hpp"
#include "reports/querymodify_report.hpp"

namespace dartcheck::reports {

namespace {

// Bin k's colour: below 0 inverted, then the bins under the poor threshold.
const char* bin_fill(std::size_t k) {
  if (k == 0) return "#e53935";
  return static_cast<double>(k - 1) / 10 < querymodify::poor_quality ? "#ffb300" : "#1e88e5";
}

}  // namespace

std::string quality_histogram_svg(const querymodify::QualitySummary& s) {
  constexpr int bar = 48, gap = 10, left = 50, top = 30, height = 220;
  const int bins = static_cast<int>(s.histogram.size());
  const int width = left + bins * (bar + gap) + 20, total = top + height + 110;
  const std::size_t most = std::max<std::size_t>(1, *std::max_element(s.histogram.begin(), s.histogram.end()));
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" font-family=\"Helvetica, Arial, sans-serif\" "
      "font-size=\"12\">\n",
      width, total);
  out += fmt::format("<title>Scaled Jacobian of the {} recombined cells</title>\n", s.cells);
  out += fmt::format("<text x=\"{}\" y=\"18\" font-size=\"14\">Scaled Jacobian of the {} recombined cells</text>\n", left, s.cells);
  const int base = top + height;
  out += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"#424242\"/>\n", left - 4, base, width - 16);
  for (int k = 0; k < bins; ++k) {
    const std::size_t n = s.histogram[static_cast<std::size_t>(k)];
    // At least one pixel for a bin with cells: a lone inverted cell shows.
    const int h = n ? std::max(1, static_cast<int>(static_cast<double>(n) * height / static_cast<double>(most) + 0.5)) : 0;
    const int x = left + k * (bar + gap);
    const char* label = querymodify::histogram_labels[static_cast<std::size_t>(k)];
    out += fmt::format("<rect class=\"bin\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"><title>{}: {} cells</title></rect>\n", x, base - h,
                       bar, h, bin_fill(static_cast<std::size_t>(k)), html_text(label), n);
    out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", x + bar / 2, base - h - 4, n);
    out += fmt::format("<text x=\"{0}\" y=\"{1}\" text-anchor=\"end\" transform=\"rotate(-40 {0} {1})\">{2}</text>\n", x + bar / 2 + 4, base + 14,
                       html_text(label));
  }
  // The legend: one meaning per colour.
  const int ly = base + 75;
  const std::pair<const char*, std::string> legend[] = {
      {"#e53935", "inverted (under 0)"},
      {"#ffb300", fmt::format("poor (under {})", querymodify::poor_quality)},
      {"#1e88e5", fmt::format("{} and above", querymodify::poor_quality)}};
  int lx = left;
  for (const auto& [fill, text] : legend) {
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"12\" height=\"12\" fill=\"{}\"/><text x=\"{}\" y=\"{}\">{}</text>\n", lx, ly, fill, lx + 16,
                       ly + 11, html_text(text));
    lx += 40 + static_cast<int>(text.size()) * 7;
  }
  out += "</svg>\n";
  return out;
}

std::string recombine_html(const querymodify::RecombineRun& run) {
  const querymodify::QualitySummary& s = run.quality;
  std::string body = fmt::format("<h1>Recombination of {}</h1>\n", html_text(run.mesh));
  body += fmt::format("<p>{} tetrahedra; strategy {}, search {}, cells {}, minimum scaled Jacobian {}{}.</p>\n", run.tets, html_text(run.strategy),
                      html_text(run.search), html_text(run.cells), run.min_quality,
                      run.output.empty() ? std::string() : fmt::format("; written to <code>{}</code>", html_text(run.output)));
  body += "<h2>Quality</h2>\n";
  if (s.cells == 0)
    body += "<p class=\"note\">No cell was recombined: the mesh is its tetrahedra.</p>\n";
  else {
    body += "<div class=\"figure\">\n" + quality_histogram_svg(s) + "</div>\n";
    if (s.poor > 0)
      body += fmt::format("<p class=\"mismatch\">{} of the {} recombined cells have a scaled Jacobian under {}, poor for a simulation; "
                          "<code>--min-quality {}</code> refuses them.</p>\n",
                          s.poor, s.cells, querymodify::poor_quality, querymodify::poor_quality);
    body += "<table>\n<tr>";
    for (const char* name : querymodify::quantile_names) body += fmt::format("<th>{}</th>", name);
    body += "</tr>\n<tr>";
    for (double q : s.quantiles) body += fmt::format("<td>{:.3f}</td>", q);
    body += "</tr>\n</table>\n";
  }
  body += "<h3>Share of the volume</h3>\n<table>\n<tr><th>hexahedra</th><th>prisms</th><th>pyramids</th><th>tetrahedra</th></tr>\n<tr>";
  for (double v : s.volume_share) body += fmt::format("<td>{:.1f}%</td>", 100 * v);
  body += "</tr>\n</table>\n";
  body += "<h2>Run</h2>\n<pre>" + html_text(recombine_text(run)) + "</pre>\n";
  return html_document(fmt::format("dartcheck recombine {}", run.mesh), body);
}

}  // namespace dartcheck::reports
