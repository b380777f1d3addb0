#include "game/scenario.h"

namespace boxing {

namespace {
constexpr Scenario kAll[] = {Scenario::Arena, Scenario::Ragdolls, Scenario::Stand,
                             Scenario::Push,  Scenario::GraphWalk, Scenario::Match, Scenario::Impacts};
}

const char* scenario_name(Scenario s) {
  switch (s) {
    case Scenario::Arena: return "arena";
    case Scenario::Ragdolls: return "ragdolls";
    case Scenario::Stand: return "stand";
    case Scenario::Push: return "push";
    case Scenario::GraphWalk: return "graph-walk";
    case Scenario::Match: return "match";
    case Scenario::Impacts: return "impacts";
  }
  return "?";
}

std::optional<Scenario> scenario_from_name(const std::string& name) {
  for (Scenario s : kAll)
    if (name == scenario_name(s)) return s;
  return std::nullopt;
}

}  // namespace boxing
