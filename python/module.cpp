// rigidlab's Python module, _rigidlab: the lab registry (common/registry.h) as it is,
// the one generic binding over the type-erased lab interface the explorer drives. A lab
// is computed once and whole from the texts given (session_at, through the one reader
// of user text), with the GIL released, so that a thread pool runs a sweep on every
// core. The Python package (rigidlab/__init__.py) makes the calls read like the text.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "common/output_paths.h"
#include "common/registry.h"
#include "common/writers.h"
#include "rigid/rotation.h"

#ifdef RIGID_HAVE_RENDER
#include "rigid/render/draw.h"
#include "rigid/render/figure_format.h"
#endif

namespace py = pybind11;
using rigid::lab::LabEntry;
using rigid::lab::Session;

namespace {

// A run's files land together under one transaction, which is the process's: the
// module writes files one call at a time, so that no other thread's file joins it.
std::mutex& files_mutex() {
  static std::mutex mutex;
  return mutex;
}

const std::vector<LabEntry>& registry() {
  static const std::vector<LabEntry> labs = rigid::lab::all_labs();
  return labs;
}

const LabEntry& entry(const std::string& name) {
  for (const LabEntry& e : registry()) {
    if (e.name == name) return e;
  }
  throw py::key_error("no lab named '" + name + "'");
}

// A JSON value as Python's: numbers, text, lists, None.
py::object to_python(const rigid::lab::Json& j) {
  if (j.is_null()) return py::none();
  if (j.is_boolean()) return py::bool_(j.get<bool>());
  if (j.is_number_integer()) return py::int_(j.get<long long>());
  if (j.is_number()) return py::float_(j.get<double>());
  if (j.is_string()) return py::str(j.get<std::string>());
  if (j.is_array()) {
    py::list out;
    for (const auto& item : j) out.append(to_python(item));
    return out;
  }
  py::dict out;
  for (const auto& [key, item] : j.items()) out[py::str(key)] = to_python(item);
  return out;
}

// One computed lab: its session, held whole.
class Run {
 public:
  Run(std::string lab, rigid::lab::GivenTexts given, std::unique_ptr<Session> session)
      : lab_(std::move(lab)), given_(std::move(given)), session_(std::move(session)) {}

  const rigid::lab::Report& report() const { return session_->report(); }

  // The JSON the command line prints with --json, its "command" the call's arguments.
  std::string json() const {
    rigid::lab::RunOutputs outputs;
    outputs.command = command();
    std::ostringstream out;
    rigid::lab::write_json(out, report(), outputs, RIGID_VERSION);
    return out.str();
  }

  std::string table() const {
    rigid::lab::RunOutputs outputs;
    outputs.command = command();
    std::ostringstream out;
    rigid::lab::write_table(out, report(), outputs);
    return out.str();
  }

  // The command line that gives the same report: the lab, then each option as given.
  std::vector<std::string> command() const {
    std::vector<std::string> argv{lab_};
    for (const auto& [flag, text] : given_) {
      argv.push_back(text.empty() ? flag : flag + "=" + text);
    }
    return argv;
  }

  // One result by its JSON key (KeyError if the lab has none): what a sweep reads, with
  // nothing else of the report converted.
  py::object value(const std::string& key) const {
    const rigid::lab::Json& results = report().results();
    const auto found = results.find(key);
    if (found == results.end()) throw py::key_error(key);
    return to_python(*found);
  }

  // (key, label, value as printed, unit, the text's value, remark, is a heading)
  py::list rows() const {
    py::list out;
    for (const rigid::lab::TableRow& r : report().rows()) {
      out.append(py::make_tuple(r.key, r.label, r.value, r.unit, r.textbook, r.remark, r.heading));
    }
    return out;
  }

  // The CSV's title, its columns (name, unit, meaning) and its numbers (rows x
  // columns), None where there is none.
  py::object series() const {
    const rigid::lab::TimeSeries& s = report().time_series();
    if (s.columns.empty()) return py::none();
    py::array_t<double> data({s.rows.size(), s.columns.size()});
    auto view = data.mutable_unchecked<2>();
    for (std::size_t i = 0; i < s.rows.size(); ++i) {
      for (std::size_t j = 0; j < s.columns.size(); ++j) view(i, j) = s.rows[i][j];
    }
    py::list columns;
    for (const rigid::lab::SeriesColumn& c : s.columns) {
      columns.append(py::make_tuple(c.name, c.unit, c.meaning));
    }
    return py::make_tuple(s.title, columns, data);
  }

  // Writes the CSV and its metadata beside it as --csv does, the two landing together
  // or neither; a path --csv would refuse raises ValueError with its rule, a failed
  // write OSError.
  void write_csv(const std::string& path) const {
    const rigid::lab::TimeSeries& series = report().time_series();
    if (series.columns.empty()) throw py::value_error(lab_ + " writes no CSV");
    std::string refused, failed;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(files_mutex());
      try {
        rigid::lab::save_csv_files(series, path);
      } catch (const rigid::lab::InputError& e) {
        refused = e.rule;
      } catch (const std::exception& e) {
        failed = e.what();
      }
    }
    if (!refused.empty()) throw py::value_error(refused);
    if (!failed.empty()) {
      PyErr_SetString(PyExc_OSError, failed.c_str());
      throw py::error_already_set();
    }
  }

  // (name, caption, "scene" or "plot") of each figure, in the lab's order.
  std::vector<std::tuple<std::string, std::string, std::string>> figures() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::tuple<std::string, std::string, std::string>> out;
    for (const rigid::lab::NamedFigure& f : session_->figures()) {
      out.emplace_back(f.name, f.caption, f.is_scene() ? "scene" : "plot");
    }
    return out;
  }

  // Writes figure `name` to `path` as the command line draws it (PNG, SVG or PDF).
  void save_figure(const std::string& name, const std::string& path, const std::string& format,
                   int width, int height) const {
#ifdef RIGID_HAVE_RENDER
    const auto kind = rigid::render::figure_format_named(format);
    if (!kind) throw py::value_error("format must be png, svg or pdf (got '" + format + "')");
    // the figures are described on first asking: one thread at a time, the GIL released
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::lock_guard<std::mutex> writing(files_mutex());
    for (const rigid::lab::NamedFigure& f : session_->figures()) {
      if (f.name != name) continue;
      std::visit(
          [&](const auto& figure) {
            rigid::render::save_figure(figure, path, *kind, width, height);
          },
          f.figure);
      return;
    }
    throw py::key_error("no figure named '" + name + "'");
#else
    (void)name, (void)path, (void)format, (void)width, (void)height;
    throw std::runtime_error("rigidlab was built without the renderer: no figures");
#endif
  }

  // The body's motion at any time (none for a lab without one).
  rigid::lab::BodyMotion body_motion() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return session_->body_motion();
  }

 private:
  std::string lab_;
  rigid::lab::GivenTexts given_;
  std::unique_ptr<Session> session_;
  mutable std::mutex mutex_;
};

// What the motion's at() gives, a column each: the name, its unit and what it is.
const std::vector<std::array<const char*, 3>>& motion_columns() {
  static const std::vector<std::array<const char*, 3>> columns = [] {
    const char* q = rigid::lab::kQuaternionConvention;
    const char* angles =
        "the z-x-z Euler angles of section 6 of the attitude (q = Rz(phi) "
        "Rx(theta) Rz(psi)), phi and psi in (-pi, pi]";
    return std::vector<std::array<const char*, 3>>{{"t_s", "s", "time"},
                                                   {"qw", "1", q},
                                                   {"qx", "1", q},
                                                   {"qy", "1", q},
                                                   {"qz", "1", q},
                                                   {"omega1", "rad/s", "omega in body axes"},
                                                   {"omega2", "rad/s", "omega in body axes"},
                                                   {"omega3", "rad/s", "omega in body axes"},
                                                   {"omega_x", "rad/s", "omega in space axes"},
                                                   {"omega_y", "rad/s", "omega in space axes"},
                                                   {"omega_z", "rad/s", "omega in space axes"},
                                                   {"phi_rad", "rad", angles},
                                                   {"theta_rad", "rad", angles},
                                                   {"psi_rad", "rad", angles}};
  }();
  return columns;
}

// The body at each of `times` (s, >= 0): a row of motion_columns() a time. A time
// before the start raises ValueError, as a run the integrator cannot make does, with
// the rule it breaks.
py::array_t<double> motion_at(
    const rigid::lab::BodyMotion& motion,
    const py::array_t<double, py::array::c_style | py::array::forcecast>& t) {
  const auto times = t.unchecked<1>();
  const std::size_t n = static_cast<std::size_t>(times.shape(0)), width = motion_columns().size();
  py::array_t<double> out({n, width});
  auto row = out.mutable_unchecked<2>();
  std::string refused;
  {
    py::gil_scoped_release release;
    try {
      for (std::size_t i = 0; i < n; ++i) {
        const double ti = times(static_cast<py::ssize_t>(i));
        if (!std::isfinite(ti))
          throw std::invalid_argument("t must be finite (got " + std::to_string(ti) + ")");
        const rigid::lab::BodyState s = motion(ti);
        const Eigen::Vector3d space = s.attitude.normalized() * s.omega_body;
        const rigid::EulerAngles e = rigid::euler_zxz(s.attitude.normalized());
        const double values[] = {ti,
                                 s.attitude.w(),
                                 s.attitude.x(),
                                 s.attitude.y(),
                                 s.attitude.z(),
                                 s.omega_body(0),
                                 s.omega_body(1),
                                 s.omega_body(2),
                                 space(0),
                                 space(1),
                                 space(2),
                                 e.phi,
                                 e.theta,
                                 e.psi};
        for (std::size_t j = 0; j < width; ++j) row(i, j) = values[j];
      }
    } catch (const rigid::lab::InputError& e) {
      refused = e.what();
    } catch (const std::invalid_argument& e) {
      refused = e.what();
    }
  }
  if (!refused.empty()) throw py::value_error(refused);
  return out;
}

// The lab computed at the texts given; a broken rule raises ValueError with the lab's
// own message, as the command line prints it after "LAB: error: ".
std::unique_ptr<Run> run(const std::string& name, const rigid::lab::GivenTexts& given) {
  const LabEntry& e = entry(name);
  std::variant<std::unique_ptr<Session>, rigid::lab::Refusal> made;
  {
    py::gil_scoped_release release;
    made = e.make_at(given);
  }
  if (auto* refusal = std::get_if<rigid::lab::Refusal>(&made)) {
    throw py::value_error(refusal->message);
  }
  return std::make_unique<Run>(name, given, std::move(std::get<std::unique_ptr<Session>>(made)));
}

// For the bench: the seconds of each of `repeats` computations of the lab at the texts
// given, in C++ alone (the GIL released, nothing of Python's in the loop): what a
// Python call's own cost is measured against.
std::vector<double> compute_seconds(const std::string& name, const rigid::lab::GivenTexts& given,
                                    int repeats) {
  const LabEntry& e = entry(name);
  std::vector<double> seconds;
  py::gil_scoped_release release;
  for (int k = 0; k < repeats; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const auto made = e.make_at(given);
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (std::holds_alternative<rigid::lab::Refusal>(made)) {
      throw py::value_error(std::get<rigid::lab::Refusal>(made).message);
    }
  }
  return seconds;
}

}  // namespace

PYBIND11_MODULE(_rigidlab, m) {
  m.doc() = "rigidlab's lab libraries; use the package rigidlab, which reads like the text.";
  m.attr("__version__") = RIGID_VERSION;
#ifdef RIGID_HAVE_RENDER
  m.attr("has_renderer") = true;
#else
  m.attr("has_renderer") = false;
#endif
  m.def("labs", [] {
    py::list out;
    for (const LabEntry& e : registry()) out.append(to_python(rigid::lab::describe(e)));
    return out;
  });
  m.def("run", &run, py::arg("lab"), py::arg("given"));
  m.def("_compute_seconds", &compute_seconds, py::arg("lab"), py::arg("given"), py::arg("repeats"));
  py::class_<Run>(m, "Run")
      .def("json", &Run::json)
      .def("table", &Run::table)
      .def("value", &Run::value)
      .def("command", &Run::command)
      .def("rows", &Run::rows)
      .def("series", &Run::series)
      .def("write_csv", &Run::write_csv, py::arg("path"))
      .def("figures", &Run::figures)
      .def("save_figure", &Run::save_figure, py::arg("name"), py::arg("path"),
           py::arg("format") = "png", py::arg("width") = 1600, py::arg("height") = 1200,
           py::call_guard<py::gil_scoped_release>())
      .def("body_motion", &Run::body_motion);
  py::class_<rigid::lab::BodyMotion>(m, "BodyMotion")
      .def("__bool__", [](const rigid::lab::BodyMotion& f) { return static_cast<bool>(f); })
      .def("at", &motion_at, py::arg("t"));
  m.def("motion_columns", [] {
    py::list out;
    for (const auto& [name, unit, meaning] : motion_columns())
      out.append(py::make_tuple(name, unit, meaning));
    return out;
  });
}
