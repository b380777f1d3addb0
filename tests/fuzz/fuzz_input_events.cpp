// libFuzzer harness: the input-event file parser (game/interaction/input_events.h) on arbitrary bytes, as
// load_input_file reads them (JSON, then parse_input_events).
// Promise checked: accepted events are in time order with finite fields, and written back (input_event_json)
// each parses again to the same event (the file form round-trips, which --record / --input rely on).
#include <cstddef>
#include <cstdint>

#include "game/interaction/input_events.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const nlohmann::json doc = nlohmann::json::parse(data, data + size, nullptr, false);
  if (doc.is_discarded()) return 0;
  auto events = boxing::parse_input_events(doc);
  if (!events) {
    fuzz::check(!events.error().empty(), "an error without a message");
    return 0;
  }
  for (size_t i = 0; i < events->size(); ++i) {
    const boxing::InputEvent& e = (*events)[i];
    fuzz::check(std::isfinite(e.t) && e.t >= 0 && (i == 0 || e.t >= (*events)[i - 1].t), "event times");
    fuzz::check(fuzz::finite(e.vec) && fuzz::finite(e.from) && fuzz::finite(e.velocity) && std::isfinite(e.duration) &&
                    std::isfinite(e.speed),
                "event fields not finite");
    fuzz::check(e.boxer >= 0 && e.at_boxer >= -1 && e.object >= -1, "event indices");
    const nlohmann::json written = boxing::input_event_json(e);
    auto again = boxing::parse_input_event(written);
    fuzz::check(again.ok(), "a written event does not parse: " + written.dump() + ": " +
                                (again.ok() ? std::string() : again.error()));
    fuzz::check(boxing::input_event_json(*again) == written, "a written event parses to another: " + written.dump());
  }
  return 0;
}
