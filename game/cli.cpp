#include "game/cli.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <set>
#include <utility>

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

// ---- The value parsers: each reads a flag's value, checks it against the allowed range or set and stores it in
// Options. They get the flag as written (an error names it) and its value; a switch gets an empty value.

using Check = std::optional<eng::Error>;  // nullopt: the value is good and stored
using Reader = std::function<Check(const std::string& flag, const std::string& value, Options& o)>;

eng::Error must_be(const std::string& flag, const std::string& what, const std::string& value) {
  return bad(flag + " must be " + what + ", got '" + value + "'");
}
eng::Error missing(const std::string& flag) { return bad("flag " + flag + " needs a value"); }

// A switch: sets `member` to `to`.
Reader set_to(bool Options::*member, bool to) {
  return [=](const std::string&, const std::string&, Options& o) -> Check {
    o.*member = to;
    return std::nullopt;
  };
}

// An integer from lo to hi; `what` is the range in the error's words.
Reader integer(int Options::*member, long long lo, long long hi, const char* what) {
  return [=](const std::string& flag, const std::string& v, Options& o) -> Check {
    long long n;
    if (!parse_int(v, lo, hi, n)) return must_be(flag, what, v);
    o.*member = int(n);
    return std::nullopt;
  };
}

// A finite number from lo to hi; `what` is the range in the error's words.
Reader number(double Options::*member, double lo, double hi, const char* what) {
  return [=](const std::string& flag, const std::string& v, Options& o) -> Check {
    double x;
    if (!parse_double(v, lo, hi, x)) return must_be(flag, what, v);
    o.*member = x;
    return std::nullopt;
  };
}

// One of a few words, each standing for a value; the error lists them ("a, b or c").
template <class T>
Reader choice(T Options::*member, std::vector<std::pair<std::string, T>> words) {
  return [=](const std::string& flag, const std::string& v, Options& o) -> Check {
    std::string list;
    for (size_t k = 0; k < words.size(); ++k) {
      if (v == words[k].first) {
        o.*member = words[k].second;
        return std::nullopt;
      }
      list += (k == 0 ? "" : k + 1 == words.size() ? " or " : ", ") + words[k].first;
    }
    return must_be(flag, list, v);
  };
}

// One of a few words, stored as given.
Reader word(std::string Options::*member, std::initializer_list<std::string> words) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const std::string& w : words) pairs.emplace_back(w, w);
  return choice(member, std::move(pairs));
}

// A name from a set; a name outside it is "unknown NOUN 'value'" followed by `listed`.
Reader one_of(std::string Options::*member, std::set<std::string> names, std::string noun, std::string listed = "") {
  return [=](const std::string&, const std::string& v, Options& o) -> Check {
    if (!names.count(v)) return bad("unknown " + noun + " '" + v + "'" + listed);
    o.*member = v;
    return std::nullopt;
  };
}

// A file or folder name (not empty).
Reader path(std::string Options::*member) {
  return [=](const std::string& flag, const std::string& v, Options& o) -> Check {
    if (v.empty()) return missing(flag);
    o.*member = v;
    return std::nullopt;
  };
}

// --input / --record: a JSON file's name.
Reader json_file(std::string Options::*member) {
  return [=](const std::string& flag, const std::string& v, Options& o) -> Check {
    if (v.empty()) return bad(flag + " needs a file name (FILE.json)");
    o.*member = v;
    return std::nullopt;
  };
}

Check read_screenshot(const std::string& flag, const std::string& v, Options& o) {
  if (v.empty()) return missing(flag);
  if (v.size() < 4 || v.substr(v.size() - 4) != ".png") return bad("--screenshot needs a .png file name, got '" + v + "'");
  o.screenshot = v;
  return std::nullopt;
}

Check read_audio_out(const std::string& flag, const std::string& v, Options& o) {
  if (v.empty()) return missing(flag);
  if (v.size() < 4 || v.substr(v.size() - 4) != ".wav") return bad("--audio-out needs a .wav file name, got '" + v + "'");
  o.audio_out = v;
  return std::nullopt;
}

Check read_seed(const std::string&, const std::string& v, Options& o) {
  if (!parse_u64(v, o.seed)) return bad("--seed must be a non-negative integer, got '" + v + "'");
  return std::nullopt;
}

Check read_scenario(const std::string&, const std::string& v, Options& o) {
  const std::optional<Scenario> s = scenario_from_name(v);
  if (!s) return bad("unknown scenario '" + v + "'");
  o.scenario_id = *s;
  o.scenario = v;
  o.scenario_given = true;
  return std::nullopt;
}

// --ai LEVEL or LEVEL,LEVEL: one level for both boxers, or red's and blue's.
Check read_ai(const std::string&, const std::string& v, Options& o) {
  const size_t comma = v.find(',');
  const std::string red = v.substr(0, comma), blue = comma == std::string::npos ? red : v.substr(comma + 1);
  const std::string levels[2] = {red, blue};
  for (const std::string& l : levels)
    if (l != "easy" && l != "normal" && l != "hard")
      return bad("--ai takes easy, normal or hard, or two of them for red and blue (e.g. easy,hard), got '" + v + "'");
  o.ai = {levels[0], levels[1]};
  return std::nullopt;
}

Check read_render_scale(const std::string&, const std::string& v, Options& o) {
  double x = 0.0;
  if (v != "auto" && !parse_double(v, 0.25, 1.0, x))
    return bad("--render-scale must be auto or a number from 0.25 to 1, got '" + v + "'");
  o.render_scale = x;
  return std::nullopt;
}

Check read_debug(const std::string&, const std::string& v, Options& o) {
  std::string rest = v + ",";
  for (size_t at = 0, comma; (comma = rest.find(',', at)) != std::string::npos; at = comma + 1) {
    const std::string item = rest.substr(at, comma - at);
    if (item != "contacts" && item != "com" && item != "support" && item != "capture" && item != "hits" &&
        item != "none")
      return bad("--debug takes a comma-separated list of contacts, com, support, capture, hits (or none), got '" +
                 item + "'");
  }
  o.debug_draw = v;
  return std::nullopt;
}

// ---- The flags. --help lists them in this order, each under its subcommand's heading.

struct Flag {
  std::vector<std::string> names;  // the flag and its aliases (--help shows the first)
  const char* value;               // the value's placeholder in --help; nullptr: a switch, which takes no value
  Reader read;                     // reads, checks and stores the value
  const char* help;                // --help's explanation; a '\n' continues it on the next line
  std::string command = "";        // the subcommand it belongs to ("graph", "clips"); empty: any
};

const std::vector<Flag> kFlags = {
    {{"--help", "-h"}, nullptr, set_to(&Options::help, true), "this text"},
    {{"--headless"}, nullptr,
     [](const std::string&, const std::string&, Options& o) -> Check {
       o.headless = o.headless_forced = true;
       return std::nullopt;
     },
     "render offscreen (lavapipe or a GPU), no window"},
    {{"--width"}, "N", integer(&Options::width, 16, 16384, "an integer from 16 to 16384"),
     "frame width in pixels (default 1280)"},
    {{"--height"}, "N", integer(&Options::height, 16, 16384, "an integer from 16 to 16384"),
     "frame height in pixels (default 720)"},
    {{"--seconds"}, "S", number(&Options::seconds, 0.0, 86400.0, "a number from 0 to 86400"),
     "simulated seconds to run, then exit (headless default 2)"},
    {{"--seed"}, "N", read_seed, "arena layout and all randomness (default 1)"},
    {{"--scenario"}, "NAME", read_scenario,
     "arena | ragdolls | stand | push | graph-walk | match | impacts (default arena)"},
    {{"--mode"}, "MODE", word(&Options::mode, {"watch", "play", "versus", "sandbox"}),
     "start a mode without the title screen: watch (AI vs AI), play (you are red, vs the AI),\n"
     "versus (two players), sandbox (the hands-on lab); headless runs it too"},
    {{"--camera"}, "NAME", one_of(&Options::camera, {"default", "closeup", "side", "top"}, "camera"),
     "default | closeup | side | top"},
    {{"--screenshot"}, "FILE.png", read_screenshot, "write the last frame"},
    {{"--report"}, "FILE.json", path(&Options::report),
     "write what ran: seed, seconds, frames, device, frame times, scenario results"},
    {{"--audio-out"}, "FILE.wav", read_audio_out,
     "write the game's sound (16-bit stereo 48 kHz, simulation time), headless too"},
    {{"--content"}, "DIR", path(&Options::content_dir), "the content folder (default: the repository's content/)"},
    {{"--frames-dir"}, "DIR", path(&Options::frames_dir), "headless: write each rendered frame as DIR/frame_NNNNN.png"},
    {{"--render-every"}, "N", integer(&Options::render_every, 0, 1000000, "a non-negative integer"),
     "headless: render every Nth 60 Hz frame (default 0 = the last frame only)"},
    {{"--frames-from"}, "S", number(&Options::frames_from, 0.0, 86400.0, "a number from 0 to 86400"),
     "headless: --render-every starts at S seconds of simulation (default 0)"},
    {{"--overlay"}, nullptr,
     [](const std::string&, const std::string&, Options& o) -> Check {
       o.overlay = o.overlay_given = true;
       return std::nullopt;
     },
     "Dear ImGui overlay (window default on, headless default off)"},
    {{"--no-overlay"}, nullptr,
     [](const std::string&, const std::string&, Options& o) -> Check {
       o.overlay = false;
       o.overlay_given = true;
       return std::nullopt;
     },
     "no overlay, in the window too"},
    {{"--ghost"}, nullptr, set_to(&Options::ghost, true), "draw the desired pose as a translucent ghost"},
    {{"--no-validation"}, nullptr, set_to(&Options::validation, false),
     "skip the Vulkan validation layer (default: on, every error is counted)"},
    {{"--no-vsync"}, nullptr, set_to(&Options::vsync, false), "window: present without vsync"},
    {{"--render-scale"}, "S|auto", read_render_scale,
     "the 3D scene's resolution per axis, 0.25-1, upscaled under the HUD (default auto: on a CPU\n"
     "rasteriser such as lavapipe the scene keeps to 0.52 Mpx, 0.75 at 1280x720; native on a GPU)"},
    {{"--present"}, "MODE", word(&Options::present, {"auto", "swapchain", "shm"}),
     "window: auto | swapchain | shm (default auto: a CPU rasteriser shows frames through X11 shared\n"
     "memory, lavapipe's own path copies each through the X socket on servers without DRI3)"},
    {{"--servo"}, "MODE",
     one_of(&Options::servo, {"world", "person", "parent", "parent-meathook"}, "servo",
            " (world, person, parent, parent-meathook)"),
     "world | person | parent | parent-meathook (boxer scenarios)"},
    {{"--push-dir"}, "DEG", number(&Options::push_dir_deg, -3600.0, 1e6, "a number from -3600 to 1e6 (degrees)"),
     "push scenario: direction in boxer 0's heading frame (0 = toward where it faces)"},
    {{"--push-force"}, "N", number(&Options::push_force, 0.0, 1e6, "a number from 0 to 1e6"),
     "push scenario: force in newtons"},
    {{"--push-duration"}, "S", number(&Options::push_duration, 0.0, 1e6, "a number from 0 to 1e6"),
     "push scenario: duration (default 0.1)"},
    {{"--push-at"}, "S", number(&Options::push_at, 0.0, 1e6, "a number from 0 to 1e6"),
     "push scenario: start time (default 2)"},
    {{"--push-shape"}, "pulse|sine", choice<bool>(&Options::push_sine, {{"pulse", false}, {"sine", true}}),
     "push scenario: constant force (default), or FORCE * sin(2 pi (t - start)) (Kudoh's sine)"},
    {{"--round-seconds"}, "S", number(&Options::round_seconds, 1.0, 86400.0, "a number from 1 to 86400"),
     "match: a round's length (default 180)"},
    {{"--rounds"}, "N", integer(&Options::rounds, 1, 15, "an integer from 1 to 15"),
     "match: the bout's rounds, a minute's rest between them (default 3)"},
    {{"--rest-seconds"}, "S", number(&Options::rest_seconds, 1.0, 600.0, "a number from 1 to 600"),
     "match: the rest between rounds (default 60)"},
    {{"--ai"}, "LEVEL[,LEVEL]", read_ai,
     "match: the AI's level, easy | normal | hard, for both boxers or red's,blue's (default normal)"},
    {{"--start-apart"}, "M", number(&Options::start_apart, 0.8, 3.6, "a number from 0.8 to 3.6"),
     "match: the marks' distance, pelvis to pelvis (default 2.8; less starts the fight at range)"},
    {{"--player"}, "0|1", choice<int>(&Options::player, {{"0", 0}, {"1", 1}}),
     "match: the keyboard steers that boxer, the AI the other (default: both AI)"},
    {{"--input"}, "FILE.json", json_file(&Options::input),
     "play timed input events: drags, throws, pushes, fight keys, settings (README: Scripted input)"},
    {{"--record"}, "FILE.json", json_file(&Options::record),
     "write every input event of the run (the window's mouse and keys) in --input's form"},
    {{"--debug"}, "LIST", read_debug,
     "debug drawing: contacts,com,support,capture,hits (comma-separated; window keys 1-5)"},
    {{"--chaos"}, "RATE", number(&Options::chaos, 0.0, 100.0, "a rate in events per second from 0 to 100"),
     "random drags, pushes and throws at RATE per second (seeded; the report's health block)"},
    {{"--slow"}, "1|2|4|10", choice<int>(&Options::slow, {{"1", 1}, {"2", 2}, {"4", 4}, {"10", 10}}),
     "window: start in slow motion (1/2, 1/4, 1/10; keys [ and ])"},
    {{"--clip"}, "NAME", path(&Options::drill_clip),
     "stand / push: guard, and the clip NAME played once every 3 s (a drill of one clip)"},
    {{"--servo-wn"}, "W", number(&Options::servo_omega_n, 0.0, 1e4, "a non-negative number"),
     "servo natural frequency omega_n, rad/s (default 15)"},
    {{"--servo-zeta"}, "Z", number(&Options::servo_zeta, 0.0, 1e4, "a non-negative number"),
     "servo damping ratio (default 1)"},
    {{"--balance"}, "qp|pd", word(&Options::balance, {"qp", "pd"}),
     "qp: the balance QP computes the joint torques (centre of pressure in the feet);\n"
     "pd: implicit world-space springs plus a PD shift of the desired root (default qp)"},
    {{"--root-spring"}, "on|off|auto", word(&Options::root_spring, {"on", "off", "auto"}),
     "the paper's torque-limited root spring. With --balance qp: a torque on the pelvis the\n"
     "QP plans (the root assist); with pd: a spring on the pelvis tilt. auto (default): on for\n"
     "graph-walk and match (the paper's boxers), off for stand / push (the balance lab)"},
    {{"--root-spring-max"}, "NM", number(&Options::root_spring_max, 0.0, 1e4, "a non-negative number (N m)"),
     "its torque limit in N m (default 400 with qp, 120 with pd)"},
    {{"--stepping"}, "on|off|auto", word(&Options::stepping, {"on", "off", "auto"}),
     "balance QP: steps when a push carries the capture point out of the feet (off: in place);\n"
     "auto (default): on for push (the lab), match and graph-walk, off elsewhere"},
    {{"--getup"}, "assisted|unassisted", word(&Options::getup, {"assisted", "unassisted"}),
     "how a floored boxer gets up: assisted (default), carried by a force under the pelvis;\n"
     "unassisted, on its own strength (balance QP on hands, knees and feet; no force)"},
    {{"--step-placement"}, "capture|ipc", word(&Options::step_placement, {"capture", "ipc"}),
     "where a balance step lands: past the capture point (default) or where Kwon & Hodgins'\n"
     "cart-pole LQR comes to rest"},
    {{"--footwork"}, "shuffle|carry", word(&Options::footwork, {"shuffle", "carry"}),
     "balance QP: the clips' steps are carried to where the clip puts the foot (default: the\n"
     "boxers really move), or shuffle, the sole pressed along its crate (the feet barely move)"},
    {{"--flat"}, nullptr, set_to(&Options::flat, true),
     "a level platform (every crate 0.30 m) instead of the uneven crates"},
    {{"--priorities"}, "kudoh|off|auto", word(&Options::priorities, {"kudoh", "off", "auto"}),
     "balance QP: Kudoh's priorities in guard (the trunk's posture over the com's place, the\n"
     "arms brought back after they swing); auto (default): the match's, off elsewhere"},
    {{"--stance-drop"}, "M", number(&Options::stance_drop, 0.0, 0.2, "a depth in metres (0 to 0.2)"),
     "the desired root M metres below the clip's (knees bent deeper; default 0.04)"},
    {{"--contact-gap"}, "M", number(&Options::contact_gap, 0.0, 0.1, "a gap in metres (0 to 0.1)"),
     "one foot-contact gap for every purpose (experiment; default: 2 cm support, 2 mm load,\n"
     "5 mm fallen, docs/decisions/foot-contact-thresholds.md)"},
    {{"--report"}, "FILE.json", path(&Options::graph_report), "graph figures", "graph"},
    {{"--dot"}, "FILE.dot", path(&Options::graph_dot), "the graph for Graphviz", "graph"},
    {{"--sheet"}, "DIR", path(&Options::sheet_dir), "the folder for the contact sheets (PNG)", "clips"},
};

// The entry for `flag` under `command`: the subcommand's own (graph's --report) before one for any subcommand,
// that before one of another subcommand (parse_cli then says where the flag belongs).
const Flag* find_flag(const std::string& flag, const std::string& command) {
  const Flag* found = nullptr;
  for (const Flag& f : kFlags) {
    if (std::find(f.names.begin(), f.names.end(), flag) == f.names.end()) continue;
    if (f.command == command) return &f;
    if (!found || f.command.empty()) found = &f;
  }
  return found;
}

// One --help line (and its continuations): "  --flag VALUE" padded to the explanation's column, or on its own line
// when longer.
void append_help(std::string& out, const Flag& f) {
  constexpr size_t kColumn = 25;
  std::string head = "  " + f.names[0] + (f.value ? std::string(" ") + f.value : "");
  if (head.size() < kColumn) head.resize(kColumn, ' ');
  else head += "\n" + std::string(kColumn, ' ');
  out += head;
  for (const char* c = f.help; *c; ++c) {
    out += *c;
    if (*c == '\n') out += std::string(kColumn, ' ');
  }
  out += "\n";
}

}  // namespace

std::string help_text() {
  std::string out = R"(boxing - physics-driven boxing prototype

usage: boxing [flags]            play (window; headless when there is no display)
       boxing graph [flags]      build the motion graph and write its report
       boxing clips --sheet DIR  render a contact sheet (PNG) of every clip into DIR

)";
  for (const char* command : {"", "graph", "clips"}) {
    out += *command ? std::string(command) + " flags:\n" : "flags:\n";
    for (const Flag& f : kFlags)
      if (f.command == command) append_help(out, f);
  }
  out += R"(
window controls: title: arrows / Enter / mouse; Esc pause menu (resume, restart, quit to title);
                 Tab the physics panel, H the debug overlay, F12 screenshot (to out/), G ghost,
                 C cycle camera, right mouse drag orbit, wheel zoom
)";
  return out;
}

eng::Result<Options> parse_cli(const std::vector<std::string>& args) {
  Options o;
  size_t i = 0;
  if (!args.empty() && (args[0] == "graph" || args[0] == "clips")) {
    o.command = args[0];
    i = 1;
  }
  for (; i < args.size(); ++i) {
    // "--flag=value" or "--flag value" (a switch takes none).
    const std::string& a = args[i];
    std::string flag = a;
    std::optional<std::string> value;
    if (auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
      flag = a.substr(0, eq);
      value = a.substr(eq + 1);
    }
    const Flag* f = find_flag(flag, o.command);
    if (!f) return bad("unknown flag '" + a + "'");
    if (!f->value) {
      if (value) return bad("flag " + flag + " takes no value");
    } else if (!value) {
      if (i + 1 >= args.size()) return missing(flag);
      value = args[++i];
    }
    if (Check e = f->read(flag, value.value_or(""), o)) return *e;
    if (!f->command.empty() && f->command != o.command) return bad(flag + " belongs to 'boxing " + f->command + "'");
  }
  if (o.command == "clips" && o.sheet_dir.empty() && !o.help) return bad("'boxing clips' needs --sheet DIR");
  if (!o.mode.empty() && o.scenario_given)
    return bad("--mode and --scenario both choose what runs: give one (--mode " + o.mode + " runs the " +
               (o.mode == "sandbox" ? "stand" : "match") + " scenario)");
  return o;
}

}  // namespace boxing
