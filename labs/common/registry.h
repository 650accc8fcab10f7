// Every lab as a live session (session.h), by name, in section order: what the
// explorer offers and what the in-process tests go through. Generated from the one
// list of labs (RIGID_LABS, labs/CMakeLists.txt), in the library rigid::lab::all.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/session.h"

namespace rigid::lab {

/// A lab and how to open it.
struct LabEntry {
  std::string name;
  std::function<std::unique_ptr<Session>()> make;
};

/// Every lab, in section order.
std::vector<LabEntry> all_labs();

}  // namespace rigid::lab
