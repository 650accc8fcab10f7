// poinsot's inputs as a test gives them: as the options would set them, through the
// lab's own table (poinsot_test.cpp, poinsot_motion_test.cpp).
#pragma once

#include <catch2/catch.hpp>
#include <sstream>
#include <string>

#include "poinsot/poinsot.h"

namespace rigid::test {

// The inputs as the options would set them ("--inertia 1,2,3 --method rk4"), through
// the lab's own table, so each case reads as the command line it stands for.
inline rigid::lab::poinsot::Inputs given(const std::string& args) {
  rigid::lab::poinsot::Inputs in;
  std::istringstream words(args);
  for (std::string flag; words >> flag;) {
    const auto* field = rigid::lab::poinsot::input_table().find(flag);
    REQUIRE(field != nullptr);
    if (field->rule.kind() == rigid::lab::InputKind::kFlag) {
      field->set(in, true);
      continue;
    }
    std::string text;
    words >> text;
    switch (field->rule.kind()) {
      case rigid::lab::InputKind::kNumber:
        field->set(in, std::stod(text));
        break;
      case rigid::lab::InputKind::kVector: {
        Eigen::Vector3d v;
        std::istringstream parts(text);
        for (int i = 0; i < 3; ++i) {
          std::string part;
          std::getline(parts, part, ',');
          v(i) = std::stod(part);
        }
        field->set(in, v);
        break;
      }
      default:
        field->set(in, text);
    }
  }
  return in;
}

}  // namespace rigid::test
