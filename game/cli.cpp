#include "game/cli.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <set>

namespace boxing {
namespace {

eng::Error bad(const std::string& msg) { return eng::make_error("boxing: " + msg + " (see --help)"); }

bool parse_int(const std::string& s, long long lo, long long hi, long long& out) {
  const char* b = s.data();
  const char* e = b + s.size();
  auto [p, ec] = std::from_chars(b, e, out);
  return ec == std::errc() && p == e && out >= lo && out <= hi;
}

bool parse_u64(const std::string& s, uint64_t& out) {
  const char* b = s.data();
  const char* e = b + s.size();
  auto [p, ec] = std::from_chars(b, e, out);
  return ec == std::errc() && p == e && !s.empty();
}

bool parse_double(const std::string& s, double lo, double hi, double& out) {
  if (s.empty()) return false;
  size_t used = 0;
  try {
    out = std::stod(s, &used);
  } catch (...) {
    return false;
  }
  return used == s.size() && std::isfinite(out) && out >= lo && out <= hi;
}

const std::set<std::string> kCameras = {"default", "closeup", "side", "top"};
const std::set<std::string> kServos = {"world", "person", "parent", "parent-meathook"};

}  // namespace

std::string help_text() {
  return R"(boxing - physics-driven boxing prototype

usage: boxing [flags]            play (window; headless when there is no display)
       boxing graph [flags]      build the motion graph and write its report
       boxing clips --sheet DIR  render a contact sheet (PNG) of every clip into DIR

flags:
  --help                 this text
  --headless             render offscreen (lavapipe or a GPU), no window
  --width N, --height N  frame size in pixels (default 1280x720)
  --seconds S            simulated seconds to run, then exit (headless default 2)
  --seed N               arena layout and all randomness (default 1)
  --scenario NAME        arena | ragdolls | stand | push | graph-walk | match | impacts (default arena)
  --camera NAME          default | closeup | side | top
  --screenshot FILE.png  write the last frame
  --report FILE.json     write what ran: seed, seconds, frames, device, frame times, scenario results
  --content DIR          the content folder (default: the repository's content/)
  --frames-dir DIR       headless: write each rendered frame as DIR/frame_NNNNN.png
  --render-every N       headless: render every Nth 60 Hz frame (default 0 = the last frame only)
  --overlay, --no-overlay   Dear ImGui overlay (window default on, headless default off)
  --ghost                draw the desired pose as a translucent ghost
  --no-validation        skip the Vulkan validation layer (default: on, every error is counted)
  --no-vsync             window: present without vsync
  --render-scale S|auto  the 3D scene's resolution per axis, 0.25-1, upscaled under the HUD (default auto: on a CPU
                         rasteriser such as lavapipe the scene keeps to 0.52 Mpx, 0.75 at 1280x720; native on a GPU)
  --present MODE         window: auto | swapchain | shm (default auto: a CPU rasteriser shows frames through X11 shared
                         memory, lavapipe's own path copies each through the X socket on servers without DRI3)
  --servo MODE           world | person | parent | parent-meathook (boxer scenarios)
  --push-dir DEG         push scenario: direction in boxer 0's heading frame (0 = toward where it faces)
  --push-force N         push scenario: force in newtons
  --push-duration S      push scenario: duration (default 0.1)
  --push-at S            push scenario: start time (default 2)
  --push-shape pulse|sine push scenario: constant force (default), or FORCE * sin(2 pi (t - start)) (Kudoh's sine)
  --round-seconds S      match: a round's length (default 180)
  --player 0|1           match: the keyboard steers that boxer, the AI the other (default: both AI)
  --input FILE.json      play timed input events: drags, throws, pushes, fight keys, settings (README: Scripted input)
  --record FILE.json     write every input event of the run (the window's mouse and keys) in --input's form
  --debug LIST           debug drawing: contacts,com,support,capture,hits (comma-separated; window keys 1-5)
  --chaos RATE           random drags, pushes and throws at RATE per second (seeded; the report's health block)
  --slow 1|2|4|10        window: start in slow motion (1/2, 1/4, 1/10; keys [ and ])
  --clip NAME            stand / push: guard, and the clip NAME played once every 3 s (a drill of one clip)
  --servo-wn W           servo natural frequency omega_n, rad/s (default 15)
  --servo-zeta Z         servo damping ratio (default 1)
  --balance qp|pd        qp: the balance QP computes the joint torques (centre of pressure in the feet);
                         pd: implicit world-space springs plus a PD shift of the desired root (default qp)
  --root-spring on|off|auto
                         the paper's torque-limited root spring. With --balance qp: a torque on the pelvis the
                         QP plans (the root assist); with pd: a spring on the pelvis tilt. auto (default): on for
                         graph-walk and match (the paper's boxers), off for stand / push (the balance lab)
  --root-spring-max NM   its torque limit in N m (default 400 with qp, 120 with pd)
  --stepping on|off|auto balance QP: steps when a push carries the capture point out of the feet (off: in place);
                         auto (default): on for push (the lab), match and graph-walk, off elsewhere
  --step-placement capture|ipc
                         where a balance step lands: past the capture point (default) or where Kwon & Hodgins'
                         cart-pole LQR comes to rest
  --footwork shuffle|carry
                         balance QP: the clips' steps are carried to where the clip puts the foot (default: the
                         boxers really move), or shuffle, the sole pressed along its crate (the feet barely move)
  --flat                 a level platform (every crate 0.30 m) instead of the uneven crates
  --priorities kudoh|off|auto
                         balance QP: Kudoh's priorities in guard (the trunk's posture over the com's place, the
                         arms brought back after they swing); auto (default): the match's, off elsewhere
  --stance-drop M        the desired root M metres below the clip's (knees bent deeper; default 0.04)
  --contact-gap M        one foot-contact gap for every purpose (experiment; default: 2 cm support, 2 mm load,
                         5 mm fallen, docs/decisions/foot-contact-thresholds.md)
graph flags:
  --report FILE.json     graph figures
  --dot FILE.dot         the graph for Graphviz

window controls: F12 screenshot (to out/), H toggle overlay, G toggle ghost, C cycle camera,
                 right mouse drag orbit, wheel zoom, Esc quit
)";
}

eng::Result<Options> parse_cli(const std::vector<std::string>& args) {
  Options o;
  size_t i = 0;
  if (!args.empty() && (args[0] == "graph" || args[0] == "clips")) {
    o.command = args[0];
    i = 1;
  }
  auto need_value = [&](const std::string& flag) -> std::optional<std::string> {
    if (i + 1 >= args.size()) return std::nullopt;
    return args[++i];
  };
  for (; i < args.size(); ++i) {
    const std::string& a = args[i];
    std::string flag = a, inline_value;
    bool has_inline = false;
    if (auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
      flag = a.substr(0, eq);
      inline_value = a.substr(eq + 1);
      has_inline = true;
    }
    auto value = [&]() -> std::optional<std::string> {
      if (has_inline) return inline_value;
      return need_value(flag);
    };
    auto missing = [&]() { return bad("flag " + flag + " needs a value"); };
    // A flag whose value is one of a few words: stored in `into`, or the error naming them ("a, b or c").
    auto choice = [&](std::initializer_list<const char*> allowed, std::string& into) -> std::optional<eng::Error> {
      auto v = value();
      if (!v) return missing();
      std::string words;
      size_t k = 0;
      for (const char* word : allowed) {
        if (*v == word) {
          into = *v;
          return std::nullopt;
        }
        words += (k == 0 ? "" : k + 1 == allowed.size() ? " or " : ", ") + std::string(word);
        ++k;
      }
      return bad(flag + " must be " + words + ", got '" + *v + "'");
    };

    if (flag == "--help" || flag == "-h") {
      o.help = true;
    } else if (flag == "--headless") {
      o.headless = o.headless_forced = true;
    } else if (flag == "--width" || flag == "--height") {
      auto v = value();
      if (!v) return missing();
      long long n;
      if (!parse_int(*v, 16, 16384, n)) return bad(flag + " must be an integer from 16 to 16384, got '" + *v + "'");
      (flag == "--width" ? o.width : o.height) = int(n);
    } else if (flag == "--seconds") {
      auto v = value();
      if (!v) return missing();
      if (!parse_double(*v, 0.0, 86400.0, o.seconds))
        return bad("--seconds must be a number from 0 to 86400, got '" + *v + "'");
    } else if (flag == "--seed") {
      auto v = value();
      if (!v) return missing();
      if (!parse_u64(*v, o.seed)) return bad("--seed must be a non-negative integer, got '" + *v + "'");
    } else if (flag == "--scenario") {
      auto v = value();
      if (!v) return missing();
      const std::optional<Scenario> s = scenario_from_name(*v);
      if (!s) return bad("unknown scenario '" + *v + "'");
      o.scenario_id = *s;
      o.scenario = *v;
    } else if (flag == "--clip") {
      auto v = value();
      if (!v || v->empty()) return missing();
      o.drill_clip = *v;
    } else if (flag == "--camera") {
      auto v = value();
      if (!v) return missing();
      if (!kCameras.count(*v)) return bad("unknown camera '" + *v + "'");
      o.camera = *v;
    } else if (flag == "--servo") {
      auto v = value();
      if (!v) return missing();
      if (!kServos.count(*v)) return bad("unknown servo '" + *v + "' (world, person, parent, parent-meathook)");
      o.servo = *v;
    } else if (flag == "--screenshot" || flag == "--report" || flag == "--frames-dir" || flag == "--dot" ||
               flag == "--content" || flag == "--sheet") {
      auto v = value();
      if (!v || v->empty()) return missing();
      if (flag == "--screenshot") {
        if (v->size() < 4 || v->substr(v->size() - 4) != ".png")
          return bad("--screenshot needs a .png file name, got '" + *v + "'");
        o.screenshot = *v;
      } else if (flag == "--report") {
        (o.command == "graph" ? o.graph_report : o.report) = *v;
      } else if (flag == "--dot") {
        if (o.command != "graph") return bad("--dot belongs to 'boxing graph'");
        o.graph_dot = *v;
      } else if (flag == "--sheet") {
        if (o.command != "clips") return bad("--sheet belongs to 'boxing clips'");
        o.sheet_dir = *v;
      } else if (flag == "--content") {
        o.content_dir = *v;
      } else {
        o.frames_dir = *v;
      }
    } else if (flag == "--round-seconds") {
      auto v = value();
      if (!v) return missing();
      if (!parse_double(*v, 1.0, 86400.0, o.round_seconds))
        return bad("--round-seconds must be a number from 1 to 86400, got '" + *v + "'");
    } else if (flag == "--player") {
      std::string v;
      if (auto e = choice({"0", "1"}, v)) return *e;
      o.player = v == "0" ? 0 : 1;
    } else if (flag == "--input" || flag == "--record") {
      auto v = value();
      if (!v) return missing();
      if (v->empty()) return bad(flag + " needs a file name (FILE.json)");
      (flag == "--input" ? o.input : o.record) = *v;
    } else if (flag == "--debug") {
      auto v = value();
      if (!v) return missing();
      std::string rest = *v + ",";
      for (size_t at = 0, comma; (comma = rest.find(',', at)) != std::string::npos; at = comma + 1) {
        const std::string item = rest.substr(at, comma - at);
        if (item != "contacts" && item != "com" && item != "support" && item != "capture" && item != "hits" &&
            item != "none")
          return bad("--debug takes a comma-separated list of contacts, com, support, capture, hits (or none), got '" +
                     item + "'");
      }
      o.debug_draw = *v;
    } else if (flag == "--chaos") {
      auto v = value();
      if (!v) return missing();
      if (!parse_double(*v, 0.0, 100.0, o.chaos))
        return bad("--chaos must be a rate in events per second from 0 to 100, got '" + *v + "'");
    } else if (flag == "--slow") {
      std::string v;
      if (auto e = choice({"1", "2", "4", "10"}, v)) return *e;
      o.slow = std::stoi(v);
    } else if (flag == "--render-every") {
      auto v = value();
      if (!v) return missing();
      long long n;
      if (!parse_int(*v, 0, 1000000, n)) return bad("--render-every must be a non-negative integer, got '" + *v + "'");
      o.render_every = int(n);
    } else if (flag == "--push-dir" || flag == "--push-force" || flag == "--push-duration" || flag == "--push-at") {
      auto v = value();
      if (!v) return missing();
      double x;
      double lo = flag == "--push-dir" ? -3600.0 : 0.0;
      if (!parse_double(*v, lo, 1e6, x))
        return bad(flag + (flag == "--push-dir" ? " must be a number from -3600 to 1e6 (degrees)"
                                                : " must be a number from 0 to 1e6") + ", got '" + *v + "'");
      if (flag == "--push-dir") o.push_dir_deg = x;
      else if (flag == "--push-force") o.push_force = x;
      else if (flag == "--push-duration") o.push_duration = x;
      else o.push_at = x;
    } else if (flag == "--push-shape") {
      std::string v;
      if (auto e = choice({"pulse", "sine"}, v)) return *e;
      o.push_sine = v == "sine";
    } else if (flag == "--servo-wn" || flag == "--servo-zeta") {
      auto v = value();
      if (!v) return missing();
      double x;
      if (!parse_double(*v, 0.0, 1e4, x)) return bad(flag + " must be a non-negative number, got '" + *v + "'");
      if (flag == "--servo-wn") o.servo_omega_n = x;
      else o.servo_zeta = x;
    } else if (flag == "--render-scale") {
      auto v = value();
      if (!v) return missing();
      double x = 0.0;
      if (*v != "auto" && !parse_double(*v, 0.25, 1.0, x))
        return bad("--render-scale must be auto or a number from 0.25 to 1, got '" + *v + "'");
      o.render_scale = x;
    } else if (flag == "--present") {
      if (auto e = choice({"auto", "swapchain", "shm"}, o.present)) return *e;
    } else if (flag == "--balance") {
      if (auto e = choice({"qp", "pd"}, o.balance)) return *e;
    } else if (flag == "--root-spring") {
      if (auto e = choice({"on", "off", "auto"}, o.root_spring)) return *e;
    } else if (flag == "--stepping") {
      if (auto e = choice({"on", "off", "auto"}, o.stepping)) return *e;
    } else if (flag == "--step-placement") {
      if (auto e = choice({"capture", "ipc"}, o.step_placement)) return *e;
    } else if (flag == "--footwork") {
      if (auto e = choice({"shuffle", "carry"}, o.footwork)) return *e;
    } else if (flag == "--flat") {
      o.flat = true;
    } else if (flag == "--priorities") {
      if (auto e = choice({"kudoh", "off", "auto"}, o.priorities)) return *e;
    } else if (flag == "--stance-drop") {
      auto v = value();
      if (!v) return missing();
      double x;
      if (!parse_double(*v, 0.0, 0.2, x)) return bad("--stance-drop must be a depth in metres (0 to 0.2), got '" + *v + "'");
      o.stance_drop = x;
    } else if (flag == "--root-spring-max") {
      auto v = value();
      if (!v) return missing();
      double x;
      if (!parse_double(*v, 0.0, 1e4, x)) return bad("--root-spring-max must be a non-negative number (N m), got '" + *v + "'");
      o.root_spring_max = x;
    } else if (flag == "--contact-gap") {
      auto v = value();
      if (!v) return missing();
      double x;
      if (!parse_double(*v, 0.0, 0.1, x)) return bad("--contact-gap must be a gap in metres (0 to 0.1), got '" + *v + "'");
      o.contact_gap = x;
    } else if (flag == "--overlay" || flag == "--no-overlay") {
      o.overlay = flag == "--overlay";
      o.overlay_given = true;
    } else if (flag == "--ghost") {
      o.ghost = true;
    } else if (flag == "--no-validation") {
      o.validation = false;
    } else if (flag == "--no-vsync") {
      o.vsync = false;
    } else {
      return bad("unknown flag '" + a + "'");
    }
    if (has_inline && (flag == "--headless" || flag == "--help" || flag == "--ghost" || flag == "--flat" || flag == "--overlay" ||
                       flag == "--no-overlay" || flag == "--no-validation" || flag == "--no-vsync"))
      return bad("flag " + flag + " takes no value");
  }
  if (o.command == "clips" && o.sheet_dir.empty() && !o.help) return bad("'boxing clips' needs --sheet DIR");
  return o;
}

}  // namespace boxing
