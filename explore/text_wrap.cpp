// Text wrapped at its blanks (text_wrap.h).
#include "text_wrap.h"

#include <algorithm>

namespace rigid::explore {

std::vector<std::string> wrap_lines(std::string_view text, float width,
                                    const std::function<float(std::string_view)>& measure) {
  std::vector<std::string> lines;
  while (true) {
    const std::size_t end = text.find('\n');
    const std::string_view paragraph = text.substr(0, end);
    std::string line;
    std::size_t at = 0;
    while (at < paragraph.size()) {
      const std::size_t word_end = std::min(paragraph.find(' ', at), paragraph.size());
      const std::string_view word = paragraph.substr(at, word_end - at);
      at = word_end + 1;
      if (word.empty()) continue;
      std::string longer = line.empty() ? std::string(word) : line + ' ' + std::string(word);
      if (line.empty() || measure(longer) <= width) {
        line = std::move(longer);
      } else {
        lines.push_back(std::move(line));
        line = std::string(word);
      }
    }
    lines.push_back(std::move(line));
    if (end == std::string_view::npos) return lines;
    text.remove_prefix(end + 1);
  }
}

}  // namespace rigid::explore
