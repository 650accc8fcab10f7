// Labs opened and closed off the frame's thread. Opening a lab computes its textbook
// example whole (every integrator compared, for some), and closing one waits for a
// whole report still under way: either would hold a frame for seconds. The loader
// does both on threads of their own; the frame asks, without waiting, whether the lab
// it asked for has come.
#pragma once

#include <cstddef>
#include <future>
#include <memory>
#include <optional>
#include <vector>

#include "common/registry.h"

namespace rigid::explore {

class LabLoader {
 public:
  /// A lab opened, and its place in the explorer's list.
  struct Opened {
    std::size_t index = 0;
    std::unique_ptr<lab::Session> session;
  };

  LabLoader() = default;
  /// Waits for what is under way (the process is ending).
  ~LabLoader();
  LabLoader(const LabLoader&) = delete;
  LabLoader& operator=(const LabLoader&) = delete;

  /// Opens `entry` (the `index`th lab); a lab asked for before and not yet come is dropped.
  void open(const lab::LabEntry& entry, std::size_t index);
  /// Whether a lab asked for has not yet come.
  bool opening() const { return opening_.valid(); }
  /// The lab asked for, once it has come (it failed to open: the exception it threw).
  std::optional<Opened> take();
  /// Closes `session`, off this thread.
  void close(std::unique_ptr<lab::Session> session);

 private:
  // Ends what has ended of the work set aside (dropped opens, closes).
  void sweep();
  std::future<Opened> opening_;
  std::vector<std::future<void>> ending_;
};

}  // namespace rigid::explore
