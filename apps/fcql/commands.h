// The fcql subcommands. Each returns the process exit status; errors are thrown and reported
// by main as one line (UsageError and fcql::ParameterError exit 2, others 1).
#pragma once

#include "pipeline/parameters.h"

#include <string>

namespace fcql {

/// Progress and information lines on stderr, silenced by --quiet.
void progress(bool quiet, const std::string& line);

/// `fcql field|trace|layout|run`: the pipeline down to `last`, its files and stats.json in
/// --out (pipeline_command.cpp).
int pipelineCommand(PipelineStage last, int argc, char** argv);
/// `fcql render DIR --out FILE.png`: pictures of a run's output directory (render_command.cpp).
int renderCommand(int argc, char** argv);
/// `fcql parameters [--markdown]`: the parameter table (usage text, or the README's Markdown).
int parametersCommand(int argc, char** argv);

}  // namespace fcql
