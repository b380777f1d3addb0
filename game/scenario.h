#pragma once
// The scenarios build/boxing runs (--scenario NAME): an enum the CLI parses, the names as the flag spells them.
#include <optional>
#include <string>

namespace boxing {

enum class Scenario { Arena, Ragdolls, Stand, Push, GraphWalk, Match, Impacts };

// "arena" | "ragdolls" | "stand" | "push" | "graph-walk" | "match" | "impacts"
const char* scenario_name(Scenario s);
std::optional<Scenario> scenario_from_name(const std::string& name);

}  // namespace boxing
