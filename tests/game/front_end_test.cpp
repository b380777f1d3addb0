// The front end's state machine (game/front_end.h) without a window: the screens a key or a choice leads to, the
// title's options, the modes' options, and the result screen opening after the bout's end; the AI levels'
// tuning (fighter_ai.h apply_ai_level): normal leaves it as it is.
#include <gtest/gtest.h>

#include "game/cli.h"
#include "game/front_end.h"
#include "game/match/fighter_ai.h"

namespace boxing {
namespace {

TEST(FrontEnd, TheWindowOpensTheTitleUnlessAModeOrAScenarioIsGiven) {
  EXPECT_EQ(front_end_for(*parse_cli({})).screen, Screen::Title);
  EXPECT_EQ(front_end_for(*parse_cli({"--mode", "watch"})).screen, Screen::Playing);
  EXPECT_EQ(front_end_for(*parse_cli({"--scenario", "match"})).screen, Screen::Playing);  // the lab's old way
  const FrontEnd fe = front_end_for(*parse_cli({"--seed", "9", "--rounds", "5", "--ai", "hard"}));
  EXPECT_EQ(fe.settings.seed, 9u);
  EXPECT_EQ(fe.settings.rounds, 5);
  EXPECT_EQ(kAiLevels[fe.settings.ai_level], std::string("hard"));
  EXPECT_EQ(fe.settings.mode, Mode::Play);
  EXPECT_EQ(fe.title_cursor, static_cast<int>(TitleItem::Play));  // Enter plays
}

TEST(FrontEnd, TitleArrowsMoveAndWrapChangeTheOptionsAndEnterStartsTheMode) {
  FrontEnd fe;
  EXPECT_EQ(front_end_key(fe, MenuKey::Up), FrontAction::None);
  EXPECT_EQ(fe.title_cursor, static_cast<int>(TitleItem::Watch));
  EXPECT_EQ(front_end_key(fe, MenuKey::Up), FrontAction::None);  // wraps to the bottom row
  EXPECT_EQ(fe.title_cursor, static_cast<int>(TitleItem::Quit));
  fe.title_cursor = static_cast<int>(TitleItem::AiLevel);
  front_end_key(fe, MenuKey::Left);
  EXPECT_EQ(fe.settings.ai_level, 0);  // easy
  front_end_key(fe, MenuKey::Left);
  EXPECT_EQ(fe.settings.ai_level, 2);  // wraps to hard
  fe.title_cursor = static_cast<int>(TitleItem::Rounds);
  front_end_key(fe, MenuKey::Left), front_end_key(fe, MenuKey::Left), front_end_key(fe, MenuKey::Left);
  EXPECT_EQ(fe.settings.rounds, 15);  // 3 -> 2 -> 1 -> 15 (--rounds' range)
  fe.title_cursor = static_cast<int>(TitleItem::Seed);
  front_end_key(fe, MenuKey::Left);
  EXPECT_EQ(fe.settings.seed, 1u);  // no seed below 1
  front_end_key(fe, MenuKey::Right);
  EXPECT_EQ(fe.settings.seed, 2u);
  fe.title_cursor = static_cast<int>(TitleItem::Sandbox);
  const FrontAction a = front_end_key(fe, MenuKey::Enter);
  EXPECT_EQ(a, FrontAction::Start);
  EXPECT_EQ(fe.settings.mode, Mode::Sandbox);
  front_end_apply(fe, a);
  EXPECT_EQ(fe.screen, Screen::Playing);
  FrontEnd quit;
  EXPECT_EQ(front_end_key(quit, MenuKey::Back), FrontAction::Quit);  // Esc on the title leaves the game
}

TEST(FrontEnd, EscPausesAndResumesThePauseMenuRestartsOrGoesToTheTitle) {
  FrontEnd fe;
  fe.screen = Screen::Playing;
  EXPECT_EQ(front_end_key(fe, MenuKey::Enter), FrontAction::None);  // Enter and the arrows are not the menu's here
  EXPECT_EQ(front_end_key(fe, MenuKey::Back), FrontAction::None);
  EXPECT_EQ(fe.screen, Screen::Paused);
  EXPECT_EQ(front_end_key(fe, MenuKey::Back), FrontAction::Resume);
  front_end_apply(fe, FrontAction::Resume);
  EXPECT_EQ(fe.screen, Screen::Playing);
  front_end_key(fe, MenuKey::Back);
  front_end_key(fe, MenuKey::Down);
  EXPECT_EQ(front_end_key(fe, MenuKey::Enter), FrontAction::Restart);
  front_end_key(fe, MenuKey::Down);
  EXPECT_EQ(front_end_key(fe, MenuKey::Enter), FrontAction::ToTitle);
  front_end_apply(fe, FrontAction::ToTitle);
  EXPECT_EQ(fe.screen, Screen::Title);
}

TEST(FrontEnd, TheResultOpensThreeSecondsAfterTheBoutEndsAndGoesBackToTheTitle) {
  FrontEnd fe;
  fe.screen = Screen::Playing;
  front_end_watch_bout(fe, false, 100.0);
  EXPECT_EQ(fe.screen, Screen::Playing);
  front_end_watch_bout(fe, true, 100.0);  // the bout over now
  front_end_watch_bout(fe, true, 100.0 + kResultDelay - 0.01);
  EXPECT_EQ(fe.screen, Screen::Playing);
  front_end_watch_bout(fe, true, 100.0 + kResultDelay);
  EXPECT_EQ(fe.screen, Screen::Result);
  EXPECT_EQ(front_end_key(fe, MenuKey::Enter), FrontAction::ToTitle);
  front_end_apply(fe, FrontAction::ToTitle);
  EXPECT_EQ(fe.screen, Screen::Title);
  EXPECT_LT(fe.result_at, 0.0);  // the next bout's end counts again
}

TEST(FrontEnd, ModesSetTheScenarioAndThePlayersAndTheTitlesSettingsTheRest) {
  const Options base = *parse_cli({"--round-seconds", "20"});
  EXPECT_EQ(apply_mode(base, Mode::Watch).scenario_id, Scenario::Match);
  EXPECT_EQ(apply_mode(base, Mode::Watch).player, -1);
  EXPECT_EQ(apply_mode(base, Mode::Play).player, 0);
  EXPECT_EQ(apply_mode(base, Mode::Versus).player, 0);  // versus: both are players' (match_setup reads the mode)
  EXPECT_EQ(apply_mode(base, Mode::Sandbox).scenario_id, Scenario::Stand);
  EXPECT_EQ(apply_mode(base, Mode::Sandbox).scenario, "stand");
  FrontEndSettings s;
  s.mode = Mode::Play, s.ai_level = 0, s.rounds = 4, s.seed = 12;
  const Options o = options_for(base, s);
  EXPECT_EQ(o.mode, "play");
  EXPECT_EQ(o.seed, 12u);
  EXPECT_EQ(o.rounds, 4);
  EXPECT_EQ(o.ai, (std::array<std::string, 2>{"easy", "easy"}));
  EXPECT_DOUBLE_EQ(o.round_seconds, 20.0);  // the command line's
}

TEST(AiLevel, NormalLeavesTheTuningAsItIsEasyAndHardMoveTheStyleRanges) {
  const FighterAiTuning d;
  FighterAiTuning n = d, e = d, h = d;
  EXPECT_TRUE(apply_ai_level(n, "normal"));
  EXPECT_EQ(n.attack_rate_min, d.attack_rate_min);  // bit for bit: the tuned fight
  EXPECT_EQ(n.defence_max, d.defence_max);
  EXPECT_EQ(n.reaction_min, d.reaction_min);
  EXPECT_TRUE(apply_ai_level(e, "easy"));
  EXPECT_TRUE(apply_ai_level(h, "hard"));
  EXPECT_LT(e.attack_rate_max, d.attack_rate_min);  // easy's busiest below normal's quietest (0.64 < 1.0 attempts/s)
  EXPECT_GT(h.attack_rate_max, d.attack_rate_max);
  EXPECT_LT(e.defence_max, d.defence_min + 0.05);
  EXPECT_GT(h.defence_min, d.defence_min);
  EXPECT_GT(e.reaction_min, d.reaction_max);  // easy reacts slower than any normal style
  EXPECT_LT(h.reaction_max, d.reaction_max);
  EXPECT_GE(h.reaction_min, 0.15);  // still a trained athlete's (fighter_ai.h)
  FighterAiTuning x = d;
  EXPECT_FALSE(apply_ai_level(x, "brutal"));
  EXPECT_EQ(x.attack_rate_max, d.attack_rate_max);
}

}  // namespace
}  // namespace boxing
