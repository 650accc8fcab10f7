// What a live view of a session says in text, the same in the explorer and on the web
// page: the command line that reproduces it and the JSON that command prints. No files,
// no windows.
#pragma once

#include <string>

#include "common/session.h"

namespace rigid::explore {

/// The JSON the command line prints (`LAB ARGS --json`), naming that command; waits for
/// the whole report.
std::string json_text(lab::Session& s);
/// The same of the report shown, the whole one's or while it is computed its preview's.
std::string shown_json_text(const lab::Session& s);
/// The command line that reproduces the session's inputs, each word a shell reads as itself.
std::string command_line(const lab::Session& s);
/// `word` as a POSIX shell reads it back: as it is where every character is safe, else
/// single-quoted (a quote inside as '\'').
std::string shell_word(const std::string& word);

}  // namespace rigid::explore
