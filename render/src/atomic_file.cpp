// Placeholder until the render-overlay branch lands its writer.
#include "rigid/render/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace rigid::render {

void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write) {
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (file == nullptr) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  write(file);
  const bool ok = std::ferror(file) == 0 && std::fflush(file) == 0;
  const int error = errno;
  if (std::fclose(file) != 0 || !ok || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(ok ? errno : error));
  }
}

}  // namespace rigid::render
