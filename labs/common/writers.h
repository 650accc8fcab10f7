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
/// The time series as CSV: a header line of names, then rows of numbers to 17 digits;
/// nothing else, so that every reader takes it with no option.
std::string csv_text(const TimeSeries& series);
/// Where a CSV's metadata goes: FILE-metadata.json beside FILE, the first name a CSV on
/// the Web processor looks for.
std::string csv_metadata_path(const std::string& csv_path);
/// The CSV's W3C CSV on the Web metadata: the table's title, each column's name,
/// datatype, meaning and unit; its url the CSV's file name, relative to the metadata.
std::string csv_metadata_text(const TimeSeries& series, const std::string& csv_path,
                              const std::string& version);
/// The series' title and its columns (name, unit, meaning), as the JSON report holds them.
Json series_columns_json(const TimeSeries& series);

}  // namespace rigid::lab
