#include "common/writers.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "rigid/format.h"
#include "rigid/support/text.h"

namespace rigid::lab {
namespace fs = std::filesystem;

namespace {

// A JSON input as the table shows it.
std::string text_of(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  // An input is echoed as given: the shortest text that reads back as the same double
  // (rounded, the Earth's Is/I = 1.0032737 read 1.0033, the digit that sets its period lost).
  const auto exact = [](const Json& number) {
    return fmt::format("{}", number.get<double>() + 0.0);
  };
  if (value.is_number()) return exact(value);
  const auto part = [&](int i) { return exact(value[i]); };
  if (value.is_array() && value.size() == 3 && value[0].is_number()) {
    return fmt::format("({}, {}, {})", part(0), part(1), part(2));
  }
  if (value.is_array() && value.size() == 2 && value[0].is_number()) {
    return fmt::format("({}, {})", part(0), part(1));
  }
  return value.dump();
}

// Every string of `json`, keys too, as valid UTF-8 (a file name may hold any bytes).
Json utf8_safe(const Json& json) {
  if (json.is_string()) return support::utf8_safe(json.get<std::string>());
  if (json.is_array()) {
    Json out = Json::array();
    for (const Json& item : json) out.push_back(utf8_safe(item));
    return out;
  }
  if (json.is_object()) {
    Json out = Json::object();
    for (const auto& [key, value] : json.items()) out[support::utf8_safe(key)] = utf8_safe(value);
    return out;
  }
  return json;
}

// The widest value that sets the value column's width; longer ones (sentences) overflow it.
constexpr std::size_t kValueColumnMax = 40;

}  // namespace

void write_table(std::ostream& out, const Report& report, const RunOutputs& outputs) {
  out << report.lab() << " - " << report.title() << "\n";
  std::string inputs;
  for (const auto& [key, value] : report.inputs().items()) {
    inputs += (inputs.empty() ? "" : ", ") + key + " = " + text_of(value);
  }
  out << "inputs: " << support::terminal_safe(inputs) << "\n";
  size_t label_width = 8, value_width = 5, unit_width = 4;
  bool any_textbook = false;
  for (const auto& row : report.rows()) {
    if (row.heading) continue;
    label_width = std::max(label_width, row.label.size());
    // A sentence (the motion in words) runs past the column instead of widening it.
    if (row.value.size() <= kValueColumnMax) value_width = std::max(value_width, row.value.size());
    unit_width = std::max(unit_width, row.unit.size());
    any_textbook = any_textbook || !row.textbook.empty();
  }
  out << "\n"
      << fmt::format("{:<{}}  {:<{}}  {:<{}}{}", "quantity", label_width, "value", value_width,
                     "unit", unit_width, any_textbook ? "  textbook" : "")
      << "\n";
  for (const auto& row : report.rows()) {
    if (row.heading) {
      out << "\n[" << row.label << "]\n";
      continue;
    }
    std::string line = fmt::format("{:<{}}  {:<{}}  {:<{}}", row.label, label_width, row.value,
                                   value_width, row.unit, unit_width);
    if (!row.textbook.empty()) line += "  " + row.textbook;
    if (!row.remark.empty()) line += "  " + row.remark;
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << "\n";
  }
  if (!report.notes().empty()) {
    out << "\nnotes:\n";
    for (const auto& note : report.notes()) out << "  - " << note << "\n";
  }
  if (!outputs.animation.is_null()) {
    out << "\nanimation: " << support::terminal_safe(outputs.animation_path) << "  "
        << outputs.animation["caption"].get<std::string>() << "\n";
  }
  if (!outputs.figures.empty()) {
    out << "\nfigures in " << support::terminal_safe(outputs.figures_dir) << ":\n";
    for (const auto& figure : outputs.figures) {
      out << "  " << support::terminal_safe(figure) << "  "
          << outputs.captions[figure].get<std::string>() << "\n";
    }
  }
}

void write_json(std::ostream& out, const Report& report, const RunOutputs& outputs,
                const std::string& version) {
  Json json;
  json["lab"] = report.lab();
  json["version"] = version;
  json["command"] = outputs.command;
  json["inputs"] = report.inputs();
  json["results"] = report.results();
  json["units"] = report.units();
  json["figures"] = outputs.figures;
  json["captions"] = outputs.captions;
  if (!outputs.animation.is_null()) json["animation"] = outputs.animation;
  if (!outputs.timing.is_null()) json["timing"] = outputs.timing;
  json["textbook"] = report.textbook_printed();
  json["textbook_values"] = report.textbook_values();
  if (!report.time_series().columns.empty())
    json["series"] = series_columns_json(report.time_series());
  // Every file the run wrote, by its absolute path.
  Json files = Json::array();
  std::error_code ec;
  for (const std::string& figure : outputs.figures) {
    files.push_back(
        fs::absolute(fs::path(outputs.figures_dir) / figure, ec).lexically_normal().string());
  }
  if (!outputs.csv_path.empty() && !report.time_series().columns.empty()) {
    for (const std::string& path : {outputs.csv_path, csv_metadata_path(outputs.csv_path)}) {
      files.push_back(fs::absolute(path, ec).lexically_normal().string());
    }
  }
  if (!outputs.animation.is_null()) files.push_back(outputs.animation["path"]);
  json["outputs"] = files;
  json["notes"] = report.notes();
  json["errata"] = Json::array();
  for (const Erratum& e : report.errata()) {
    json["errata"].push_back(
        {{"where", e.where}, {"printed", e.printed}, {"correction", e.correction}});
  }
  out << utf8_safe(json).dump(2) << "\n";
}

std::string csv_text(const TimeSeries& series) {
  std::string text;
  for (size_t i = 0; i < series.columns.size(); ++i) {
    text += (i ? "," : "") + series.columns[i].name;
  }
  text += "\n";
  for (const auto& row : series.rows) {
    for (size_t i = 0; i < row.size(); ++i) text += fmt::format("{}{:.17g}", i ? "," : "", row[i]);
    text += "\n";
  }
  return text;
}

namespace {

// A file name as a relative URL: every byte but the unreserved ones percent-encoded
// (RFC 3986), so that any name a file system allows resolves to that file.
std::string url_of_file_name(const std::string& name) {
  std::string url;
  for (const unsigned char c : name) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
      url += static_cast<char>(c);
    } else {
      url += fmt::format("%{:02X}", c);
    }
  }
  return url;
}

}  // namespace

std::string csv_metadata_path(const std::string& csv_path) {
  return csv_path + "-metadata.json";
}

Json series_columns_json(const TimeSeries& series) {
  Json columns = Json::array();
  for (const SeriesColumn& c : series.columns) {
    columns.push_back({{"name", c.name}, {"unit", c.unit}, {"meaning", c.meaning}});
  }
  return {{"title", series.title}, {"columns", columns}};
}

std::string csv_metadata_text(const TimeSeries& series, const std::string& csv_path,
                              const std::string& version) {
  // W3C CSV on the Web (https://www.w3.org/TR/tabular-metadata/): a column's meaning
  // as dc:description and its unit as schema:unitText, both from the initial context
  // every CSVW processor knows.
  Json columns = Json::array();
  for (const SeriesColumn& c : series.columns) {
    columns.push_back({{"name", c.name},
                       {"titles", c.name},
                       {"datatype", "double"},
                       {"required", true},
                       {"dc:description", c.meaning},
                       {"schema:unitText", c.unit}});
  }
  Json json;
  json["@context"] = {"http://www.w3.org/ns/csvw", {{"@language", "en"}}};
  json["url"] = url_of_file_name(fs::path(csv_path).filename().string());
  json["dc:title"] = series.title;
  json["dc:creator"] = "rigidlab " + version;
  json["dialect"] = {{"header", true}, {"delimiter", ","}};
  json["tableSchema"] = {{"columns", columns}};
  return json.dump(2) + "\n";
}

}  // namespace rigid::lab
