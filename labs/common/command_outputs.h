// A lab run's outputs, one pipeline over one file transaction: the report computed,
// the animation and the figures drawn (command_render.h), the CSV written, then the
// table or the JSON on stdout, and only once that is out do the files land, all of
// them or none (render::FileTransaction), with the folders the run made.
#pragma once

#include <functional>
#include <string>

#include "common/command.h"
#include "common/command_options.h"

namespace rigid::lab {

/// Computes the report and writes what `options` ask for. Returns the exit status: 0, or
/// 1 where a write failed (its one line on stderr). Throws InputError for an input found
/// bad only now (an output path, a motion with no span), and what `compute` throws.
int write_outputs(const CommandOptions& options, const std::function<Computed()>& compute);

/// `status`, or 1 with one line on stderr if what went to stdout did not arrive.
int stdout_written(const std::string& lab, int status);

}  // namespace rigid::lab
