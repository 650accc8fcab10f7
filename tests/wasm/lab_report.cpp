// One lab's report as JSON, the same program native and under node (emscripten):
// the lab libraries are portable when the two print the same numbers.
#include <iostream>

#include "common/writers.h"
#include "tire_balancing/tire_balancing.h"

int main() {
  namespace lab = rigid::lab;
  lab::Json out;
  const auto report_of = [](const lab::Report& report) {
    return lab::Json{
        {"inputs", report.inputs()}, {"results", report.results()}, {"notes", report.notes()}};
  };
  lab::tire_balancing::Inputs in;
  out["tire_balancing"] = report_of(lab::tire_balancing::compute(in));
  in.tilt_deg = 7.5, in.offset = 0.09, in.road_speed = 33.0;
  out["tire_balancing_road"] = report_of(lab::tire_balancing::compute(in));
  std::cout << out.dump(1) << "\n";
}
