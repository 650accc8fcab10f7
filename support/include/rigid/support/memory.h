// How much memory a run may use: what the system says it can have, within the limits
// set on it, or what the user states. A run that draws large images checks its need
// against this before any work, and `rigidlab figures` runs as many labs at once as
// fit in it: a machine with many processors and little memory is not an
// out-of-memory kill midway.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace rigid::support {

/// The environment variable that states the budget, in MiB (a whole number, 1 or more).
inline constexpr char kMemoryBudgetVariable[] = "RIGIDLAB_MEMORY_MB";

/// What a run may use: its bytes, and where the number comes from, as a person reads it
/// ("RIGIDLAB_MEMORY_MB=500", "the memory available", "the control group's limit").
struct MemoryBudget {
  std::uint64_t bytes = 0;
  std::string source;
};

/// The budget: RIGIDLAB_MEMORY_MB if set; else the memory available
/// (MemAvailable in /proc/meminfo: free memory and what the kernel can reclaim without
/// swapping), no more than what the run's control group has left below its limit
/// (cgroup v2 memory.max, or v1 memory.limit_in_bytes). nullopt where none of them can
/// be read. Throws std::invalid_argument naming the variable and its rule for a setting
/// that is not a whole number of MiB from 1 to 2^40.
std::optional<MemoryBudget> memory_budget();

/// A number of bytes as a person reads it: "940 MB", "3.4 GB" (decimal units, 2 or 3 digits).
std::string bytes_text(std::uint64_t bytes);

/// The tunable that has glibc's malloc back its large blocks with transparent huge pages.
inline constexpr char kHugePagesTunable[] = "glibc.malloc.hugetlb=1";

/// Starts this program again, the same arguments and environment, with glibc's malloc
/// asking for huge pages (GLIBC_TUNABLES gains kHugePagesTunable), unless GLIBC_TUNABLES
/// already says how malloc takes them. A drawing's buffers (some 70 MB at 1600x1200,
/// zeroed by Mesa as they are made) then fault in 2 MiB at a time instead of 4 KiB: on
/// this project's machine the first figure of a process went from 0.37 s to 0.15 s. A
/// tunable is read only as a program starts, hence the restart, done before any work.
/// Returns only where it cannot (no /proc/self/exe, or exec refused), the environment
/// as it was, or where this process has asked once already: a program that runs several
/// labs' commands in turn (rigidlab-draw) asks with its own arguments first, and a lab's
/// own ask then never starts it again with the lab's.
void restart_with_huge_pages(char** argv);

}  // namespace rigid::support
