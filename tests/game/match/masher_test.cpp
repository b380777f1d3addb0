// A masher loses (issue 65 item 3): red presses jab every 0.15 s from 0.5 s to the bout's end, blue is the
// normal AI, over a bout of three 20 s rounds (2 s rests: short rounds keep the test's time down; the stamina rule does
// not depend on the round's length) on seeds 1-10, through the executable with --input as a person scripts it. Blue
// must win on at least 9 of the 10 (the bound), and the masher runs dry every time (stamina.h). Measured: 10 of
// 10; the same script from 1.0 s gave 8 (seed 2 a draw, seed 7 red on points): docs/decisions/stamina.md.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "game/match/stamina.h"
#include "support/run_boxing.h"
#include "test_paths.h"

namespace {

TEST(Masher, AJabEvery0_15sLosesToTheNormalAiOnNineOfTenSeeds) {
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/masher_test";
  std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str());
  const std::string input = dir + "/masher.json";
  {
    std::ofstream out(input);
    out << "{\"events\": [";
    for (int i = 0; 0.5 + 0.15 * i < 80.0; ++i)
      out << (i ? "," : "") << "{\"t\": " << 0.5 + 0.15 * i << ", \"key\": {\"action\": \"jab\", \"boxer\": 0}}";
    out << "]}\n";
  }
  int blue_wins = 0;
  std::string record;
  for (int seed = 1; seed <= 10; ++seed) {
    const std::string report = dir + "/report_" + std::to_string(seed) + ".json";
    // 3 x 20 s + 2 x 2 s = 64 s, and a count under way at the last bell is finished first (bout.h): --seconds 80.
    const auto run = boxing_test::run_boxing("--headless --scenario match --player 0 --rounds 3 --round-seconds 20 "
                                             "--rest-seconds 2 --seconds 80 --seed " + std::to_string(seed) +
                                             " --input " + input + " --report " + report);
    ASSERT_EQ(run.code, 0) << run.output;
    std::ifstream in(report);
    const nlohmann::json m = nlohmann::json::parse(in)["match"];
    EXPECT_TRUE(m["result"]["finished"].get<bool>()) << "seed " << seed;
    const bool blue = m["result"]["winner"] == 1;
    blue_wins += blue;
    EXPECT_LT(m["stamina_lowest"][0].get<double>(), boxing::StaminaTuning{}.punch_cost)
        << "seed " << seed << ": the masher never ran dry";
    record += "seed " + std::to_string(seed) + ": " + (blue ? "blue" : m["result"]["winner"].is_null() ? "draw" : "RED") +
              " (" + m["result"]["method"].get<std::string>() + ") landed " + m["punches_landed"].dump() + " thrown " +
              m["punches_thrown"].dump() + "\n";
  }
  std::printf("%s", record.c_str());
  EXPECT_GE(blue_wins, 9) << record;
}

}  // namespace
