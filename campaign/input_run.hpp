// The output of a per-input command (recombine, query; per_input_command in
// campaign/shard_stream.hpp) as --format asks: its text, its JSON document,
// or (jsonl) the one run of a campaign over many inputs: a header naming
// the input and the options that change results, the input's line, and a
// summary with the exit status.
#pragma once

#include <string>

#include "campaign/run_parameters.hpp"
#include "reports/output_format.hpp"
#include "reports/querymodify_report.hpp"

namespace dartcheck::campaign {

void print_input_run(reports::OutputFormat format, const std::string& mesh, const Parameters& parameters, const reports::RecombineRun& run,
                     int status);
void print_input_run(reports::OutputFormat format, const std::string& map, const Parameters& parameters, const reports::QueryRun& run, int status);

}  // namespace dartcheck::campaign
