// The writers of a Report: the human table, the JSON object and the CSV text.
// They only format; the command line (command.h) decides where each goes.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "common/report.h"

namespace rigid::lab {

/// What a run wrote besides its report, for the table's and the JSON's listing.
struct RunOutputs {
  std::vector<std::string> command;  ///< argv as given
  std::string figures_dir;
  std::vector<std::string> figures;  ///< file names, in the order drawn
  Json captions = Json::object();    ///< by file name
  std::string csv_path;              ///< "" if no CSV was asked for
  std::string animation_path;
  Json animation = nullptr;  ///< what --animate wrote, if anything
  Json timing = nullptr;     ///< --timing: where each figure's time went
};

/// The human table: the title, the inputs, a row a result, the notes, the files.
void write_table(std::ostream& out, const Report& report, const RunOutputs& outputs);
/// One JSON object (schemas/lab-output.schema.json).
void write_json(std::ostream& out, const Report& report, const RunOutputs& outputs,
                const std::string& version);
/// The time series as CSV: a header line, then rows of numbers to 17 digits.
std::string csv_text(const TimeSeries& series);

}  // namespace rigid::lab
