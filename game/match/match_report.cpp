#include "game/match/match_report.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "game/interaction/input_events.h"
#include "game/match/match.h"
#include "game/world.h"

namespace boxing {

MatchHud match_hud(const World& w) {
  const Match& mt = *w.match;
  MatchHud h;
  h.round = mt.bout.round;
  h.clock_s = bout_clock_left(w);
  h.resting = mt.bout.phase == BoutPhase::Rest;
  for (int k = 0; k < 2 && k < static_cast<int>(w.boxers.size()); ++k) {
    const MatchFighter& f = mt.fighter[k];
    h.side[k].consciousness = static_cast<float>(w.boxers[k].ctl.root_spring.consciousness());
    h.side[k].landed = f.landed, h.side[k].thrown = f.thrown, h.side[k].knockdowns = f.knockdowns;
    h.side[k].player = f.player;
    h.side[k].name = k == 0 ? "RED" : "BLUE";
    for (int c = 0; c < 3; ++c) h.side[k].colour[c] = w.boxers[k].team_color[c];
    if (f.player) h.side[k].tag = "YOU";
    h.side[k].state = boxer_state_name(w.boxers[k].ctl.state.state);
    h.side[k].stamina = static_cast<float>(f.stamina.level);
    h.side[k].notice = player_notice(w, k);
    if (f.getup >= 0 && !mt.over) {
      const GetUp& g = mt.getups[f.getup];
      // The count's number once it has started (the standing boxer in a neutral corner, referee.h).
      h.banner = std::string(k == 0 ? "RED" : "BLUE") + " DOWN";
      h.down = k;
      if (g.count_from >= 0.0) {
        const int count = std::min(static_cast<int>(mt.tuning.count_seconds),
                                   static_cast<int>(g.counted_ticks * kPhysicsDt) + 1);
        h.banner += "   " + std::to_string(count);
        h.count = count;
        h.count_stopped = !g.counting;
        if (!g.counting) h.banner += "   (count stopped: to the neutral corner)";
      }
    }
  }
  // Between rounds: the round's cards (red first), the judges in order.
  if (h.resting && !mt.bout.cards.empty()) {
    const RoundCard& c = mt.bout.cards.back();
    h.banner = "END OF ROUND " + std::to_string(c.round) + "  ";
    for (const auto& j : c.judges) h.banner += "  " + std::to_string(j[0]) + "-" + std::to_string(j[1]);
    h.cards = h.banner;
  }
  if (mt.over) h.banner = h.result = mt.bout.result.text;
  return h;
}

BoutSummary bout_summary(const World& w) {
  const Match& mt = *w.match;
  const Bout& bt = mt.bout;
  BoutSummary s;
  for (int k = 0; k < 2 && k < static_cast<int>(w.boxers.size()); ++k)
    for (int c = 0; c < 3; ++c) s.colour[k][c] = w.boxers[k].team_color[c];
  s.winner = bt.result.winner;
  s.method = bt.result.method;
  s.round = bt.result.round;
  s.time_s = bt.result.time_s;
  const std::array<int, 3> d = decide(bt.cards);
  s.judges_for[0] = d[1], s.judges_for[1] = d[2];
  for (const RoundCard& c : bt.cards) {
    BoutSummary::Round r;
    r.round = c.round;
    for (int j = 0; j < 3; ++j) r.judges[j][0] = c.judges[j][0], r.judges[j][1] = c.judges[j][1];
    for (int k = 0; k < 2; ++k) r.landed[k] = c.landed[k], r.thrown[k] = c.thrown[k], r.knockdowns[k] = c.knockdowns[k];
    s.rounds.push_back(r);
  }
  return s;
}

namespace {

// A fight command's key action (input_events.h: the --input file's name for it).
const char* fight_command_action(FightCommand c) {
  const int i = static_cast<int>(c) - 1;
  return i >= 0 && i < kKeyActionCount ? kKeyActions[i] : "none";
}

// Per boxer, the footwork as measured (footwork_metrics.h) and the ropes' contact time (ring_ropes.h).
nlohmann::json footwork_report(const World& w) {
  nlohmann::json out = nlohmann::json::array();
  for (int k = 0; k < 2 && k < static_cast<int>(w.boxers.size()); ++k) {
    const FootworkMetrics& m = w.match->footwork[k];
    out.push_back({{"boxer", k},
                   {"steps", m.steps},
                   {"standing_s", m.standing_s},
                   {"steps_per_minute_standing", m.standing_s > 0.0 ? 60.0 * m.steps / m.standing_s : 0.0},
                   {"path_m", m.path_m},
                   {"time_in_range_s", m.time_in_range_s},
                   {"legs_through_s", m.legs_through_s},
                   {"ring_exits", m.ring_exits},
                   {"ring_exits_after_hit", m.ring_exits_after_hit},
                   {"rope_contacts_s", w.ropes.contact_s[k]},
                   {"teleports", m.teleports}});
  }
  return out;
}

}  // namespace

nlohmann::json match_report(const World& w) {
  const Match& mt = *w.match;
  nlohmann::json events = nlohmann::json::array();
  for (const PunchEvent& e : mt.events)
    events.push_back({{"t", e.t},
                      {"boxer", e.boxer},
                      {"punch", e.punch},
                      {"target", e.target},
                      {"landed", e.landed},
                      {"blocked", e.blocked},
                      {"hit", e.hit_part},
                      {"other_clip", e.other_clip},
                      {"defence", e.defence},
                      {"speed", e.speed},
                      {"fist_speed", e.fist_speed},
                      {"peak_speed", e.peak_speed},
                      {"opening_m", e.opening},
                      {"consciousness", e.consciousness},
                      {"impulse", e.impulse},
                      {"damage", e.damage},
                      {"stamina", e.stamina},
                      {"landed_at", e.landed ? nlohmann::json(e.landed_at) : nlohmann::json(nullptr)}});
  nlohmann::json getups = nlohmann::json::array();
  for (const GetUp& g : mt.getups)
    getups.push_back({{"boxer", g.boxer},
                      {"down_at_s", g.down_at},
                      {"count_from_s", g.count_from},
                      {"up_at_s", g.up_at >= 0.0 ? nlohmann::json(g.up_at) : nlohmann::json(nullptr)},
                      {"lying", g.lying.empty() ? nlohmann::json(nullptr) : nlohmann::json(g.lying)},
                      {"root_assist_rms_nm", g.assist_time > 0 ? std::sqrt(g.assist_sq_dt / g.assist_time) : 0.0},
                      {"root_assist_force_rms_n", g.assist_time > 0 ? std::sqrt(g.assist_force_sq_dt / g.assist_time) : 0.0},
                      {"stand_up_s", g.assist_time},
                      {"stand_up_retries", g.retries},
                      {"count_s", g.counted_ticks * kPhysicsDt},
                      {"count_paused_s", g.paused_ticks * kPhysicsDt},
                      {"count_distance_min_m", g.count_distance_min >= 0.0 ? nlohmann::json(g.count_distance_min)
                                                                          : nlohmann::json(nullptr)},
                      {"down_distance_min_m", g.down_distance_min >= 0.0 ? nlohmann::json(g.down_distance_min)
                                                                        : nlohmann::json(nullptr)}});
  auto pair = [&mt](auto get) { return nlohmann::json::array({get(mt.fighter[0]), get(mt.fighter[1])}); };
  // The rounds scored, and (a run that ends mid-bout) the round under way scored as it stands: the result is then
  // the decision the cards so far give, marked unfinished.
  const Bout& bt = mt.bout;
  std::vector<RoundCard> cards = bt.cards;
  if (!mt.over && bt.phase == BoutPhase::Fighting && w.data.time > bt.phase_from)
    cards.push_back(score_round(mt, bt.round, bt.phase_from, w.data.time));
  nlohmann::json rounds = nlohmann::json::array();
  for (const RoundCard& c : cards)
    rounds.push_back({{"round", c.round}, {"from_s", c.from_s}, {"to_s", c.to_s}, {"landed", c.landed},
                      {"thrown", c.thrown}, {"knockdowns", c.knockdowns}, {"judges", c.judges}});
  const std::array<int, 3> d = decide(cards);
  const int winner = mt.over ? bt.result.winner : d[0];
  const bool resting = !mt.over && bt.phase == BoutPhase::Rest && !cards.empty();  // the last card's round is over
  const nlohmann::json result = {
      {"winner", winner >= 0 ? nlohmann::json(winner) : nlohmann::json(nullptr)},
      {"method", mt.over ? bt.result.method : (d[0] < 0 ? "draw" : "decision")},
      {"round", resting ? cards.back().round : bt.round},
      {"time_s", mt.over    ? bt.result.time_s
                 : resting ? cards.back().to_s - cards.back().from_s
                           : w.data.time - bt.phase_from},
      {"finished", mt.over},
      {"judges_for", {d[1], d[2]}}};  // judges whose cards name red, blue
  const std::string result_text = mt.over       ? bt.result.text
                                  : winner < 0 ? "DRAW SO FAR"
                                               : std::string(winner == 0 ? "RED" : "BLUE") + " AHEAD ON POINTS";
  // Every fight key pressed and what became of it (player_input.h).
  nlohmann::json inputs = nlohmann::json::array();
  for (const PlayerPress& p : mt.presses) {
    nlohmann::json j = {{"t_pressed", p.t_pressed},
                        {"action", fight_command_action(p.action)},
                        {"boxer", p.boxer},
                        {"waited", p.waited == PressWait::Free ? "free" : "buffered"}};
    if (p.t_started >= 0.0) j["t_started"] = p.t_started;
    else if (p.refused) j["refused"] = p.refused;
    else j["pending"] = true;  // still waiting when the run ended
    inputs.push_back(std::move(j));
  }
  std::vector<double> speeds, fists;
  for (const PunchEvent& e : mt.events)
    if (e.landed) speeds.push_back(e.speed), fists.push_back(e.fist_speed);
  std::sort(speeds.begin(), speeds.end());
  std::sort(fists.begin(), fists.end());
  return {{"punches_thrown", pair([](const MatchFighter& f) { return f.thrown; })},
          {"punches_landed", pair([](const MatchFighter& f) { return f.landed; })},
          {"knockdowns", pair([](const MatchFighter& f) { return f.knockdowns; })},
          {"falls_without_hit", pair([](const MatchFighter& f) { return f.falls_without_hit; })},
          {"falls_after_hit", pair([](const MatchFighter& f) { return f.falls_after_hit; })},
          {"balance_steps_after_hit", pair([](const MatchFighter& f) { return f.balance_steps_after_hit; })},
          {"rocked", pair([](const MatchFighter& f) { return f.rocked; })},
          {"landed_speed_median", speeds.empty() ? 0.0 : speeds[speeds.size() / 2]},
          {"landed_fist_speed_median", fists.empty() ? 0.0 : fists[fists.size() / 2]},
          {"consciousness", pair([&w](const MatchFighter& f) {
             const int k = static_cast<int>(&f - &w.match->fighter[0]);
             return w.boxers[k].ctl.root_spring.consciousness();
           })},
          {"players", pair([](const MatchFighter& f) { return f.player; })},
          {"styles", pair([](const MatchFighter& f) {
             const FighterStyle& s = f.ai.style;
             return nlohmann::json{{"attack_rate", s.attack_rate}, {"combo", s.combo}, {"defence", s.defence},
                                   {"reaction_s", s.reaction_s}, {"body_share", s.body_share},
                                   {"punch_weight", s.punch_weight}};
           })},
          {"ai", w.options.ai},  // the AI levels asked for (--ai), red's and blue's
          {"player_commands_taken", pair([](const MatchFighter& f) { return f.commands_taken; })},
          {"player_inputs", inputs},
          {"stamina", pair([](const MatchFighter& f) { return f.stamina.level; })},
          {"stamina_lowest", pair([](const MatchFighter& f) { return f.stamina.lowest; })},
          {"stamina_rule", stamina_rule_text(mt.tuning.stamina)},
          {"round_seconds", bt.round_seconds},
          {"round", bt.round},
          {"rounds_scheduled", bt.tuning.rounds},
          {"rounds", rounds},
          {"ended_at_s", w.data.time},  // the run's end: a knockdown less than the count before it has no up_at_s yet
          {"getups", getups},
          {"teleports", mt.teleports},
          // the time the boxers were locked at a forearm's length (clinch.h)
          {"clinch", {{"locked_s", mt.clinch.locked_s}, {"longest_s", mt.clinch.longest_s}}},
          {"fighters", footwork_report(w)},
          {"result", result},
          {"result_text", result_text},
          {"defence", defence_report(w)},  // the defences as the bodies made them (defence_metrics.h)
          {"events", events}};
}

}  // namespace boxing
