// rigidlab-explore: a lab live in a window (explorer.h). The adapter between the
// desktop and the explorer: options, the GLFW window and its OpenGL 3.3 context,
// Dear ImGui's GLFW and OpenGL 3 backends, and a loop that calls Explorer::frame()
// and waits for events while nothing moves.
//
//   rigidlab-explore [LAB] [--script FILE] [--size WxH] [LAB'S OPTIONS...]
//   rigidlab explore LAB ...  and  LAB --explore ...  run it.
// The window's OpenGL 3.3 core names (GL_READ_FRAMEBUFFER, PFNGLREADPIXELSPROC, ...).
#define GLFW_INCLUDE_GLCOREARB
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "explorer.h"
#include "exports.h"
#include "rigid/render/atomic_file.h"
#include "rigid/render/context.h"
#include "rigid/support/cli.h"
#include "rigid/support/text.h"
#include "script.h"
#include "style.h"

namespace {

using rigid::support::terminal_safe;
// The name its messages go by: its own, or the lab's when a lab's --explore ran it.
std::string g_name = "rigidlab-explore";
std::string g_glfw_error = "GLFW gave no reason";

// The largest drawable, each side, in pixels: --size's bound, and the window's however
// it is resized. Mesa's software renderer holds a window's buffers whole and draws them
// all (16384 square: 3 GB and minutes a frame; 32767 square overflows them), so no
// window is let grow past it: a window manager is told the limit, and where none keeps
// it (Xvfb, a resize by xdotool) the window is put back to it before it is drawn.
constexpr int kMaxDrawable = 8192;

void cap_drawable(GLFWwindow* window) {
  int fw = 0, fh = 0, ww = 0, wh = 0;
  glfwGetFramebufferSize(window, &fw, &fh);
  if (fw <= kMaxDrawable && fh <= kMaxDrawable) return;
  glfwGetWindowSize(window, &ww, &wh);
  // a window's size is in screen units, its drawable in pixels (2 a unit on a display
  // scaled so)
  const auto capped = [](int units, int pixels) {
    if (pixels <= kMaxDrawable || units <= 0) return units;
    return std::max(1, static_cast<int>(static_cast<long long>(units) * kMaxDrawable / pixels));
  };
  glfwSetWindowSize(window, capped(ww, fw), capped(wh, fh));
}

// The few GL calls the loop makes itself, from the window's context.
struct WindowGl {
  PFNGLVIEWPORTPROC Viewport = nullptr;
  PFNGLCLEARCOLORPROC ClearColor = nullptr;
  PFNGLCLEARPROC Clear = nullptr;
  PFNGLBINDFRAMEBUFFERPROC BindFramebuffer = nullptr;
  PFNGLREADBUFFERPROC ReadBuffer = nullptr;
  PFNGLPIXELSTOREIPROC PixelStorei = nullptr;
  PFNGLREADPIXELSPROC ReadPixels = nullptr;
  PFNGLBINDTEXTUREPROC BindTexture = nullptr;
  PFNGLTEXPARAMETERIPROC TexParameteri = nullptr;
  PFNGLFINISHPROC Finish = nullptr;
  template <class F>
  static void load(F& f, const char* name) {
    f = reinterpret_cast<F>(glfwGetProcAddress(name));
  }
  bool load_all() {
    load(Viewport, "glViewport");
    load(ClearColor, "glClearColor");
    load(Clear, "glClear");
    load(BindFramebuffer, "glBindFramebuffer");
    load(ReadBuffer, "glReadBuffer");
    load(PixelStorei, "glPixelStorei");
    load(ReadPixels, "glReadPixels");
    load(BindTexture, "glBindTexture");
    load(TexParameteri, "glTexParameteri");
    load(Finish, "glFinish");
    return Viewport && ClearColor && Clear && BindFramebuffer && ReadBuffer && PixelStorei &&
           ReadPixels && BindTexture && TexParameteri && Finish;
  }
  // The back buffer just drawn, rows top to bottom.
  rigid::render::Image read_back(int w, int h) const {
    rigid::render::Image img;
    img.width = w;
    img.height = h;
    img.rgb.resize(static_cast<std::size_t>(w) * h * 3);
    BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    ReadBuffer(GL_BACK);
    PixelStorei(GL_PACK_ALIGNMENT, 1);
    ReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, img.rgb.data());
    const std::size_t row = static_cast<std::size_t>(w) * 3;
    for (int y = 0; y < h / 2; ++y)
      std::swap_ranges(img.rgb.begin() + y * row, img.rgb.begin() + (y + 1) * row,
                       img.rgb.begin() + (h - 1 - y) * row);
    return img;
  }
};

int fail(const std::string& option, const std::string& rule) {
  std::cerr << g_name << ": error: " << terminal_safe(option.empty() ? rule : option + ": " + rule)
            << '\n';
  return 2;
}

// The lab's options as on its command line ("--flag value", "--flag=value", "--switch"),
// each handed to `set` (flag, text), which reads the text as the lab's command line does;
// the first refusal, or "".
std::string apply_lab_options(
    const rigid::lab::Session& s, const std::vector<std::string>& args,
    const std::function<std::string(const std::string&, const std::string&)>& set) {
  std::vector<std::size_t> given;
  for (std::size_t k = 0; k < args.size(); ++k) {
    std::string flag = args[k], value;
    bool has_value = false;
    if (const auto eq = flag.find('='); flag.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = flag.substr(eq + 1);
      flag = flag.substr(0, eq);
      has_value = true;
    }
    const std::size_t i = s.find(flag);
    if (i >= s.input_count()) {
      return flag + ": not an input of " + s.name() + " (the explorer takes only the lab's inputs)";
    }
    if (s.rule(i).kind() != rigid::lab::InputKind::kFlag) {
      // as on the lab's command line: which of two values was meant is not guessed
      if (std::find(given.begin(), given.end(), i) != given.end())
        return flag + ": given twice: give it once";
      given.push_back(i);
      if (!has_value) {
        if (k + 1 >= args.size()) return flag + ": needs a value";
        value = args[++k];
      }
    }
    if (std::string why = set(flag, value); !why.empty()) return why;
  }
  return "";
}

// What the command line asks for.
struct Options {
  std::string lab = "top_nutation", script_path, size = "1280x720", frame_log;
  bool frame_phases = false;
  std::vector<std::string> lab_options;  // the lab's own, as on its command line
  int width = 0, height = 0;
  std::vector<rigid::lab::LabEntry> labs;
  std::unique_ptr<rigid::explore::Script> script;
};

void describe(CLI::App& app, Options& o) {
  app.add_option("lab", o.lab, "the lab to open (rigidlab list names them)")->capture_default_str();
  app.add_option("--script", o.script_path,
                 "run the commands of FILE, one a frame, then close (the commands: below)")
      ->type_name("FILE");
  app.add_option("--size", o.size, "the window's size in pixels")->capture_default_str();
  app.add_option("--frame-log", o.frame_log,
                 "write each frame's wall time (and whether the inputs changed in it) to FILE "
                 "as JSON on exit, for bench/")
      ->type_name("FILE");
  app.add_flag("--frame-phases", o.frame_phases,
               "with --frame-log: each frame's time by phase too (the GL waited for at the end "
               "of each, which slows the frame a little)");
  app.set_version_flag("--version", std::string("rigidlab-explore ") + RIGID_VERSION);
  app.footer(
      "In the window: drag the scene to turn it, the wheel to zoom, a double click to reset the "
      "view; space plays and pauses, the arrow keys step a frame, the keys 1 to 9 hide and "
      "show the scene's parts (Show lists them). A value typed into a field "
      "is taken on Enter; one that breaks a rule shows the rule and the view keeps the last "
      "valid inputs.\n\n"
      "A script (--script FILE) runs one command a frame, then closes the window:\n"
      "  set --OPTION VALUE       an input, as typed in its field (a refusal is printed)\n"
      "  drag --OPTION VALUE      an input, as its slider held and moved there\n"
      "  unset --OPTION           an optional input back to the lab's own choice\n"
      "  textbook                 the text's example\n"
      "  lab NAME                 another lab\n"
      "  play SECONDS             plays that much of the motion, a frame each 1/30 s of it\n"
      "  pause | seek T | speed X\n"
      "  turn RIGHT UP | zoom F | reset-view    the view (degrees, a factor)\n"
      "  show-scene NAME | show-plot NAME       motion, strip or a figure of the lab\n"
      "  hide PART | show PART    a part of the scene, by its legend entry (\"in quotes\")\n"
      "  frames N | wait SECONDS  draws N frames; waits, the window live\n"
      "  wait-for FILE            waits until FILE exists, the window live\n"
      "  screenshot FILE          the window as a PNG\n"
      "  save-figure NAME FILE [WxH]            a figure, as the lab's --figures draws it "
      "(FILE.svg,\n"
      "                                         FILE.pdf: vectors)\n"
      "  save-view FILE [WxH]     the scene as shown\n"
      "  export-json FILE | export-csv FILE | record FILE.mp4|FILE.webp\n"
      "  print-command | print-json             on stdout\n"
      "  quit\n"
      "Blank lines and text after # are skipped. " +
      rigid::explore::script_rules() + " Examples: explore/demos/.");
  app.allow_extras();
  app.positionals_at_end(false);
}

// The options read and checked, the lab's inputs among them, before any window opens
// (bad input is exit 2 anywhere); the exit status if the run ends here.
std::optional<int> read_options(int argc, char** argv, Options& o) {
  CLI::App app(
      "rigidlab-explore: a lab live in a window: its inputs as sliders and fields, its scene "
      "turned with the mouse, its motion played, its numbers and plots recomputed on every "
      "change. Any other options are the lab's own (see LAB --help).",
      "rigidlab-explore");
  describe(app, o);
  if (const std::string twice =
          rigid::support::repeated_option(app, std::vector<std::string>(argv + 1, argv + argc));
      !twice.empty())
    return fail(twice, "given twice: give it once");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    return fail("", e.what());
  }
  o.lab_options = app.remaining();
  o.labs = rigid::lab::all_labs();
  const auto entry =
      std::find_if(o.labs.begin(), o.labs.end(), [&](const auto& l) { return l.name == o.lab; });
  if (entry == o.labs.end()) {
    std::string names;
    for (const auto& l : o.labs) names += (names.empty() ? "" : ", ") + l.name;
    return fail("LAB", "'" + o.lab + "' is not a lab (one of " + names + ")");
  }
  const auto read = rigid::lab::read_size(o.size, {640, 400, kMaxDrawable, kMaxDrawable, false});
  if (const auto* why = std::get_if<std::string>(&read)) return fail("--size", *why);
  o.width = std::get<rigid::lab::Size>(read).width;
  o.height = std::get<rigid::lab::Size>(read).height;
  const std::unique_ptr<rigid::lab::Session> check = entry->make();
  const std::string why = apply_lab_options(
      *check, o.lab_options, [&check](const std::string& flag, const std::string& text) {
        const auto refusal = check->set_text(check->find(flag), text);
        return refusal ? refusal->message : std::string();
      });
  if (!why.empty()) return fail("", why);
  // a file's option given an empty name asks for no file: a slip, not a wish
  for (const auto& [flag, name] :
       {std::pair{"--script", &o.script_path}, std::pair{"--frame-log", &o.frame_log}}) {
    if (app.count(flag) > 0 && name->empty()) return fail(flag, "needs a file name");
  }
  if (!o.frame_log.empty()) {
    if (const std::string why = rigid::explore::output_refusal(o.frame_log); !why.empty())
      return fail("--frame-log", why);
  } else if (o.frame_phases) {
    return fail("--frame-phases", "needs --frame-log: the phases go in its file");
  }
  if (!o.script_path.empty()) {
    std::vector<std::string> names;
    for (const auto& l : o.labs) names.push_back(l.name);
    try {
      o.script = std::make_unique<rigid::explore::Script>(
          rigid::explore::Script::read(o.script_path, names));
      o.script->errors_to(std::cerr, g_name + ": error: --script: ");
    } catch (const std::invalid_argument& e) {
      return fail("--script", e.what());
    }
  }
  return std::nullopt;
}

// A window with an OpenGL 3.3 core context, current; nullptr (said why) if none.
GLFWwindow* open_window(const Options& o) {
  // GLFW's own words on a failure, said in the one line that reports it
  glfwSetErrorCallback([](int, const char* what) { g_glfw_error = what; });
  if (!glfwInit()) {
    std::cerr << g_name << ": error: no window can be opened (" << terminal_safe(g_glfw_error)
              << "; headless: xvfb-run -a rigidlab-explore ...)\n";
    return nullptr;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  const std::string title = "rigidlab explore: " + o.lab;
  GLFWwindow* window = glfwCreateWindow(o.width, o.height, title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    std::cerr << g_name << ": error: no OpenGL 3.3 window could be made ("
              << terminal_safe(g_glfw_error) << ")\n";
    glfwTerminate();
    return nullptr;
  }
  glfwSetWindowSizeLimits(window, GLFW_DONT_CARE, GLFW_DONT_CARE, kMaxDrawable, kMaxDrawable);
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { cap_drawable(w); });
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  return window;
}

// Dear ImGui on the window: its backends, the light style, the figures' own font.
void start_imgui(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is the explorer's, not remembered
  ImGui::StyleColorsLight();
  ImGuiStyle& style = ImGui::GetStyle();
  style.FrameRounding = 3.0f;
  style.WindowBorderSize = 0.0f;
  // the monitor's content scale (a HiDPI screen's 2) enlarges the text and every size
  // with it (style.h's ui_scale()); held to 4, past which no screen goes
  float xscale = 1.0f, yscale = 1.0f;
  glfwGetWindowContentScale(window, &xscale, &yscale);
  const float scale = std::clamp(std::isfinite(yscale) ? yscale : 1.0f, 1.0f, 4.0f);
  style.ScaleAllSizes(scale);
  // the figures' own font, so the window and its figures read alike
  if (io.Fonts->AddFontFromFileTTF(RIGID_FONT_PATH, rigid::explore::kFontPx * scale) == nullptr)
    io.Fonts->AddFontDefault();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

// What the window does for the explorer.
rigid::explore::Window hooks_of(GLFWwindow* window, const WindowGl& gl) {
  rigid::explore::Window hooks;
  hooks.set_clipboard = [window](const std::string& text) {
    glfwSetClipboardString(window, text.c_str());
  };
  hooks.close = [window] { glfwSetWindowShouldClose(window, GLFW_TRUE); };
  hooks.set_title = [window](const std::string& text) { glfwSetWindowTitle(window, text.c_str()); };
  hooks.read_frame = [window, &gl] {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    return gl.read_back(w, h);
  };
  return hooks;
}

// The text's glyphs sampled nearest, once the backend has made their texture: they are
// drawn at whole pixels, where nearest is what linear gives, at a third of linear's cost
// on a software rasteriser (llvmpipe), where text is most of what the window draws.
void nearest_font_atlas(const WindowGl& gl) {
  static ImTextureID done = nullptr;
  const ImTextureID atlas = ImGui::GetIO().Fonts->TexID;
  if (atlas == nullptr || atlas == done) return;
  gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(atlas)));
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  done = atlas;
}

// Where a frame's time went, with --frame-phases: the explorer's own phases, then the
// window's widgets drawn (the GL waited for) and the frame shown.
struct WindowPhases {
  double widgets_drawn = 0, shown = 0;
};

// One frame: the explorer's UI built and drawn, a screenshot taken, the frame shown.
void draw_frame(GLFWwindow* window, const WindowGl& gl, rigid::explore::Explorer& explorer,
                double seconds, WindowPhases* phases) {
  ImGui_ImplOpenGL3_NewFrame();
  nearest_font_atlas(gl);
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  explorer.frame(seconds);
  const auto built = std::chrono::steady_clock::now();
  ImGui::Render();
  cap_drawable(window);
  int fw = 0, fh = 0;
  glfwGetFramebufferSize(window, &fw, &fh);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.Viewport(0, 0, fw, fh);
  // the panels' colour: they draw no background of their own (style.h's kPanel)
  const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  gl.ClearColor(bg.x, bg.y, bg.z, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (phases) gl.Finish();
  explorer.after_render();
  const auto shown = std::chrono::steady_clock::now();
  glfwSwapBuffers(window);
  if (phases) {
    const auto now = std::chrono::steady_clock::now();
    phases->widgets_drawn = std::chrono::duration<double>(shown - built).count();
    phases->shown = std::chrono::duration<double>(now - shown).count();
  }
}

// A frame's phases as the frame log writes them.
nlohmann::json phases_json(const rigid::explore::Explorer::FramePhases& e, const WindowPhases& w) {
  return {{"actions", e.actions},
          {"widgets", e.widgets},
          {"scene", e.scene.scene},
          {"scene_setup", e.scene.drawing.setup},
          {"scene_layout", e.scene.drawing.layout},
          {"scene_draw", e.scene.drawing.draw},
          {"scene_resolve", e.scene.drawing.resolve},
          {"plot", e.scene.plot},
          {"widgets_drawn", w.widgets_drawn},
          {"shown", w.shown}};
}

// The frames until the window closes, waiting for events while nothing moves; each
// frame's time into `frames` if a log is asked for.
void loop(GLFWwindow* window, const WindowGl& gl, rigid::explore::Explorer& explorer, bool log,
          bool timed, nlohmann::json& frames) {
  explorer.timed(timed);
  WindowPhases phases;
  // After an event ImGui needs a frame or two to settle (hover, release): a few more
  // frames are drawn before the loop waits again.
  int settle = 3;
  auto last = std::chrono::steady_clock::now();
  while (!glfwWindowShouldClose(window)) {
    if (explorer.animating() || settle > 0) {
      glfwPollEvents();
    } else {
      glfwWaitEvents();
      settle = 3;
    }
    --settle;
    const auto now = std::chrono::steady_clock::now();
    const double dt = std::chrono::duration<double>(now - last).count();
    last = now;
    const long generation = explorer.session().generation();
    draw_frame(window, gl, explorer, dt, timed ? &phases : nullptr);
    if (log) {
      frames.push_back(
          {{"seconds",
            std::chrono::duration<double>(std::chrono::steady_clock::now() - now).count()},
           {"changed", explorer.session().generation() != generation}});
      if (timed) frames.back()["phases"] = phases_json(explorer.phases(), phases);
    }
    // A display without vertical sync (Xvfb, some drivers) would let a playing motion
    // take every cycle: frames are paced to 60 a second (a script runs unpaced).
    if (!explorer.scripted()) {
      std::this_thread::sleep_until(now + std::chrono::microseconds(16667));
    }
  }
}

// The log written, its path checked again as it is (the file system may have changed
// since the run began); "" or why it could not be.
std::string write_frame_log(const Options& o, const nlohmann::json& frames) {
  if (const std::string why = rigid::explore::output_refusal(o.frame_log); !why.empty()) return why;
  const auto& info = rigid::render::context();
  const nlohmann::json log = {{"lab", o.lab},
                              {"width", o.width},
                              {"height", o.height},
                              {"gl_renderer", info.gl_renderer},
                              {"samples", info.samples},
                              {"frames", frames}};
  try {
    rigid::render::write_text_atomically(o.frame_log, log.dump());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// The explorer in the window, to its end; the exit status.
int explore(GLFWwindow* window, Options& o) {
  WindowGl gl;
  if (!gl.load_all()) throw std::runtime_error("the window's OpenGL lacks a function");
  rigid::render::use_current_context(glfwGetProcAddress);
  start_imgui(window);
  int status = 0;
  {
    rigid::explore::Explorer explorer(std::move(o.labs), o.lab, hooks_of(window, gl));
    const std::string why =
        apply_lab_options(explorer.session(), o.lab_options,
                          [&explorer](const std::string& flag, const std::string& text) {
                            return explorer.apply(rigid::explore::action::SetText{flag, text});
                          });
    if (!why.empty()) {
      status = fail("", why);
    } else {
      if (o.script) explorer.run(std::move(o.script));
      nlohmann::json frames = nlohmann::json::array();
      loop(window, gl, explorer, !o.frame_log.empty(), o.frame_phases, frames);
      status = explorer.status();
      if (!o.frame_log.empty()) {
        if (const std::string why = write_frame_log(o, frames); !why.empty()) {
          std::cerr << g_name << ": error: --frame-log: " << terminal_safe(why) << '\n';
          status = 1;
        }
      }
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 0 && argv[0][0] != '\0') g_name = std::filesystem::path(argv[0]).filename().string();
  Options options;
  if (const std::optional<int> status = read_options(argc, argv, options)) return *status;
  GLFWwindow* window = open_window(options);
  if (window == nullptr) return 1;
  int status = 0;
  try {
    status = explore(window, options);
  } catch (const std::exception& e) {
    std::cerr << g_name << ": error: " << terminal_safe(e.what()) << '\n';
    status = 1;
  }
  glfwDestroyWindow(window);
  // No glfwTerminate(): closing the display unloads Mesa's driver before the process
  // ends, and what the driver still holds would then read as leaks of no library
  // (LeakSanitizer could name neither the library nor a suppression for it). The
  // process's end gives everything back.
  return status;
}
