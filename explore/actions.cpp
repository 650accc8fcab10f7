// What the actions say of themselves (actions.h).
#include "actions.h"

namespace rigid::explore {

const char* const kFigureSizeRule = "size: must be WxH, each 16 to 8192";

bool read_figure_size(const std::string& text, int& width, int& height) {
  const auto size = lab::read_size(text, {16, 16, 8192, 8192, false});
  const auto* read = std::get_if<lab::Size>(&size);
  if (read == nullptr) return false;
  width = read->width;
  height = read->height;
  return true;
}

bool needs_whole_report(const Action& a) {
  return std::holds_alternative<action::SaveFigure>(a) ||
         std::holds_alternative<action::ExportJson>(a) ||
         std::holds_alternative<action::ExportCsv>(a);
}

std::string written_path(const Action& a) {
  if (const auto* f = std::get_if<action::SaveFigure>(&a)) return f->path;
  if (const auto* v = std::get_if<action::SaveView>(&a)) return v->path;
  if (const auto* j = std::get_if<action::ExportJson>(&a)) return j->path;
  if (const auto* c = std::get_if<action::ExportCsv>(&a)) return c->path;
  return "";
}

bool writes_file(const Action& a) {
  return !written_path(a).empty() || std::holds_alternative<action::Record>(a) ||
         std::holds_alternative<action::Screenshot>(a);
}

}  // namespace rigid::explore
