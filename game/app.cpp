#include "game/app.h"

#include <GLFW/glfw3.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "engine/physics/dynamics.h"
#include "engine/platform/window.h"
#include "engine/render/renderer.h"
#include "engine/ui/ui.h"
#include "game/audio/game_audio.h"
#include "game/control_panel.h"
#include "game/front_end.h"
#include "game/front_end_screens.h"
#include "game/hit_feedback.h"
#include "game/hud.h"
#include "game/interaction/fight_keys.h"
#include "game/interaction/gamepad.h"
#include "game/interaction/mouse_hands.h"
#include "game/match/match.h"
#include "game/scenarios/scenario_hooks.h"
#include "game/scene_view.h"
#include "game/world.h"

namespace boxing {

namespace fs = std::filesystem;
using clock_type = std::chrono::steady_clock;

namespace {

// When the program started (static initialisation, before main): the report's start_to_first_frame_s counts from
// here to the end of the first rendered frame (window: presented; headless: read back).
const clock_type::time_point kProgramStart = clock_type::now();

// CPU time of the whole process (every thread: lavapipe rasterises on its own LP_NUM_THREADS threads) in ms. The
// render timings take it around Renderer::render, which waits for the frame headless, so the difference is what
// the frame cost the CPUs: steadier than wall time on a machine other work shares.
double process_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

// Peak resident set size of the process so far, in MiB.
double max_rss_mb() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return double(ru.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

struct FrameTimes {
  std::vector<double> ms;
  nlohmann::json summary() const {
    if (ms.empty()) return {{"count", 0}};
    std::vector<double> s = ms;
    std::sort(s.begin(), s.end());
    double sum = 0;
    for (double x : s) sum += x;
    return {{"count", s.size()},
            {"mean_ms", sum / s.size()},
            {"p50_ms", s[s.size() / 2]},
            {"p95_ms", s[std::min(s.size() - 1, s.size() * 95 / 100)]},
            {"max_ms", s.back()}};
  }
};

// The display face's sizes the HUD and the screens draw with (engine/ui/ui.h).
HudFonts hud_fonts(const eng::ui::Ui& ui) {
  return {eng::ui::ui_font(ui, eng::ui::Font::Medium), eng::ui::ui_font(ui, eng::ui::Font::Large),
          eng::ui::ui_font(ui, eng::ui::Font::Huge)};
}

eng::render::RendererConfig renderer_config(const Options& o) {
  eng::render::RendererConfig c;
  c.width = o.width;
  c.height = o.height;
  c.validation = o.validation;
  c.vsync = o.vsync;
  c.render_scale = o.render_scale;
  using P = eng::render::RendererConfig::Present;
  c.present = o.present == "swapchain" ? P::Swapchain : o.present == "shm" ? P::SharedMemory : P::Auto;
  return c;
}

// The frame costs: `simulate` (4 physics ticks), `render` (wall time of fill_frame + render, headless also the read
// back), `render_cpu` (the CPU time all threads spent in it, headless only: the window overlaps frames) and, in the
// window, `frame` (from one shown frame to the next: what the player sees, simulation and UI included).
struct RunTimes {
  FrameTimes sim, render, render_cpu, frame;
  double first_frame_s = -1.0;  // start_to_first_frame_s; -1 when nothing was rendered
  void frame_done() {
    if (first_frame_s < 0.0) first_frame_s = std::chrono::duration<double>(clock_type::now() - kProgramStart).count();
  }
};

nlohmann::json base_report(const Options& o, const World& w, long frames, const eng::render::Renderer& r,
                           const RunTimes& t, bool headless) {
  nlohmann::json j = world_report(w);
  j["seed"] = w.options.seed;  // the world's: in the window the title's start may change it
  j["seconds"] = w.data.time;
  j["frames"] = frames;
  j["headless"] = headless;
  j["width"] = o.width;
  j["height"] = o.height;
  j["device"] = r.device_name();
  j["driver"] = r.driver_info();
  j["validation"] = {{"active", r.validation_active()},
                     {"errors", r.validation_errors()},
                     {"warnings", r.validation_warnings()}};
  j["frame_times"] = {{"simulate", t.sim.summary()}, {"render", t.render.summary()}};
  if (headless) j["frame_times"]["render_cpu"] = t.render_cpu.summary();
  else j["frame_times"]["frame"] = t.frame.summary();
  j["present"] = r.present_path();
  j["start_to_first_frame_s"] = t.first_frame_s;
  j["max_rss_mb"] = max_rss_mb();
  return j;
}

eng::Result<void> write_report(const std::string& path, const nlohmann::json& j) {
  if (path.empty()) return {};
  const std::string fail = "boxing: cannot write report '" + path + "' (check the folder exists and is writable)";
  std::error_code ec;  // the non-throwing overload: a read-only parent is this error, not an exception
  if (auto parent = fs::path(path).parent_path(); !parent.empty()) fs::create_directories(parent, ec);
  if (ec) return eng::make_error(fail + ": " + ec.message());
  std::ofstream f(path);
  if (!f) return eng::make_error(fail);
  f << j.dump(2) << "\n";
  f.close();
  if (!f) return eng::make_error(fail + ": the write failed");
  return {};
}

eng::Result<void> save_png(const eng::Image& img, const std::string& path) {
  if (auto parent = fs::path(path).parent_path(); !parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
  }
  auto r = eng::write_png(img, path);
  if (!r) return eng::make_error("boxing: cannot write '" + path + "': " + r.error());
  return {};
}

eng::Result<void> write_recording(const Options& o, const World& w) {
  if (o.record.empty()) return {};
  auto ok = write_input_file(o.record, w.interaction->recorded);
  if (ok) std::printf("boxing: %zu input events recorded to %s (play back: --scenario %s --seed %llu --input %s)\n",
                      w.interaction->recorded.size(), o.record.c_str(), w.options.scenario.c_str(),
                      static_cast<unsigned long long>(w.options.seed), o.record.c_str());
  return ok;
}

}  // namespace

eng::Result<HeadlessRun> run_headless(const Options& o) {
  auto world = make_world(o);
  if (!world) return eng::make_error(world.error());
  World& w = **world;
  std::unique_ptr<GameAudio> audio;  // --audio-out: the mix to a WAV (headless never opens an audio device)
  if (!o.audio_out.empty()) {
    auto a = make_game_audio({o.audio_out, false, {}});
    if (!a) return eng::make_error(a.error());
    audio = std::move(*a);
  }
  auto renderer = eng::render::Renderer::create_headless(renderer_config(o));
  if (!renderer) return eng::make_error("boxing: " + renderer.error());
  eng::render::Renderer& r = **renderer;
  const SceneView view = make_scene_view(w, r);

  const double seconds = o.seconds > 0 ? o.seconds : 2.0;
  const long frames = std::max(1L, std::lround(seconds * 60.0));
  eng::render::FrameDesc f;
  f.camera = camera_preset(o.camera, w);
  f.overlay = o.overlay_given && o.overlay;
  RunTimes times;
  FrameTimes &sim = times.sim, &render = times.render;
  HeadlessRun out;
  if (audio) game_audio_listen(*audio, f.camera);
  for (long frame = 1; frame <= frames; ++frame) {
    const auto t0 = clock_type::now();
    for (int s = 0; s < kStepsPerFrame; ++s) step_world(w);
    sim.ms.push_back(std::chrono::duration<double, std::milli>(clock_type::now() - t0).count());
    if (audio)
      if (auto ok = game_audio_update(*audio, w); !ok) return eng::make_error(ok.error());
    const bool last = frame == frames;
    const bool every = o.render_every > 0 && frame % o.render_every == 0 && frame >= o.frames_from * 60.0;
    if (!last && !every) continue;
    const auto t1 = clock_type::now();
    const double c1 = process_cpu_ms();
    fill_frame(w, view, f);
    if (f.overlay) {  // no input headless: the panel only shows
      eng::ui::UiInput in;
      in.display_width = float(o.width);
      in.display_height = float(o.height);
      eng::ui::ui_begin(r.ui(), in);
      draw_stats_panel({float(sim.ms.back()), r.device_name(),
                        {"t = " + std::to_string(w.data.time) + " s", "scenario " + o.scenario},
                        w.match->active ? 175.0f : 10.0f});  // below the HUD's name plates and their notices
      if (w.match->active) draw_broadcast_hud(match_hud(w), hud_fonts(r.ui()));
      eng::ui::ui_end(r.ui());
    }
    if (auto ok = r.render(f); !ok) return eng::make_error("boxing: rendering failed: " + ok.error());
    auto img = r.read_back();
    if (!img) return eng::make_error("boxing: reading the frame back failed: " + img.error());
    render.ms.push_back(std::chrono::duration<double, std::milli>(clock_type::now() - t1).count());
    times.render_cpu.ms.push_back(process_cpu_ms() - c1);
    times.frame_done();
    if (every && !o.frames_dir.empty()) {
      char name[64];
      std::snprintf(name, sizeof name, "frame_%05ld.png", frame);
      if (auto ok = save_png(*img, (fs::path(o.frames_dir) / name).string()); !ok) return eng::make_error(ok.error());
    }
    if (last) out.image = std::move(*img);
  }
  out.report = base_report(o, w, frames, r, times, true);
  if (audio) {
    if (auto ok = game_audio_finish(*audio, w); !ok) return eng::make_error(ok.error());
    out.report["audio"] = game_audio_report(*audio);
  }
  out.driver = r.device_name() + " / " + r.driver_info();
  out.validation_errors = r.validation_errors();
  out.validation_active = r.validation_active();
  if (!o.screenshot.empty())
    if (auto ok = save_png(out.image, o.screenshot); !ok) return eng::make_error(ok.error());
  if (auto ok = write_report(o.report, out.report); !ok) return eng::make_error(ok.error());
  if (auto ok = write_recording(o, w); !ok) return eng::make_error(ok.error());
  return out;
}

namespace {

// Orbit camera for the window: right-drag orbits, wheel zooms, C cycles the presets.
struct OrbitCamera {
  glm::vec3 target;
  float yaw, pitch, dist;
  void from(const eng::render::Camera& c) {
    target = c.target;
    const glm::vec3 d = c.eye - c.target;
    dist = glm::length(d);
    yaw = std::atan2(d.y, d.x);
    pitch = std::asin(d.z / dist);
  }
  eng::render::Camera to(eng::render::Camera c) const {
    c.target = target;
    c.eye = target + dist * glm::vec3(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
    return c;
  }
};

static_assert(unsigned(kHeldLeftShift) == eng::platform::Window::kHeldLeftShift &&
                  unsigned(kHeldRightShift) == eng::platform::Window::kHeldRightShift &&
                  unsigned(kHeldLeftCtrl) == eng::platform::Window::kHeldLeftCtrl &&
                  unsigned(kHeldRightCtrl) == eng::platform::Window::kHeldRightCtrl,
              "fight_keys.h's modifier bits are the window's");

const char* const kCameras[] = {"default", "closeup", "side", "top"};  // the C key's cycle

// The instant replay (match): a second after a knockdown, the 1.5 s before it and the second after, at 0.35x from
// the side camera; the simulation waits (it is not stepped), so the fight is the same with or without replays.
struct Replay {
  bool active = false;
  double pending = -1.0, from = 0.0, to = 0.0, at = 0.0;
  int knockdowns = 0;
};

// What the window's loop carries from one frame to the next.
struct WindowRun {
  const Options& o;
  std::unique_ptr<World>& world;  // replaced by a restart
  eng::platform::Window& win;
  eng::render::Renderer& r;
  SceneView view;
  eng::render::FrameDesc f;
  OrbitCamera orbit;
  int camera_index = 0;
  bool overlay = false;  // H: the debug overlay (frame time, device, time scale, seed); --overlay starts with it
  bool ui_visible = true;  // the HUD and the screens (--no-overlay: none, a clean picture)
  PanelState panel;
  FrontEnd front;        // the screens: title, playing, paused, result (front_end.h)
  // A heavy hit's hit-stop (hit_feedback.h): the simulation holds until then; the hits' times already read.
  clock_type::time_point hit_stop_until{};
  double hits_read_to = 0.0;
  int hit_stops = 0;
  double hit_stop_max_s = 0.0;
  std::string title;     // the window's title now
  std::vector<std::string> log;  // what the keys and menus did, in order (the report's front_end.log; tests read it)
  MouseHands hands;
  bool left_was_down = false;
  RunTimes times;
  long frames = 0, frames_shown = 0;  // simulated 60 Hz frames; frames shown
  int shots = 0;                      // F12 screenshots so far
  double accumulator = 0.0;           // real time (scaled by the slow motion) not yet simulated, s
  clock_type::time_point last_shown{}, last_sim{}, last_ui{};
  Replay replay;
  Eigen::VectorXd live_q;  // the live coordinates while a replay shows recorded ones
  glm::dvec2 last_mouse;
  // The gamepads (poll_pads): each one's state as read this frame and as last sent to the world (a pad event when
  // they differ), and its name.
  std::array<PadState, kMaxPads> pad_now{}, pad_sent{};
  std::array<std::string, kMaxPads> pad_name;

  WindowRun(const Options& options, std::unique_ptr<World>& w, eng::platform::Window& window,
            eng::render::Renderer& renderer)
      : o(options), world(w), win(window), r(renderer), view(make_scene_view(*w, renderer)) {
    for (int i = 0; i < 4; ++i)
      if (o.camera == kCameras[i]) camera_index = i;
    orbit.from(camera_preset(kCameras[camera_index], *world));
    overlay = o.overlay_given && o.overlay;
    ui_visible = !o.overlay_given || o.overlay;
    panel.open = false;  // the physics panel: Tab opens and closes it
    front = front_end_for(o);
    panel.seed = int(o.seed);
    panel.slow = o.slow == 2 ? 1 : o.slow == 4 ? 2 : o.slow == 10 ? 3 : 0;
    last_sim = clock_type::now();
    last_mouse = win.mouse_position();
    last_ui = clock_type::now();
  }
};

// This frame's UI input, read once after the events are polled, and the camera and cursor ray it gives.
struct FrameInput {
  eng::ui::UiInput uin;
  float ui_dt = 0.0f;  // s since the last UI frame
  bool ui_mouse = false;  // the mouse belongs to a panel or a screen
  bool ui_text = false;   // a clicked text field is being edited: the keys are its own
  eng::render::Camera cam;
  bool mouse_in = false;  // the cursor is over the window
  CameraRay ray;
};

// The UI frame opens first: it says whether this frame's mouse and keys belong to a panel or to the scene; the
// panels are built after the simulation (they show its time) and the frame ends before rendering.
FrameInput begin_ui_frame(WindowRun& s) {
  FrameInput in;
  const auto ui_now = clock_type::now();
  in.ui_dt = std::max(1e-4f, std::chrono::duration<float>(ui_now - s.last_ui).count());
  s.last_ui = ui_now;
  in.uin = s.win.ui_input(in.ui_dt);
  // Tab is the game's (the panel's toggle), never ImGui's: with a panel focused, ImGui's Tab moved the focus into
  // its next field (a slider turned text field), which then held the keyboard.
  in.uin.key_down[static_cast<int>(eng::ui::Key::Tab)] = false;
  eng::ui::ui_begin(s.r.ui(), in.uin);
  in.ui_mouse = eng::ui::ui_wants_mouse(s.r.ui());
  // The keys are the game's unless a text field the player clicked is being edited (io.WantTextInput). Not
  // io.WantCaptureKeyboard: it is true whenever any widget is active (ImGui 1.86: ActiveId != 0), a text field that
  // Tab had focused included, and the game's keys then went nowhere.
  in.ui_text = eng::ui::ui_wants_text(s.r.ui());
  if (s.front.screen == Screen::Title) s.orbit.yaw += 0.05f * in.ui_dt;  // the title's camera circles the ring slowly
  in.cam = s.orbit.to(camera_preset(kCameras[s.camera_index], *s.world));
  in.mouse_in = in.uin.mouse_x > -1e30f;
  in.ray = camera_ray(in.cam, in.uin.mouse_x, in.uin.mouse_y, in.uin.display_width, in.uin.display_height);
  return in;
}

// A new world for `options` (a mode started from the title, a restart): the view keeps its ghost and debug drawing,
// the camera its preset; the hands, the replay and the time accumulated start again.
void start_world(WindowRun& s, const Options& options) {
  auto made = make_world(options);
  if (!made) {
    std::fprintf(stderr, "%s\n", made.error().c_str());
    return;
  }
  s.world = std::move(*made);
  SceneView v = make_scene_view(*s.world, s.r);
  v.ghost = s.view.ghost, v.debug = s.view.debug;
  s.view = std::move(v);
  s.hands = MouseHands{};
  s.pad_sent = {};  // the new world has heard of no pad: what is held now is sent again
  s.replay = {};
  s.accumulator = 0.0;
  s.hits_read_to = 0.0, s.hit_stop_until = {};
  s.panel.seed = int(options.seed);
}

// The panel's restart (F5, its button): a new world with the panel's seed (the recording starts again with it).
void restart_if_asked(WindowRun& s) {
  if (!s.panel.restart) return;
  s.panel.restart = false;
  Options ro = s.world->options;
  ro.seed = uint64_t(s.panel.seed);
  start_world(s, ro);
}

// What a menu chose (front_end.h), carried out: a mode started or restarted (a new world), the title, quit.
void carry_out(WindowRun& s, FrontAction a) {
  if (a == FrontAction::None) return;
  const Screen was = s.front.screen;
  front_end_apply(s.front, a);
  if (a == FrontAction::Start || a == FrontAction::Restart) s.panel.paused = false;
  if (a == FrontAction::Start) {
    start_world(s, options_for(s.o, s.front.settings));
    s.orbit.from(camera_preset(kCameras[s.camera_index], *s.world));
    s.log.push_back(std::string("start ") + mode_name(s.front.settings.mode));
  } else if (a == FrontAction::Restart) {
    start_world(s, s.world->options);
    s.log.push_back("restart");
  } else if (a == FrontAction::Quit) {
    s.win.request_close();
    s.log.push_back("quit");
  } else if (s.front.screen != was) {
    s.log.push_back(screen_name(s.front.screen));
  }
}

// A menu key (the keyboard's or a pad's) on the screen showing.
void apply_menu_key(WindowRun& s, MenuKey k) {
  const Screen was = s.front.screen;
  const FrontAction a = front_end_key(s.front, k);
  if (s.front.screen != was) s.log.push_back(screen_name(s.front.screen));
  carry_out(s, a);
}

// The menus' keys on the title, the pause menu and the result; Esc while playing opens the pause menu.
void handle_menu_keys(WindowRun& s) {
  constexpr std::pair<int, MenuKey> kMenuKeys[] = {
      {GLFW_KEY_UP, MenuKey::Up},       {GLFW_KEY_DOWN, MenuKey::Down},      {GLFW_KEY_LEFT, MenuKey::Left},
      {GLFW_KEY_RIGHT, MenuKey::Right}, {GLFW_KEY_ENTER, MenuKey::Enter},    {GLFW_KEY_KP_ENTER, MenuKey::Enter},
      {GLFW_KEY_SPACE, MenuKey::Enter}, {GLFW_KEY_ESCAPE, MenuKey::Back}};
  for (const int pressed : s.win.keys_pressed())  // in order: two quick Downs move the cursor two rows
    for (const auto& [key, menu_key] : kMenuKeys) {
      if (key != pressed) continue;
      if (s.front.screen == Screen::Playing && menu_key != MenuKey::Back) continue;  // the arrows are not the game's
      apply_menu_key(s, menu_key);
    }
}

// The keys, unless a text field the player clicked has them: the menus'; then, playing, the debug overlay, the ghost,
// the camera, the fight keys, throws and the panel's keys (Tab the panel, P pause, ...).
void handle_keys(WindowRun& s, const FrameInput& in) {
  if (in.ui_text) return;
  handle_menu_keys(s);  // may start a new world
  if (s.front.screen != Screen::Playing) return;
  World& w = *s.world;
  eng::platform::Window& win = s.win;
  if (win.key_pressed(GLFW_KEY_H)) {
    s.overlay = !s.overlay;
    s.log.push_back(s.overlay ? "debug overlay on" : "debug overlay off");
  }
  if (win.key_pressed(GLFW_KEY_G)) s.view.ghost = !s.view.ghost;
  if (win.key_pressed(GLFW_KEY_C)) {
    s.camera_index = (s.camera_index + 1) % 4;
    s.orbit.from(camera_preset(kCameras[s.camera_index], w));
  }
  // The fight keys (fight_keys.h): each half of the keyboard drives its boxer (two players: left red, right blue;
  // one: the player's whole keyboard); the first key takes that boxer over from the AI. Every press of the frame,
  // in the order pressed (two presses of J in one frame are two jabs: player_input.h).
  if (w.match->active) {
    const bool versus = w.options.mode == "versus";
    const int pads = pads_connected(*w.interaction);
    const std::vector<int>& keys = win.keys_pressed();
    const std::vector<unsigned>& held = win.keys_pressed_held();
    for (size_t i = 0; i < keys.size(); ++i)
      if (const FightKey* k = fight_key(keys[i], held[i])) {
        InputEvent e;
        e.kind = InputKind::Key;
        e.action = k->action;
        e.boxer = key_boxer(k->half, pads, versus, w.options.player);
        interaction_submit(w, e);
      }
  }
  // Throws from the camera toward the cursor; Backspace clears them.
  if (in.mouse_in && win.key_pressed(GLFW_KEY_T)) interaction_submit(w, throw_from_camera(w, in.ray, ObjectKind::Ball));
  if (in.mouse_in && win.key_pressed(GLFW_KEY_Y)) interaction_submit(w, throw_from_camera(w, in.ray, ObjectKind::Crate));
  if (win.key_pressed(GLFW_KEY_BACKSPACE)) {
    InputEvent e;
    e.kind = InputKind::Clear;
    interaction_submit(w, e);
  }
  const PanelState before = s.panel;
  handle_panel_keys(w, s.view, s.panel,
                    {[](const void* c, int k) { return static_cast<const eng::platform::Window*>(c)->key_pressed(k); },
                     &win});
  if (s.panel.open != before.open) s.log.push_back(s.panel.open ? "panel open" : "panel closed");
  if (s.panel.paused != before.paused) s.log.push_back(s.panel.paused ? "physics paused" : "physics running");
  if (s.panel.step_once && !before.step_once) s.log.push_back("one frame");
  if (s.panel.slow != before.slow) s.log.push_back(std::string("time ") + time_scale_name(s.panel));
}

// The gamepads, read every frame through GLFW's gamepad API (a pad plugged in or pulled out shows up here: the
// hot-plug). Start pauses and resumes; off the fight the d-pad, A and B work the menus as the arrows, Enter and Esc
// do. While a match plays, a pad whose state changed goes to the world as a pad event (gamepad.h maps it to fight
// actions each physics step; --record writes it).
void poll_pads(WindowRun& s) {
  for (int jid = 0; jid < kMaxPads; ++jid) {
    const eng::platform::GamepadReading g = eng::platform::read_gamepad(jid);
    PadState now;
    now.connected = g.connected;
    for (int k = 0; k < kPadButtons; ++k) now.buttons[k] = g.buttons[k];
    for (int k = 0; k < kPadAxes; ++k) now.axes[k] = g.axes[k];
    const PadState was = s.pad_now[jid];
    s.pad_now[jid] = now;
    if (now.connected != was.connected) {
      s.pad_name[jid] = g.name;
      s.log.push_back("pad " + std::to_string(jid + 1) + (now.connected ? " connected: " + s.pad_name[jid] : " gone"));
    }
    auto pressed = [&](PadButton b) { return now.buttons[b] && !was.buttons[b]; };
    if (s.front.screen == Screen::Playing) {
      if (pressed(kPadStart)) apply_menu_key(s, MenuKey::Back);
      continue;
    }
    constexpr std::pair<PadButton, MenuKey> kPadMenu[] = {
        {kPadDpadUp, MenuKey::Up},     {kPadDpadDown, MenuKey::Down}, {kPadDpadLeft, MenuKey::Left},
        {kPadDpadRight, MenuKey::Right}, {kPadA, MenuKey::Enter},       {kPadB, MenuKey::Back}};
    for (const auto& [button, key] : kPadMenu)
      if (pressed(button)) apply_menu_key(s, key);
    if (pressed(kPadStart)) apply_menu_key(s, s.front.screen == Screen::Paused ? MenuKey::Back : MenuKey::Enter);
  }
  World& w = *s.world;
  if (s.front.screen != Screen::Playing || !w.match->active) return;
  for (int jid = 0; jid < kMaxPads; ++jid) {
    if (s.pad_now[jid] == s.pad_sent[jid]) continue;
    InputEvent e;
    e.kind = InputKind::Pad;
    e.pad = jid;
    e.pad_state = s.pad_now[jid];
    interaction_submit(w, e);
    s.pad_sent[jid] = s.pad_now[jid];
  }
}

// Who has which controls (the HUD's name plates, the pause menu): two players, or the player with pads.
std::string who_controls(const World& w, int boxer) {
  const bool versus = w.options.mode == "versus";
  return controls_tag(boxer, pads_connected(*w.interaction), versus, w.options.player);
}

// The pause menu's lines under the controls: each player's controls, the pads by name.
std::vector<std::string> pause_who(const WindowRun& s) {
  const World& w = *s.world;
  std::vector<std::string> who;
  if (w.match->active && (w.options.mode == "versus" || w.options.player >= 0))
    for (int k = 0; k < 2; ++k)
      if (const std::string t = who_controls(w, k); !t.empty())
        who.push_back(std::string(k == 0 ? "RED" : "BLUE") + (w.options.mode == "versus" ? (k == 0 ? " (P1): " : " (P2): ") : ": ") + t);
  std::string pads;
  for (int jid = 0; jid < kMaxPads; ++jid)
    if (s.pad_now[jid].connected) pads += (pads.empty() ? "" : ", ") + std::to_string(jid + 1) + " " + s.pad_name[jid];
  who.push_back(pads.empty() ? "NO GAMEPAD (plug one in: it is picked up at once)" : "GAMEPADS: " + pads);
  return who;
}

// The mouse: the left button grabs what is under the cursor, drags it and lets go (the panel keeps its own clicks);
// the right button orbits the camera and the wheel zooms (a held body takes the wheel instead).
void handle_mouse(WindowRun& s, const FrameInput& in) {
  World& w = *s.world;
  const glm::dvec2 mouse = s.win.mouse_position();
  const bool left = in.uin.mouse_down[0];
  const double wheel = in.uin.wheel_y;
  if (left && !s.left_was_down && !in.ui_mouse && in.mouse_in) {
    const bool strong = s.win.key_down(GLFW_KEY_LEFT_SHIFT) || s.win.key_down(GLFW_KEY_RIGHT_SHIFT);
    hands_press(w, s.hands, in.ray, in.cam, strong);
  } else if (left && s.hands.held && in.mouse_in) {
    hands_drag(w, s.hands, in.ray, in.cam, wheel);
  } else if (!left && s.hands.held) {
    hands_release(w, s.hands);
  }
  s.left_was_down = left;
  if (!in.ui_mouse) {  // drags and the wheel over a panel are the panel's
    if (s.win.mouse_button_down(GLFW_MOUSE_BUTTON_RIGHT)) {
      s.orbit.yaw -= float(mouse.x - s.last_mouse.x) * 0.006f;
      s.orbit.pitch = std::clamp(s.orbit.pitch + float(mouse.y - s.last_mouse.y) * 0.006f, -0.1f, 1.5f);
    }
    if (!s.hands.held)
      s.orbit.dist = std::clamp(s.orbit.dist * std::pow(0.9f, float(s.win.scroll_delta().y)), 1.0f, 20.0f);
  }
  s.last_mouse = mouse;
}

// Fixed 60 Hz simulation frames, as many as real time (scaled by the slow motion) asks for: the simulated clock
// keeps up with the wall clock down to 4 rendered frames a second (a frame of two boxers' physics costs about
// 1 ms, so the catch-up of 15 frames is 15 ms); below that, at most 0.25 s a frame, the game slows down instead
// of spiralling. Paused or in a replay: only the panel's single steps. --seconds closes the window.
void step_simulation(WindowRun& s) {
  World& w = *s.world;
  constexpr double kMaxCatchUp = 0.25;
  const auto now = clock_type::now();
  if (now < s.hit_stop_until) {  // a heavy hit holds the fight a moment of real time (not caught up after)
    s.last_sim = now;
    return;
  }
  s.accumulator =
      std::min(s.accumulator + time_scale(s.panel) * std::chrono::duration<double>(now - s.last_sim).count(), kMaxCatchUp);
  s.last_sim = now;
  // Off the fight (the title, the pause menu, the result) the simulation waits, as it does paused or in a replay.
  const bool playing = s.front.screen == Screen::Playing;
  if (!playing) s.panel.step_once = false;
  if (s.replay.active || s.panel.paused || !playing) s.accumulator = 0.0;
  if (s.panel.step_once && !s.replay.active) s.accumulator = 1.0 / 60.0, s.panel.step_once = false;
  while (s.accumulator >= 1.0 / 60.0) {
    const auto t0 = clock_type::now();
    for (int k = 0; k < kStepsPerFrame; ++k) step_world(w);
    s.times.sim.ms.push_back(std::chrono::duration<double, std::milli>(clock_type::now() - t0).count());
    s.accumulator -= 1.0 / 60.0;
    ++s.frames;
  }
  // The frame's new hits: the heaviest sets the hit-stop.
  double stop = 0.0;
  for (const Interaction::Flash& fl : w.interaction->flashes)
    if (fl.t > s.hits_read_to) stop = std::max(stop, hit_stop_seconds(fl));
  s.hits_read_to = w.data.time;
  if (stop > 0.0) {
    s.hit_stop_until = clock_type::now() + std::chrono::duration_cast<clock_type::duration>(std::chrono::duration<double>(stop));
    ++s.hit_stops;
    s.hit_stop_max_s = std::max(s.hit_stop_max_s, stop);
  }
  if (s.o.seconds > 0 && w.data.time >= s.o.seconds) s.win.request_close();
}

// A knockdown in the match schedules the instant replay a second later; it starts once the replay buffer has
// frames, from the live coordinates kept in live_q. The bout over, the result screen opens a little later.
void watch_for_replay(WindowRun& s) {
  World& w = *s.world;
  if (!w.match->active) return;
  const Screen was = s.front.screen;
  front_end_watch_bout(s.front, w.match->over && !s.replay.active, w.data.time);
  if (s.front.screen != was) s.log.push_back(screen_name(s.front.screen));
  Replay& replay = s.replay;
  const int kd = w.match->fighter[0].knockdowns + w.match->fighter[1].knockdowns;
  if (kd > replay.knockdowns && !replay.active) replay.pending = w.data.time + 1.0, replay.from = w.data.time - 1.5;
  replay.knockdowns = kd;
  if (replay.pending >= 0.0 && w.data.time >= replay.pending && w.match->replay.count() > 0) {
    replay.active = true;
    replay.pending = -1.0;
    replay.to = w.data.time;
    replay.at = std::max(replay.from, w.match->replay.time(0));
    s.live_q = w.data.q;
  }
}

// The key hints along the bottom while playing: what a newcomer needs to find the menu, the panel and the fight.
std::string key_hints(const World& w) {
  std::string line = "Esc menu + controls   Tab physics panel   H debug";
  const bool versus = w.options.mode == "versus";
  if (w.match->active && versus)
    line += "   P1: WASD QE  R F V B Z X  L-Shift+WASD   P2: arrows  J K U I N M  R-Shift+arrows";
  else if (w.match->active && w.options.player >= 0)
    line += "   WASD step  QE pivot  J K jab cross  U I hooks  N M uppercuts  Shift+WASD block slip duck";
  else if (!w.match->active) line += "   left-drag grab   T ball   Y crate   C camera";
  else line += "   C camera";
  return line;
}

// The screen's UI: the broadcast HUD while a match shows (the fight, the pause menu and the result over it), the
// debug overlay (H) and the physics panel (Tab) while playing, the title, the pause menu or the result; then the UI
// frame ends. The chosen menu action is carried out after the frame.
void draw_panels(WindowRun& s) {
  World& w = *s.world;
  const HudFonts fonts = hud_fonts(s.r.ui());
  const bool playing = s.front.screen == Screen::Playing;
  if (w.match->active && s.front.screen != Screen::Title) {
    MatchHud hud = match_hud(w);
    if (s.replay.active) hud.banner = hud.cards = "REPLAY";
    // Who has which controls: two players' halves and pads, or the player's pads.
    for (int k = 0; k < 2; ++k) {
      const std::string t = who_controls(w, k);
      if (w.options.mode == "versus") hud.side[k].tag = (k == 0 ? "P1: " : "P2: ") + t;
      else if (hud.side[k].player && pads_connected(*w.interaction) > 0) hud.side[k].tag = "YOU: " + t;
    }
    if (s.front.screen != Screen::Result) draw_broadcast_hud(hud, fonts);
  }
  if (playing && s.overlay) {
    char status[160];
    std::snprintf(status, sizeof status, "t = %.2f s  %s  scenario %s  seed %llu", w.data.time,
                  s.panel.paused ? "PAUSED" : time_scale_name(s.panel), w.options.scenario.c_str(),
                  static_cast<unsigned long long>(w.options.seed));
    // Below the HUD's name plates. The HUD shows the frame as the player gets it: from one shown frame to the next.
    HudStats stats{s.times.frame.ms.empty() ? 0.0f : float(s.times.frame.ms.back()), s.r.device_name(),
                   {status, "F12 shot  H debug  C camera  Tab panel  Esc menu"}};
    stats.top = 175.0f;  // below the name plates and their notices (TIRED, BUSY)
    draw_stats_panel(stats);
  }
  if (playing && s.panel.open) {
    draw_control_panel(w, s.view, s.panel);
    if (!s.panel.open) s.log.push_back("panel closed");  // its title bar's arrow
  }
  if (playing) draw_key_hints(key_hints(w), fonts.medium);
  if (playing && s.ui_visible && !w.match->active) draw_caption(scenario_caption(w), fonts.medium);  // says what it is
  FrontAction chosen = FrontAction::None;
  if (s.front.screen == Screen::Title) chosen = draw_title(s.front, fonts);
  if (s.front.screen == Screen::Paused) chosen = draw_pause_menu(s.front, fonts, pause_who(s));
  if (s.front.screen == Screen::Result && w.match->active) chosen = draw_result(bout_summary(w), fonts);
  eng::ui::ui_end(s.r.ui());
  carry_out(s, chosen);
}

// The frame: the live scene from the orbit camera, or during a replay the recorded coordinates of its moment from
// the side camera (the live ones restored after), then rendered and presented. False when rendering failed.
bool render_frame(WindowRun& s, const FrameInput& in) {
  World& w = *s.world;
  const auto t1 = clock_type::now();
  if (s.replay.active) {
    const ReplayBuffer& rb = w.match->replay;
    const int i = rb.at_or_before(s.replay.at);
    std::copy(rb.q(i), rb.q(i) + rb.nq(), w.data.q.data());
    eng::physics::forward_kinematics(w.model, w.data);
    fill_frame(w, s.view, s.f);
    s.f.camera = camera_preset("side", w);
    w.data.q = s.live_q;
    eng::physics::forward_kinematics(w.model, w.data);
    s.replay.at += 0.35 * in.ui_dt;
    if (s.replay.at > s.replay.to) s.replay.active = false;
  } else {
    fill_frame(w, s.view, s.f);
    s.f.camera = in.cam;
    const glm::vec3 shake = camera_shake(*w.interaction, w.data.time);  // heavy hits shake it (hit_feedback.h)
    s.f.camera.eye += shake, s.f.camera.target += shake;
  }
  s.f.overlay = s.ui_visible || s.front.screen != Screen::Playing;  // --no-overlay hides no menu
  if (auto ok = s.r.render(s.f); !ok) {
    std::fprintf(stderr, "boxing: rendering failed: %s\n", ok.error().c_str());
    return false;
  }
  const auto t2 = clock_type::now();
  s.times.render.ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
  if (s.frames_shown++ > 0) s.times.frame.ms.push_back(std::chrono::duration<double, std::milli>(t2 - s.last_shown).count());
  s.last_shown = t2;
  s.times.frame_done();
  return true;
}

// F12 saves out/screenshot_NNN.png; --screenshot saves the last frame when the window closes.
void save_screenshot_if_asked(WindowRun& s) {
  if (!s.win.key_pressed(GLFW_KEY_F12) && (s.o.screenshot.empty() || !s.win.should_close())) return;
  std::string path = s.o.screenshot;
  if (path.empty() || !s.win.should_close()) {
    char name[64];
    std::snprintf(name, sizeof name, "out/screenshot_%03d.png", ++s.shots);
    path = name;
  }
  auto img = s.r.read_back();
  if (img && save_png(*img, path).ok()) std::printf("boxing: screenshot saved to %s\n", path.c_str());
  else std::fprintf(stderr, "boxing: screenshot failed\n");
}

// The window's title says what runs and the screen: "Boxing - title (seed 1)", "Boxing - play (seed 3)", "Boxing -
// play (seed 3) - result" (a player sees it; a window test finds its window by it and waits on its screen).
std::string window_title(const FrontEnd& fe, const Options& world) {
  const std::string seed = " (seed " + std::to_string(world.seed) + ")";
  if (fe.screen == Screen::Title) return "Boxing - title" + seed;
  const std::string what = "Boxing - " + (world.mode.empty() ? world.scenario : world.mode) + seed;
  return fe.screen == Screen::Playing ? what : what + " - " + screen_name(fe.screen);
}

void update_title(WindowRun& s) {
  std::string t = window_title(s.front, s.world->options);
  if (t == s.title) return;
  s.win.set_title(t);
  s.title = std::move(t);
}

// The frame's sound: the listener at the camera, the slow motion's speed, the world's new events mixed and played
// (the device, and --audio-out). False (said) when the WAV cannot be written.
bool feed_audio(GameAudio& a, WindowRun& s, const FrameInput& in) {
  game_audio_listen(a, in.cam);
  game_audio_speed(a, time_scale(s.panel));
  auto ok = game_audio_update(a, *s.world);
  if (!ok) std::fprintf(stderr, "%s\n", ok.error().c_str());
  return ok.ok();
}

// After the window closes: the report, the recording, and the exit code (1 on a validation error).
int finish_windowed(WindowRun& s) {
  World& w = *s.world;
  nlohmann::json report = base_report(s.o, w, s.frames, s.r, s.times, false);
  // The window's own state at the close and what its keys and menus did, in order (the window tests read it).
  report["front_end"] = {{"screen", screen_name(s.front.screen)},
                         {"mode", w.options.mode},
                         {"panel_open", s.panel.open},
                         {"debug_overlay", s.overlay},
                         {"physics_paused", s.panel.paused},
                         {"time_scale", time_scale_name(s.panel)},
                         {"hit_stops", s.hit_stops},
                         {"hit_stop_max_ms", 1000.0 * s.hit_stop_max_s},
                         {"log", s.log}};
  if (auto ok = write_report(s.o.report, report); !ok) {
    std::fprintf(stderr, "%s\n", ok.error().c_str());
    return 1;
  }
  if (auto ok = write_recording(s.o, w); !ok) {
    std::fprintf(stderr, "%s\n", ok.error().c_str());
    return 1;
  }
  if (s.r.validation_errors() > 0) {
    std::fprintf(stderr, "boxing: %d Vulkan validation errors (see above)\n", s.r.validation_errors());
    return 1;
  }
  return 0;
}

// The window: one loop of stages a frame, in this order; the simulation steps between the input and the panels.
int run_windowed(const Options& o) {
  // The title shows the match's ring and boxers behind it, waiting (the simulation runs only while playing).
  const bool title = front_end_for(o).screen == Screen::Title;
  auto made = make_world(title ? apply_mode(o, Mode::Watch) : o);
  if (!made) {
    std::fprintf(stderr, "%s\n", made.error().c_str());
    return 1;
  }
  std::unique_ptr<World> world = std::move(*made);
  eng::platform::WindowConfig wc;
  wc.width = o.width;
  wc.height = o.height;
  wc.title = window_title(front_end_for(o), title ? apply_mode(o, Mode::Watch) : o);
  auto window = eng::platform::Window::create(wc);
  if (!window) {
    std::fprintf(stderr, "boxing: %s\n", window.error().c_str());
    return 1;
  }
  auto renderer = eng::render::Renderer::create_windowed(renderer_config(o), **window);
  if (!renderer) {
    std::fprintf(stderr, "boxing: %s\n", renderer.error().c_str());
    return 1;
  }
  WindowRun s(o, world, **window, **renderer);
  s.title = wc.title;
  auto audio = make_game_audio({o.audio_out, true, {}});  // the device (or silent, said once) and --audio-out
  if (!audio) {
    std::fprintf(stderr, "%s\n", audio.error().c_str());
    return 1;
  }
  while (!s.win.should_close()) {
    restart_if_asked(s);
    s.win.poll_events();
    const FrameInput in = begin_ui_frame(s);
    handle_keys(s, in);
    poll_pads(s);
    handle_mouse(s, in);
    step_simulation(s);
    if (!feed_audio(**audio, s, in)) return 1;
    watch_for_replay(s);
    draw_panels(s);
    update_title(s);
    if (s.win.minimized()) continue;
    if (!render_frame(s, in)) return 1;
    save_screenshot_if_asked(s);
  }
  if (auto ok = game_audio_finish(**audio, *s.world); !ok) {
    std::fprintf(stderr, "%s\n", ok.error().c_str());
    return 1;
  }
  return finish_windowed(s);
}

}  // namespace

int run(const Options& given) {
  // --mode: its scenario and players (front_end.h), in the window and headless alike.
  const std::optional<Mode> mode = mode_from_name(given.mode);
  const Options o = mode ? apply_mode(given, *mode) : given;
  bool headless = o.headless;
  if (!headless && !eng::platform::display_available()) {
    std::fprintf(stderr, "boxing: no display found (DISPLAY is not set or the X server does not answer); "
                         "running headless instead (pass --headless to choose it, or start an X server / Xvfb)\n");
    headless = true;
  }
  if (!headless) return run_windowed(o);
  Options ho = o;
  ho.headless = true;
  auto run = run_headless(ho);
  if (!run) {
    std::fprintf(stderr, "%s\n", run.error().c_str());
    return 1;
  }
  if (!o.screenshot.empty()) std::printf("boxing: last frame written to %s\n", o.screenshot.c_str());
  if (!o.report.empty()) std::printf("boxing: report written to %s\n", o.report.c_str());
  if (run->validation_errors > 0) {
    std::fprintf(stderr, "boxing: %d Vulkan validation errors (see above)\n", run->validation_errors);
    return 1;
  }
  return 0;
}

}  // namespace boxing
