// The explorer's exports (exports.h).
#include "exports.h"

#include <cstdio>
#include <sstream>

#include "common/output_paths.h"
#include "common/writers.h"
#include "rigid/render/atomic_file.h"
#include "rigid/render/draw.h"
#include "rigid/render/memory.h"
#include "rigid/render/png.h"
#include "rigid/support/programs.h"
#include "scene_cache.h"

namespace rigid::explore {

namespace {

std::string write_text(const std::string& path, const std::string& text) {
  if (std::string why = output_refusal(path); !why.empty()) return why;
  try {
    render::write_text_atomically(path, text);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

std::string output_refusal(const std::string& path) {
  try {
    lab::check_output_file("", path);
  } catch (const lab::InputError& e) {
    return e.rule;
  }
  return "";
}

std::string drawing_refusal(int width, int height) {
  try {
    lab::check_drawing_memory("", width, height, render::figure_peak_bytes(width, height));
  } catch (const lab::InputError& e) {
    return e.what();
  }
  return "";
}

std::string save_figure(lab::Session& s, const std::string& name, const std::string& path,
                        render::FigureFormat format, int width, int height) {
  s.wait();  // the figure the command line draws, from the whole report
  const lab::NamedFigure* f = figure_named(s, name);
  if (f == nullptr) return s.name() + " has no figure named '" + name + "'";
  if (std::string why = output_refusal(path); !why.empty()) return why;
  try {
    std::visit(
        [&](const auto& figure) { render::save_figure(figure, path, format, width, height); },
        f->figure);
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
  return "";
}

std::string save_view(const render::Scene3D& scene, const std::string& path, int width,
                      int height) {
  if (std::string why = output_refusal(path); !why.empty()) return why;
  try {
    render::save_png(scene, path, width, height);
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
  return "";
}

std::string export_json(lab::Session& s, const std::string& path) {
  return write_text(path, json_text(s));
}

std::string export_csv(lab::Session& s, const std::string& path) {
  s.wait();
  const lab::TimeSeries& series = s.report().time_series();
  if (series.columns.empty()) return "this run has no time series";
  // the CSV and its metadata land together, as the command line's --csv writes them
  try {
    lab::save_csv_files(series, path);
  } catch (const lab::InputError& e) {
    return e.rule;
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// The lab's own command writes the animation, so the file is the command line's, byte
// for byte, and the window goes on meanwhile.
support::Subprocess start_recording(const lab::Session& s, const std::string& path) {
  const std::string program = support::program_path(s.name(), "labs").string();
  std::vector<std::string> args{program};
  for (const std::string& a : s.arguments()) args.push_back(a);
  for (const std::string& a : {std::string("--animate"), path, std::string("--quiet")})
    args.push_back(a);
  support::Subprocess::Options options{support::Redirect::null(), support::Redirect::pipe()};
  options.end_with_parent = true;
  return support::Subprocess(program, args, options);
}

}  // namespace rigid::explore
