#include "game/front_end.h"

#include <algorithm>

namespace boxing {

namespace {
constexpr std::array<const char*, 4> kModeNames = {"watch", "play", "versus", "sandbox"};
constexpr std::array<const char*, 4> kScreenNames = {"title", "playing", "paused", "result"};
constexpr int kMaxRounds = 15;  // --rounds' range (cli.cpp)
}  // namespace

const char* mode_name(Mode m) { return kModeNames[static_cast<int>(m)]; }
const char* screen_name(Screen s) { return kScreenNames[static_cast<int>(s)]; }

std::optional<Mode> mode_from_name(const std::string& name) {
  for (size_t k = 0; k < kModeNames.size(); ++k)
    if (name == kModeNames[k]) return static_cast<Mode>(k);
  return std::nullopt;
}

FrontEnd front_end_for(const Options& o) {
  FrontEnd fe;
  fe.settings.rounds = o.rounds;
  fe.settings.seed = std::max<uint64_t>(1, o.seed);
  const int level = static_cast<int>(std::find(kAiLevels.begin(), kAiLevels.end(), o.ai[1]) - kAiLevels.begin());
  fe.settings.ai_level = level < static_cast<int>(kAiLevels.size()) ? level : 1;
  if (const std::optional<Mode> m = mode_from_name(o.mode)) fe.settings.mode = *m;
  if (!o.mode.empty() || o.scenario_given) fe.screen = Screen::Playing;
  return fe;
}

void title_step(FrontEnd& fe, TitleItem item, int dir) {
  FrontEndSettings& s = fe.settings;
  const int levels = static_cast<int>(kAiLevels.size());
  if (item == TitleItem::AiLevel) s.ai_level = (s.ai_level + dir + levels) % levels;
  if (item == TitleItem::Rounds) s.rounds = (s.rounds - 1 + dir + kMaxRounds) % kMaxRounds + 1;
  if (item == TitleItem::Seed) s.seed = dir < 0 && s.seed <= 1 ? 1 : s.seed + dir;
}

FrontAction title_choose(FrontEnd& fe, TitleItem item) {
  switch (item) {
    case TitleItem::Watch: fe.settings.mode = Mode::Watch; return FrontAction::Start;
    case TitleItem::Play: fe.settings.mode = Mode::Play; return FrontAction::Start;
    case TitleItem::Versus: fe.settings.mode = Mode::Versus; return FrontAction::Start;
    case TitleItem::Sandbox: fe.settings.mode = Mode::Sandbox; return FrontAction::Start;
    case TitleItem::Quit: return FrontAction::Quit;
    default: title_step(fe, item, +1); return FrontAction::None;
  }
}

FrontAction pause_choose(FrontEnd&, PauseItem item) {
  switch (item) {
    case PauseItem::Resume: return FrontAction::Resume;
    case PauseItem::Restart: return FrontAction::Restart;
    default: return FrontAction::ToTitle;
  }
}

FrontAction front_end_key(FrontEnd& fe, MenuKey k) {
  auto move = [k](int& cursor, int count) {
    if (k == MenuKey::Up) cursor = (cursor + count - 1) % count;
    if (k == MenuKey::Down) cursor = (cursor + 1) % count;
  };
  switch (fe.screen) {
    case Screen::Title: {
      const int rows = static_cast<int>(TitleItem::Count);
      move(fe.title_cursor, rows);
      const TitleItem item = static_cast<TitleItem>(fe.title_cursor);
      if (k == MenuKey::Left || k == MenuKey::Right) title_step(fe, item, k == MenuKey::Left ? -1 : +1);
      if (k == MenuKey::Enter) return title_choose(fe, item);
      if (k == MenuKey::Back) return FrontAction::Quit;
      return FrontAction::None;
    }
    case Screen::Playing:
      if (k == MenuKey::Back) {
        fe.screen = Screen::Paused;
        fe.pause_cursor = 0;
      }
      return FrontAction::None;
    case Screen::Paused:
      move(fe.pause_cursor, static_cast<int>(PauseItem::Count));
      if (k == MenuKey::Enter) return pause_choose(fe, static_cast<PauseItem>(fe.pause_cursor));
      if (k == MenuKey::Back) return FrontAction::Resume;
      return FrontAction::None;
    case Screen::Result:
      return k == MenuKey::Enter || k == MenuKey::Back ? FrontAction::ToTitle : FrontAction::None;
  }
  return FrontAction::None;
}

void front_end_apply(FrontEnd& fe, FrontAction a) {
  if (a == FrontAction::Start || a == FrontAction::Resume || a == FrontAction::Restart) fe.screen = Screen::Playing;
  if (a == FrontAction::ToTitle) fe.screen = Screen::Title;
  if (a == FrontAction::Start || a == FrontAction::Restart || a == FrontAction::ToTitle) fe.result_at = -1.0;
}

void front_end_watch_bout(FrontEnd& fe, bool bout_over, double time_s) {
  if (fe.screen != Screen::Playing || !bout_over) return;
  if (fe.result_at < 0.0) fe.result_at = time_s + kResultDelay;
  if (time_s >= fe.result_at) fe.screen = Screen::Result;
}

Options apply_mode(Options o, Mode m) {
  o.mode = mode_name(m);
  o.scenario_id = m == Mode::Sandbox ? Scenario::Stand : Scenario::Match;
  o.scenario = scenario_name(o.scenario_id);
  o.player = m == Mode::Play || m == Mode::Versus ? 0 : -1;
  return o;
}

Options options_for(const Options& base, const FrontEndSettings& s) {
  Options o = apply_mode(base, s.mode);
  o.seed = s.seed;
  o.rounds = s.rounds;
  o.ai = {kAiLevels[s.ai_level], kAiLevels[s.ai_level]};
  return o;
}

}  // namespace boxing
