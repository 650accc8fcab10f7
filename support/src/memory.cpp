// The memory budget (memory.h): read from the kernel's own accounts.
#include "rigid/support/memory.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace rigid::support {
namespace {

constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
constexpr std::uint64_t kMostMiB = std::uint64_t{1} << 40;

// The whole of `text` as an unsigned number, or nullopt.
std::optional<std::uint64_t> whole_number(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

std::optional<std::uint64_t> file_number(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  if (!in || !std::getline(in, text)) return std::nullopt;
  return whole_number(text);
}

// MemAvailable, in bytes (the file gives kB).
std::optional<std::uint64_t> available() {
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream fields(line.substr(13));
    std::uint64_t kb = 0;
    if (fields >> kb) return kb * 1024;
  }
  return std::nullopt;
}

// What the control group has left below its limit: v2 (the "0::PATH" line of
// /proc/self/cgroup) or v1 (the memory controller's own mount); nullopt if unlimited
// or unknown. ("max", or v1's near-2^63 "no limit", is no limit.)
std::optional<std::uint64_t> group_left() {
  std::ifstream in("/proc/self/cgroup");
  std::string v2;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("0::", 0) == 0) v2 = "/sys/fs/cgroup" + line.substr(3);
  const auto left = [](std::optional<std::uint64_t> limit,
                       std::optional<std::uint64_t> used) -> std::optional<std::uint64_t> {
    if (!limit || *limit >= (std::uint64_t{1} << 62)) return std::nullopt;
    return *limit > used.value_or(0) ? *limit - used.value_or(0) : 0;
  };
  if (!v2.empty()) {
    if (auto l = left(file_number(v2 + "/memory.max"), file_number(v2 + "/memory.current"))) {
      return l;
    }
  }
  return left(file_number("/sys/fs/cgroup/memory/memory.limit_in_bytes"),
              file_number("/sys/fs/cgroup/memory/memory.usage_in_bytes"));
}

}  // namespace

std::optional<MemoryBudget> memory_budget() {
  if (const char* stated = std::getenv(kMemoryBudgetVariable); stated != nullptr) {
    const std::optional<std::uint64_t> mib = whole_number(stated);
    if (!mib || *mib < 1 || *mib > kMostMiB) {
      throw std::invalid_argument(
          fmt::format("must be a whole number of MiB from 1 to {}", kMostMiB));
    }
    return MemoryBudget{*mib * kMiB, fmt::format("{}={}", kMemoryBudgetVariable, *mib)};
  }
  const std::optional<std::uint64_t> system = available(), group = group_left();
  if (group && (!system || *group < *system)) {
    return MemoryBudget{*group, "what the control group's limit leaves"};
  }
  if (system) return MemoryBudget{*system, "the memory available"};
  return std::nullopt;
}

std::string bytes_text(std::uint64_t bytes) {
  const double b = static_cast<double>(bytes);
  if (b < 1e6) return fmt::format("{:.0f} kB", b / 1e3);
  if (b < 1e9) return fmt::format("{:.0f} MB", b / 1e6);
  if (b < 1e12) return fmt::format("{:.{}f} GB", b / 1e9, b < 1e10 ? 1 : 0);
  return fmt::format("{:.{}f} TB", b / 1e12, b < 1e13 ? 1 : 0);
}

void restart_with_huge_pages(char** argv) {
  static bool asked = false;
  if (asked) return;
  asked = true;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables != nullptr && std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr) return;
  const std::string before = tunables != nullptr ? tunables : "";
  const std::string with = before.empty() ? kHugePagesTunable : before + ":" + kHugePagesTunable;
  if (::setenv("GLIBC_TUNABLES", with.c_str(), 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  // exec refused: go on as this process, its environment as it was
  if (tunables != nullptr)
    ::setenv("GLIBC_TUNABLES", before.c_str(), 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
}

}  // namespace rigid::support
