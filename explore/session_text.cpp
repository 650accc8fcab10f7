// The texts a session's view gives (session_text.h).
#include "session_text.h"

#include <sstream>

#include "common/writers.h"

namespace rigid::explore {

std::string shell_word(const std::string& word) {
  if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                              "0123456789_./=,:+-@%") == std::string::npos) {
    return word;
  }
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string json_text(lab::Session& s) {
  s.wait();  // the numbers the command line prints, the whole report's
  return shown_json_text(s);
}

std::string shown_json_text(const lab::Session& s) {
  // the command line that reproduces it, as the command's own JSON names its argv
  lab::RunOutputs outputs;
  outputs.command.push_back(s.name());
  for (const std::string& a : s.arguments()) outputs.command.push_back(a);
  std::ostringstream text;
  lab::write_json(text, s.report(), outputs, RIGID_VERSION);
  return text.str();
}

std::string command_line(const lab::Session& s) {
  std::string line = s.name();
  for (const std::string& a : s.arguments()) line += " " + shell_word(a);
  return line;
}

}  // namespace rigid::explore
