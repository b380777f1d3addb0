#include "game/interaction/input_events.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace boxing {

namespace {

constexpr std::pair<InputKind, const char*> kKinds[] = {
    {InputKind::Drag, "drag"},   {InputKind::Grab, "grab"},   {InputKind::Move, "move"},
    {InputKind::Release, "release"}, {InputKind::Throw, "throw"}, {InputKind::Clear, "clear"},
    {InputKind::Push, "push"},   {InputKind::Key, "key"},     {InputKind::Set, "set"},
    {InputKind::Pad, "pad"}};

// Field readers: each returns an error message naming KIND.FIELD, or "" when the field is fine (or absent and
// optional).
struct Fields {
  const nlohmann::json& obj;
  std::string kind;
  std::string err;

  bool has(const char* f) const { return obj.contains(f); }
  void fail(const char* f, const std::string& what) {
    if (err.empty()) err = kind + "." + f + " " + what;
  }
  void number(const char* f, double& out, bool required, double lo = -1e300, double hi = 1e300) {
    if (!has(f)) {
      if (required) fail(f, "is missing (a number)");
      return;
    }
    const auto& v = obj[f];
    if (!v.is_number() || !std::isfinite(v.get<double>())) return fail(f, "must be a finite number");
    const double x = v.get<double>();
    if (x < lo || x > hi) {
      std::ostringstream s;
      s << "must be in [" << lo << ", " << hi << "] (got " << x << ")";
      return fail(f, s.str());
    }
    out = x;
  }
  void integer(const char* f, int& out, bool required, int lo, int hi) {
    if (!has(f)) {
      if (required) fail(f, "is missing (an integer)");
      return;
    }
    const auto& v = obj[f];
    if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
      return fail(f, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    out = v.get<int>();
  }
  void vec3(const char* f, Eigen::Vector3d& out, bool required, double limit) {
    if (!has(f)) {
      if (required) fail(f, "is missing (an array of 3 numbers)");
      return;
    }
    const auto& v = obj[f];
    if (!v.is_array() || v.size() != 3) return fail(f, "must be an array of 3 numbers");
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>()) || std::abs(v[i].get<double>()) > limit)
        return fail(f, "must be an array of 3 finite numbers of magnitude <= " + std::to_string(int(limit)));
      out[i] = v[i].get<double>();
    }
  }
  void text(const char* f, std::string& out, bool required) {
    if (!has(f)) {
      if (required) fail(f, "is missing (a string)");
      return;
    }
    if (!obj[f].is_string() || obj[f].get<std::string>().empty()) return fail(f, "must be a non-empty string");
    out = obj[f].get<std::string>();
  }
  void choice(const char* f, std::optional<std::string>& out, std::initializer_list<const char*> allowed) {
    if (!has(f)) return;
    std::string s, list;
    text(f, s, true);
    for (const char* a : allowed) {
      if (s == a) {
        out = s;
        return;
      }
      list += list.empty() ? a : std::string(" | ") + a;
    }
    fail(f, "must be one of " + list);
  }
  void flag(const char* f, bool& out) {
    if (!has(f)) return;
    if (!obj[f].is_boolean()) return fail(f, "must be true or false");
    out = obj[f].get<bool>();
  }
  void only(std::initializer_list<const char*> known) {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      bool ok = false;
      for (const char* k : known) ok = ok || it.key() == k;
      if (!ok) {
        std::string list;
        for (const char* k : known) list += list.empty() ? k : std::string(", ") + k;
        if (err.empty()) err = kind + "." + it.key() + " is not a field of " + kind + " (fields: " + list + ")";
      }
    }
  }
};

constexpr double kMaxCoord = 1000.0;  // m, m/s, or N: anything larger is a typo, not a game
constexpr int kMaxBoxer = 15;

// A pad event's body: its index, and the state it is in from now on (absent buttons up, absent axes at rest).
void parse_pad(Fields& f, InputEvent& e) {
  f.only({"pad", "connected", "buttons", "axes", "boxer"});
  f.integer("pad", e.pad, true, 0, kMaxPads - 1);
  e.pad_state = PadState{};
  e.pad_state.connected = true;
  f.flag("connected", e.pad_state.connected);
  f.integer("boxer", e.pad_boxer, false, 0, 1);
  if (!f.err.empty()) return;
  if (!e.pad_state.connected && (f.has("buttons") || f.has("axes")))
    return f.fail("connected", "is false: an unplugged pad has no buttons or axes (drop them, or connect it)");
  auto names = [](const char* const* list, int n) {
    std::string s;
    for (int i = 0; i < n; ++i) {
      if (i) s += ' ';
      s += list[i];
    }
    return s;
  };
  if (f.has("buttons")) {
    const auto& b = f.obj["buttons"];
    if (!b.is_object()) return f.fail("buttons", "must be an object of button: true | false");
    for (auto it = b.begin(); it != b.end(); ++it) {
      int k = 0;
      while (k < kPadButtons && it.key() != kPadButtonNames[k]) ++k;
      if (k == kPadButtons)
        return f.fail("buttons", "has '" + it.key() + "', not a button (one of: " +
                                     names(kPadButtonNames, kPadButtons) + ")");
      if (!it->is_boolean()) return void(f.err = "pad.buttons." + it.key() + " must be true or false");
      e.pad_state.buttons[k] = it->get<bool>();
    }
  }
  if (f.has("axes")) {
    const auto& a = f.obj["axes"];
    if (!a.is_object()) return f.fail("axes", "must be an object of axis: number in [-1, 1]");
    for (auto it = a.begin(); it != a.end(); ++it) {
      int k = 0;
      while (k < kPadAxes && it.key() != kPadAxisNames[k]) ++k;
      if (k == kPadAxes)
        return f.fail("axes", "has '" + it.key() + "', not an axis (one of: " + names(kPadAxisNames, kPadAxes) + ")");
      if (!it->is_number() || !std::isfinite(it->get<double>()) || std::abs(it->get<double>()) > 1.0)
        return void(f.err = "pad.axes." + it.key() + " must be a number in [-1, 1] (sticks: up and left negative; "
                                                      "triggers: -1 released, 1 pulled)");
      e.pad_state.axes[k] = static_cast<float>(it->get<double>());
    }
  }
}

}  // namespace

const char* input_kind_name(InputKind k) {
  for (const auto& [kind, name] : kKinds)
    if (kind == k) return name;
  return "?";
}
const char* object_kind_name(ObjectKind k) { return k == ObjectKind::Ball ? "ball" : "crate"; }

eng::Result<InputEvent> parse_input_event(const nlohmann::json& j) {
  if (!j.is_object()) return eng::make_error("must be an object like {\"t\": 2.0, \"drag\": {...}}");
  InputEvent e;
  if (!j.contains("t") || !j["t"].is_number() || !std::isfinite(j["t"].get<double>()) || j["t"].get<double>() < 0)
    return eng::make_error("t must be a time in seconds >= 0");
  e.t = j["t"].get<double>();
  const std::pair<InputKind, const char*>* found = nullptr;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "t") continue;
    const std::pair<InputKind, const char*>* k = nullptr;
    for (const auto& kk : kKinds)
      if (it.key() == kk.second) k = &kk;
    if (!k)
      return eng::make_error("'" + it.key() +
                             "' is not an event (one of: drag grab move release throw clear push key set pad)");
    if (found) return eng::make_error(std::string("has two events ('") + found->second + "' and '" + k->second +
                                      "'): one per entry");
    found = k;
  }
  if (!found) return eng::make_error("has no event (one of: drag grab move release throw clear push key set pad)");
  e.kind = found->first;
  const nlohmann::json& body = j[found->second];
  if (!body.is_object()) return eng::make_error(std::string(found->second) + " must be an object ({} if empty)");
  Fields f{body, found->second, ""};
  switch (e.kind) {
    case InputKind::Drag:
      f.only({"boxer", "bone", "offset", "duration", "strong", "point"});
      f.integer("boxer", e.boxer, true, 0, kMaxBoxer);
      f.text("bone", e.bone, true);
      f.vec3("offset", e.vec, true, 10.0);
      f.number("duration", e.duration, true, 0.0, 3600.0);
      f.flag("strong", e.strong);
      if (f.has("point")) f.vec3("point", e.point.emplace(), true, 2.0);
      break;
    case InputKind::Grab:
      f.only({"boxer", "bone", "object", "point", "strong"});
      if (f.has("object")) {
        f.integer("object", e.object, true, 0, 255);
        if (f.has("boxer") || f.has("bone")) f.fail("object", "and boxer / bone exclude each other");
      } else {
        f.integer("boxer", e.boxer, true, 0, kMaxBoxer);
        f.text("bone", e.bone, true);
      }
      if (f.has("point")) f.vec3("point", e.point.emplace(), true, 2.0);
      f.flag("strong", e.strong);
      break;
    case InputKind::Move:
      f.only({"target"});
      f.vec3("target", e.vec, true, kMaxCoord);
      break;
    case InputKind::Release:
    case InputKind::Clear:
      f.only({});
      break;
    case InputKind::Throw: {
      f.only({"object", "at_boxer", "speed", "from", "velocity"});
      std::optional<std::string> kind;
      if (!f.has("object")) f.fail("object", "is missing (ball | crate)");
      f.choice("object", kind, {"ball", "crate"});
      e.object_kind = kind && *kind == "crate" ? ObjectKind::Crate : ObjectKind::Ball;
      if (f.has("at_boxer")) {
        f.integer("at_boxer", e.at_boxer, true, 0, kMaxBoxer);
        f.number("speed", e.speed, true, 0.1, 40.0);
        if (f.has("from") || f.has("velocity")) f.fail("at_boxer", "and from / velocity exclude each other");
      } else {
        f.vec3("from", e.from, true, kMaxCoord);
        f.vec3("velocity", e.velocity, true, 40.0);
      }
      break;
    }
    case InputKind::Push:
      f.only({"boxer", "bone", "force", "duration"});
      f.integer("boxer", e.boxer, true, 0, kMaxBoxer);
      e.bone = "chest";
      f.text("bone", e.bone, false);
      f.vec3("force", e.vec, true, 20000.0);
      f.number("duration", e.duration, true, 0.0, 60.0);
      break;
    case InputKind::Key:
      f.only({"action", "boxer"});
      f.text("action", e.action, true);
      if (f.err.empty()) {
        bool known = false;
        std::string list;
        for (const char* a : kKeyActions) known = known || e.action == a, list += list.empty() ? a : std::string(" ") + a;
        if (!known) f.fail("action", "'" + e.action + "' is not a fight key (one of: " + list + ")");
      }
      f.integer("boxer", e.boxer, false, 0, kMaxBoxer);
      break;
    case InputKind::Pad: parse_pad(f, e); break;
    case InputKind::Set:
      f.only({"boxer", "servo", "balance", "omega_n", "root_spring", "root_limit", "control", "consciousness"});
      f.integer("boxer", e.boxer, true, 0, kMaxBoxer);
      f.choice("servo", e.servo, {"world", "person", "parent"});
      f.choice("balance", e.balance, {"qp", "pd"});
      f.choice("root_spring", e.root_spring, {"on", "off"});
      f.choice("control", e.control, {"ai", "player"});
      if (f.has("omega_n")) f.number("omega_n", e.omega_n.emplace(), true, 1.0, 60.0);
      if (f.has("root_limit")) f.number("root_limit", e.root_limit.emplace(), true, 0.0, 5000.0);
      if (f.has("consciousness")) f.number("consciousness", e.consciousness.emplace(), true, 0.0, 1.0);
      break;
  }
  if (!f.err.empty()) return eng::make_error(f.err);
  return e;
}

eng::Result<std::vector<InputEvent>> parse_input_events(const nlohmann::json& doc) {
  const nlohmann::json* list = &doc;
  if (doc.is_object()) {
    if (!doc.contains("events")) return eng::make_error("has no \"events\" array (write {\"events\": [...]})");
    list = &doc["events"];
  }
  if (!list->is_array()) return eng::make_error("\"events\" must be an array of events");
  std::vector<InputEvent> out;
  for (size_t i = 0; i < list->size(); ++i) {
    auto e = parse_input_event((*list)[i]);
    if (!e) {
      std::ostringstream s;
      s << "event " << i;
      if ((*list)[i].is_object() && (*list)[i].contains("t") && (*list)[i]["t"].is_number())
        s << " (t = " << (*list)[i]["t"].get<double>() << ")";
      return eng::make_error(s.str() + ": " + e.error());
    }
    out.push_back(std::move(*e));
  }
  for (size_t i = 1; i < out.size(); ++i)
    if (out[i].t < out[i - 1].t)
      return eng::make_error("event " + std::to_string(i) + ": events must be in time order (t = " +
                             std::to_string(out[i].t) + " comes after t = " + std::to_string(out[i - 1].t) + ")");
  return out;
}

eng::Result<std::vector<InputEvent>> load_input_file(const std::string& path) {
  const std::string where = "boxing: input '" + path + "': ";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return eng::make_error(where + "no such file (give --input a JSON file of events; README: Scripted input)");
  std::ifstream in(path);
  nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);
  if (doc.is_discarded())
    return eng::make_error(where + "not valid JSON (check brackets and commas; README: Scripted input)");
  auto events = parse_input_events(doc);
  if (!events) return eng::make_error(where + events.error());
  return events;
}

nlohmann::json input_event_json(const InputEvent& e) {
  auto v3 = [](const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
  nlohmann::json b = nlohmann::json::object();
  switch (e.kind) {
    case InputKind::Drag:
      b = {{"boxer", e.boxer}, {"bone", e.bone}, {"offset", v3(e.vec)}, {"duration", e.duration}, {"strong", e.strong}};
      if (e.point) b["point"] = v3(*e.point);
      break;
    case InputKind::Grab:
      if (e.object >= 0) b["object"] = e.object;
      else b["boxer"] = e.boxer, b["bone"] = e.bone;
      if (e.point) b["point"] = v3(*e.point);
      b["strong"] = e.strong;
      break;
    case InputKind::Move: b = {{"target", v3(e.vec)}}; break;
    case InputKind::Release:
    case InputKind::Clear: break;
    case InputKind::Throw:
      b["object"] = object_kind_name(e.object_kind);
      if (e.at_boxer >= 0) b["at_boxer"] = e.at_boxer, b["speed"] = e.speed;
      else b["from"] = v3(e.from), b["velocity"] = v3(e.velocity);
      break;
    case InputKind::Push:
      b = {{"boxer", e.boxer}, {"bone", e.bone.empty() ? "chest" : e.bone}, {"force", v3(e.vec)}, {"duration", e.duration}};
      break;
    case InputKind::Key: b = {{"action", e.action}, {"boxer", e.boxer}}; break;
    case InputKind::Pad:
      b["pad"] = e.pad;
      if (!e.pad_state.connected) b["connected"] = false;
      if (e.pad_boxer >= 0) b["boxer"] = e.pad_boxer;
      for (int k = 0; k < kPadButtons && e.pad_state.connected; ++k)
        if (e.pad_state.buttons[k]) b["buttons"][kPadButtonNames[k]] = true;
      for (int k = 0; k < kPadAxes && e.pad_state.connected; ++k)
        if (e.pad_state.axes[k] != pad_axis_rest(k)) b["axes"][kPadAxisNames[k]] = double(e.pad_state.axes[k]);
      break;
    case InputKind::Set:
      b["boxer"] = e.boxer;
      if (e.servo) b["servo"] = *e.servo;
      if (e.balance) b["balance"] = *e.balance;
      if (e.root_spring) b["root_spring"] = *e.root_spring;
      if (e.control) b["control"] = *e.control;
      if (e.omega_n) b["omega_n"] = *e.omega_n;
      if (e.root_limit) b["root_limit"] = *e.root_limit;
      if (e.consciousness) b["consciousness"] = *e.consciousness;
      break;
  }
  return {{"t", e.t}, {input_kind_name(e.kind), b}};
}

eng::Result<void> write_input_file(const std::string& path, const std::vector<InputEvent>& events) {
  nlohmann::json list = nlohmann::json::array();
  for (const InputEvent& e : events) list.push_back(input_event_json(e));
  if (auto parent = std::filesystem::path(path).parent_path(); !parent.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
  }
  std::ofstream f(path);
  if (!f) return eng::make_error("boxing: cannot write the recording '" + path + "' (check the folder is writable)");
  f << nlohmann::json{{"events", list}}.dump(1) << "\n";
  if (!f) return eng::make_error("boxing: writing the recording '" + path + "' failed");
  return {};
}

}  // namespace boxing
