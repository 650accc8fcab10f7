// Labs opened and closed off the frame's thread (lab_loader.h).
#include "lab_loader.h"

#include <chrono>

namespace rigid::explore {

namespace {

bool ready(const std::future<void>& f) {
  return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

}  // namespace

LabLoader::~LabLoader() {
  if (opening_.valid()) opening_.wait();
  for (std::future<void>& f : ending_) f.wait();
}

void LabLoader::open(const lab::LabEntry& entry, std::size_t index) {
  if (opening_.valid()) {
    // the lab no longer wanted is closed when it comes, off this thread
    ending_.push_back(std::async(std::launch::async, [dropped = std::move(opening_)]() mutable {
      try {
        dropped.get();
      } catch (const std::exception&) {
        // no lab to close
      }
    }));
  }
  opening_ = std::async(std::launch::async, [make = entry.make, index] {
    return Opened{index, make()};
  });
  sweep();
}

std::optional<LabLoader::Opened> LabLoader::take() {
  sweep();
  if (!opening_.valid() ||
      opening_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return std::nullopt;
  }
  return opening_.get();
}

void LabLoader::close(std::unique_ptr<lab::Session> session) {
  ending_.push_back(std::async(std::launch::async,
                               [closing = std::move(session)]() mutable { closing.reset(); }));
  sweep();
}

void LabLoader::sweep() {
  for (auto it = ending_.begin(); it != ending_.end();) {
    it = ready(*it) ? ending_.erase(it) : it + 1;
  }
}

}  // namespace rigid::explore
