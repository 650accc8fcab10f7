// What the explorer writes, each through the lab's own writers so that a file is the
// command line's, byte for byte: a figure, the view as shown, the JSON, the CSV, the
// command line that reproduces the view, and an animation written by the lab's own
// command in a child process. Each waits for the session's whole report (the explorer
// asks for an export only once it has come). "" or the one line saying what failed.
//
// Every file the explorer writes is held to the command line's rules for an output
// (output_paths.h, as `--csv` is): a regular file or none, never a link, a folder, a
// device or a pipe, in a folder it can write, under a name the system takes; checked
// when the path is given (a script is read, --frame-log) and again when it is written,
// since the file system can change between. The file lands whole by one rename
// (atomic_file.h), or not at all.
#pragma once

#include <string>

#include "common/session.h"
#include "rigid/render/figure_format.h"
#include "rigid/render/scene3d.h"
#include "rigid/support/subprocess.h"
#include "session_text.h"

namespace rigid::explore {

/// "" if `path` may be written as an output, else the rule it breaks ("'PATH' is a
/// symbolic link; give the file itself"), its user text escaped.
std::string output_refusal(const std::string& path);
/// "" if a figure or view of `width` x `height` can be drawn within the memory the run
/// may use (render/memory.h, support/memory.h), else the rule it breaks, as the
/// command line's --figure-size says it.
std::string drawing_refusal(int width, int height);

std::string save_figure(lab::Session& s, const std::string& name, const std::string& path,
                        render::FigureFormat format, int width, int height);
/// `scene`: the view as shown, at the size asked for.
std::string save_view(const render::Scene3D& scene, const std::string& path, int width, int height);
std::string export_json(lab::Session& s, const std::string& path);
std::string export_csv(lab::Session& s, const std::string& path);
/// `LAB ARGS --animate PATH --quiet` started, its stderr into a pipe this process reads,
/// ended (SIGTERM, which removes its temporaries) if this process dies first; throws
/// std::system_error if it cannot be started.
support::Subprocess start_recording(const lab::Session& s, const std::string& path);

}  // namespace rigid::explore
