#pragma once
// The clinch as measured: the time the boxers stand locked together, one's head inside the other's forearm's length
// of its chest (reach_distance < MatchTuning::clinch_within), both up. Issue 62 asks that gloves touch only in
// exchanges; a lock is where the boxers lean their weight on each other and one can go over with no punch on him.
// Observe only. A referee's "break" driven by it was tried and not kept (docs/decisions/clinch-break.md).
namespace boxing {

struct World;

struct ClinchMetrics {
  double locked_s = 0.0;   // s locked in all (the report's match.clinch.locked_s)
  double longest_s = 0.0;  // s, the longest lock (match.clinch.longest_s)
  double current_s = 0.0;  // s, the lock under way (0: apart)
};

// Each tick after the referee.
void measure_clinch(World& w);

}  // namespace boxing
