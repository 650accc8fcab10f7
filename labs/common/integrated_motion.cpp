// The parts of an integrated motion (integrated_motion.h) that know no problem.
#include "common/integrated_motion.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace rigid::lab {

std::vector<double> times_from_start(std::vector<double> times) {
  times.erase(std::remove_if(times.begin(), times.end(), [](double t) { return !(t > 0.0); }),
              times.end());
  times.push_back(0.0);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

void refuse_divergence(const std::string& input) {
  throw InputError(input,
                   "the integration diverged (its state is no longer finite); shorten the step "
                   "or tighten the tolerance");
}

void refuse_before_start(double t) {
  throw std::invalid_argument(fmt::format("the motion starts at t = 0 (asked for t = {:g} s)", t));
}

}  // namespace rigid::lab
