// dartcheck recombine: tetrahedra -> hexahedra by query-modify (001 Sec.
// 7.1), the run querymodify/recombined_mesh does, rendered by reports/.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

#include <fmt/format.h>

#include "campaign/input_run.hpp"
#include "cli/commands.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "core/terminal.hpp"
#include "querymodify/recombined_mesh.hpp"
#include "reports/querymodify_report.hpp"
#include "reports/recombine_report.hpp"

namespace dartcheck::cli {

namespace {

// On a terminal, a status line naming the stage at work and, in the
// candidate search, how many vertices are done (at most 5 redraws a
// second); cleared before the report. Nothing off a terminal or under -q.
class StatusLine {
 public:
  StatusLine() : shown_(isatty(fileno(stderr)) != 0 && !terminal().quiet) {}
  ~StatusLine() { clear(); }
  StatusLine(const StatusLine&) = delete;
  StatusLine& operator=(const StatusLine&) = delete;

  querymodify::Progress progress() {
    if (!shown_) return {};
    return [this](std::string_view stage, std::size_t done, std::size_t total) {
      const auto now = std::chrono::steady_clock::now();
      if (done > 0 && now - last_ < std::chrono::milliseconds(200)) return;
      last_ = now;
      if (total > 0)
        fmt::print(stderr, "\r\033[Krecombine: {}: vertex {} of {} ({:.0f}%)", stage, done, total, 100.0 * double(done) / double(total));
      else
        fmt::print(stderr, "\r\033[Krecombine: {}", stage);
      drawn_ = true;
    };
  }
  void clear() {
    if (drawn_) fmt::print(stderr, "\r\033[K");
    drawn_ = false;
  }

 private:
  bool shown_, drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace

int recombine(const RecombineOptions& o) {
  // Before the work, as the output file.
  querymodify::check_contacts(querymodify::parse_strategy(o.strategy), querymodify::parse_search(o.search), o.conforming);
  querymodify::parse_cells(o.cells);
  if (!o.output.empty() && !is_volume_mesh_output(o.output))
    throw UsageError(fmt::format("-o: expected a {} file, got '{}'", volume_mesh_outputs, o.output));
  if (!o.output.empty()) check_writable(o.output);
  if (!o.report.empty()) ensure_directory(o.report);
  StatusLine status_line;
  const auto run = querymodify::recombine_mesh(o.mesh, o.strategy, o.min_quality, o.output, o.search, o.conforming, o.cells, status_line.progress(),
                                               o.msh_version == "2.2" ? GmshVersion::v22 : GmshVersion::v41);
  status_line.clear();
  if (!run.input_valid) {
    fmt::print(stderr, "BUG: the map of {} is not a valid open 3-O-map\n", o.mesh);
    return soundness_bug;
  }
  const int status = run.sound() ? ok : soundness_bug;
  // jsonl: one run of a campaign over many meshes (docs/scale.md), which merge gathers.
  campaign::print_input_run(
      reports::output_format(o.format), o.mesh,
      {{"strategy", o.strategy}, {"search", run.search}, {"min_quality", o.min_quality}, {"conforming", o.conforming}, {"cells", o.cells}}, run,
      status);
  if (!o.report.empty()) {
    const std::filesystem::path dir(o.report);
    write_file((dir / "quality.svg").string(), reports::quality_histogram_svg(run.quality));
    write_file((dir / "index.html").string(), reports::recombine_html(run));
    if (!terminal().quiet && o.format == "text") fmt::print("report      {}\n", (dir / "index.html").string());
  }
  if (status != ok)
    fmt::print(stderr, "BUG: the recombined map is {} ({} darts, {} expected)\n", run.valid ? "valid" : "invalid", run.darts, run.expected_darts);
  // Accepted is not good: the threshold keeps valid cells, not cells a
  // solver is happy with.
  if (run.quality.poor > 0 && !terminal().quiet) {
    std::fflush(stdout);  // after the report it is about, in a stream that merges both
    fmt::print(stderr, "{}: warning: {} of the {} recombined cells have a scaled Jacobian under {} (the worst {:.3g}), poor for a simulation; "
                       "`--min-quality {}` refuses them\n",
               printable(o.mesh), run.quality.poor, run.quality.cells, querymodify::poor_quality, run.quality.quantiles[0], querymodify::poor_quality);
  }
  return status;
}

}  // namespace dartcheck::cli
