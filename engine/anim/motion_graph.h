#pragma once
// Motion graph (Kovar, Gleicher, Pighin 2002, "Motion Graphs") over a set of clips, plus a
// random-walk player (GraphWalker) with steering (request_tag / request_clip) and knockdowns
// (force_clip), in the spirit of the boxers of Jenkins/Wrotek/McGuire (random motion-graph traversal
// of punches plus a stand-up motion).
// The graph knows no character: which extra points describe a pose, which clip tags are entered only by
// force, and the home clip come from MotionGraphOptions, filled by the game (game/boxing_motion.h). With
// the default (empty) options the features are the joint positions alone, every clip is a transition
// source and destination, there are no knockdown edges, and walks start at clip 0.
//
// Construction (MotionGraph::build):
//  * Frames: every clip sampled at GraphOptions::fps (30 Hz): node (clip, frame), frame f at f/fps.
//  * Frame features: a point cloud per frame by forward kinematics: every joint position plus the
//    MotionGraphOptions::feature_points (bone + offset in the bone frame; the boxer adds the glove centres,
//    the toes and the top of the head: 16 + 5 = 21 points), in clip space.
//  * Distance D(A_i, B_j): sum of squared distances between the point clouds of the windows
//    A_i..A_{i+k-1} and B_j..B_{j+k-1} (k = GraphOptions::window = 5 frames, ~0.17 s), uniform weights,
//    after the optimal rigid 2D alignment of B onto A (rotation about the vertical Z axis plus a
//    translation on the floor; closed form, align_2d(), as in the paper's appendix).
//    Reported as a per-point RMS: rms = sqrt(D / (k * points)).
//  * Candidate transitions: local minima of D over (i, j) (<= all 8 neighbours of the same clip pair)
//    with rms < GraphOptions::threshold_rms. Default 4 cm: below that a 5-frame slerp blend with the
//    root aligned is invisible at game distance and well inside what the PD servos track; clips that
//    pass through guard match at ~0-2 cm, distinct poses (mid-punch vs guard) sit at 10-30 cm.
//    Sources: every clip without a MotionGraphOptions::no_source_tags tag (boxer: fall, down);
//    destinations: every clip without an entry_only_tags tag (boxer: fall, down, getup, reaction -- those
//    are only entered through force_clip -- a hit or a knockdown -- or a clip's natural continuation).
//    Self-transitions need |i - j| >= 2k.
//  * A transition edge A_i -> B_{j+k-1} plays A_i..A_{i+k-1} blended into the aligned
//    B_j..B_{j+k-1} with the C1 ease weight w = 3u^2 - 2u^3 (the paper's alpha = 1 - w),
//    slerp per joint, lerp of the aligned root.
//  * Natural continuations: the last frame of a clip -> frame 0 of each clip in Clip::next (when empty:
//    a loop -> itself, else the home clip; boxer: punches -> guard, fall_back -> down_back -> down_back |
//    getup_back ...),
//    root aligned with the same 2D alignment of the two frames' point clouds, no blend (the clips are
//    authored to meet exactly).
//  * Knockdown (forced-entry) edges: virtual edges home clip frame 0 -> frame 0 of every clip with a
//    forced_entry_tags tag (boxer: fall, reaction). The game enters those clips with force_clip (from any frame) when a boxer is hit
//    or knocked down; these edges only make them count as reachable when pruning. The random walk
//    and the planner never take them.
//  * Pruning: the largest strongly connected component (iterative Tarjan) is kept; nodes outside are
//    marked dead and edges into them removed, so no walk can reach a dead end.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/anim/clip.h"

namespace eng::anim {

// Rigid motion of the floor plane: rotation theta about +Z, then translation (tx, ty).
struct Align2D {
  double theta = 0.0, tx = 0.0, ty = 0.0;
  Eigen::Vector3d apply(const Eigen::Vector3d& p) const;
  Eigen::Quaterniond rotation() const;
  Align2D then(const Align2D& inner) const;  // this * inner (apply inner first)
};

// The Align2D T minimising sum_i w_i |a_i - T b_i|^2 (weights uniform when w is empty).
Align2D align_2d(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                 const std::vector<double>& w = {});

struct GraphOptions {
  double fps = 30.0;
  int window = 5;               // k frames compared and blended
  double threshold_rms = 0.04;  // metres per point (see the header comment)
  double min_self_gap_windows = 2.0;
};

// A feature point beyond the joint positions: a point fixed to a bone (offset in the bone's frame, m).
struct FeaturePoint {
  std::string bone;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

// What the clips mean to the graph: given by the game, neutral by default (see the header comment).
struct MotionGraphOptions {
  std::vector<FeaturePoint> feature_points;     // added to every joint position, in this order
  std::vector<std::string> entry_only_tags;     // clips never entered by a random transition
  std::vector<std::string> no_source_tags;      // clips never left by a random transition
  std::vector<std::string> forced_entry_tags;   // clips given a knockdown edge from the home clip
  std::string home_clip;  // walk start, continuation of a non-loop clip without next, knockdown source
};

enum class EdgeKind { Next, Transition, Continuation, Knockdown };

struct GraphEdge {
  int to = -1;                 // node index
  EdgeKind kind = EdgeKind::Next;
  double blend = 0.0;          // seconds of blending (transitions: (k-1)/fps)
  int dst_start_frame = 0;     // transitions: B frame j where the blend window starts
  Align2D align;               // maps the destination clip's space into the source clip's space
  double rms = 0.0;            // transitions: window distance as per-point RMS (m)
};

struct GraphNode {
  int clip = -1;
  int frame = 0;
};

struct MotionGraph {
  std::vector<Clip> clips;
  GraphOptions options;
  MotionGraphOptions content;
  Skeleton skeleton;
  std::vector<GraphNode> nodes;
  std::vector<std::vector<GraphEdge>> edges;  // out edges per node
  std::vector<int> first_node;                // per clip
  std::vector<int> frame_count;               // per clip
  std::vector<char> alive;                    // per node: in the kept strongly connected component
  // statistics
  int candidate_pairs = 0;  // window pairs compared
  int transitions = 0;      // transition edges kept
  int transitions_before_prune = 0;
  double mean_rms = 0.0;    // mean window distance over all compared pairs (m)
  int scc_size = 0;

  void build(const std::vector<Clip>& clips, const GraphOptions& options, const MotionGraphOptions& content,
             const Skeleton& skeleton);
  int node(int clip, int frame) const { return first_node[clip] + frame; }
  int clip_index(const std::string& name) const { return find_clip(clips, name); }
  double frame_time(int frame) const { return frame / options.fps; }
  // Frame point cloud (clip space) used by the distance metric.
  std::vector<Eigen::Vector3d> point_cloud(const Pose& p) const;
};

// Seeded random walk over a MotionGraph producing desired poses for the servos.
class GraphWalker {
 public:
  // start_clip empty: the graph's home clip (MotionGraphOptions::home_clip); unknown: clip 0.
  GraphWalker(const MotionGraph& g, uint64_t seed, const std::string& start_clip = {});

  // Advances by dt and returns the desired pose: parent-space rotations, world root pose (root
  // motion accumulated along the walk with the 2D alignment at every transition), root velocity and
  // angular velocities (central difference of the played motion, h = 1e-4 s; PoseSample contract).
  PoseSample tick(double dt);
  // The same into *out, reusing its storage (no allocation once warm: the per-tick call).
  void tick(double dt, PoseSample* out);

  // Steering: plan the shortest (in frames, Dijkstra) path to the early frames (first quarter) of the
  // nearest clip with the tag / name; the planned transitions are taken as soon as the walk reaches
  // them. Returns false when no such clip is reachable.
  // A request is done once the walk is in the target; repeat = true keeps it (every continuation plans back to it until
  // another request replaces it: a leash that keeps stepping back).
  bool request_tag(const std::string& tag, bool repeat = false);
  bool request_clip(const std::string& name, bool repeat = false);
  // Knockdown / hit reaction: blend (>= k-1 frames, longer for distant poses, root aligned) from the current pose into
  // frame 0 of the clip, from any frame; its natural continuations take over afterwards
  // (fall_back -> down_back -> getup_back -> guard). Returns false for an unknown clip.
  bool force_clip(const std::string& name);
  // A reset: the walk starts over at frame 0 of the clip (the home clip when empty) at its origin, as when it was made:
  // no blend, no plan, the root motion accumulated so far dropped (the caller sets the body on the new pose). The random
  // stream carries on. Returns false for an unknown clip.
  bool restart(const std::string& name = {});

  // The walk's world pose `ahead` seconds after the last tick, were it to stay in the current clip (and blend): the
  // next transition is not drawn yet, so time stops at the clip's end. Look-ahead, e.g. where a step will land.
  // The pose is the walker's: valid until the next preview or tick.
  const Pose& preview(double ahead) const;
  const std::string& current_clip() const;
  int current_clip_index() const { return clip_; }
  // Seconds into the current clip (a looping clip's time keeps growing; wrap it with the clip's duration).
  double clip_time() const { return time_; }
  int current_node() const { return g_->node(clip_, frame_); }
  bool blending() const { return blend_.active; }
  bool has_plan() const { return !plan_.empty(); }
  double transition_probability = 0.08;  // per frame, for the random choice of a transition
  // At the end of a clip whose continuations include itself (guard, down loops): probability of
  // looping; otherwise the other continuations are drawn uniformly.
  double loop_probability = 0.35;
  // Heading hold (1/s; 0 = off, Kovar's walk): the yaw the transitions' 2D alignments accumulate (T's theta; a random
  // walk, 40 deg in 100 s of boxing clips) is steered back toward the clips' own facing at this rate, the walk's frame
  // turned about the root's floor position (the root does not jump). For clips authored facing one way (a boxer
  // toward its opponent) whose feet cannot follow a drifting heading.
  double heading_hold = 0.0;
  // While set (the caller's, per tick), the walk stays in its clip: no random transition, no planned transition taken
  // (a plan waits and is made again), and at the clip's end it continues into the home clip when it can. The game sets
  // it while a carried step's foot is in the air (the balance QP's footwork, docs/decisions/footwork.md): a punch
  // entered mid-swing left the foot hanging short of a higher crate.
  bool hold_transitions = false;

 private:
  struct Blend {
    bool active = false;
    int clip = -1;
    double time = 0.0;
    Align2D T;
    double elapsed = 0.0, duration = 0.0;
  };
  struct Step {
    int from_node;
    int edge;
  };
  double uniform();  // [0,1) from 53 bits of mt19937_64 (same on every standard library)
  void take_edge(int from_node, const GraphEdge& e);
  void decide();
  // decide's stages: the plan's next edge (true: decided, decide returns), a continuation drawn at the clip's end, a
  // random transition.
  bool follow_plan(int v, bool at_end);
  void take_continuation(int v);
  void take_random_transition(int v);
  bool plan_to(const std::vector<char>& target);
  // root_only: out.root_position alone (out.rotation left empty), the same number as the whole pose's.
  void world_pose_at(double dt_offset, Pose& out, bool root_only = false) const;
  void hold_heading(double dt);  // heading_hold's turn of the walk's frames, before the tick samples them

  const MotionGraph* g_;
  std::mt19937_64 rng_;
  int home_ = -1;  // the home clip's index (hold_transitions' continuation)
  int clip_ = 0;
  int frame_ = 0;
  double time_ = 0.0;
  Align2D T_;
  int prev_clip_ = -1;  // clip left by the last continuation (for derivatives across the seam)
  Align2D prev_T_;
  Blend blend_;
  std::vector<Step> plan_;
  std::vector<char> plan_target_;
  bool repeat_ = false;  // keep plan_target_ once reached (request_* repeat)
  // Scratch kept between ticks and plans so that a walk allocates nothing once warm.
  mutable Pose preview_, blend_from_;
  Pose fd_a_, fd_b_;  // the poses of tick's central difference
  std::vector<double> dist_;
  std::vector<std::pair<int, int>> prev_;
  std::vector<std::pair<double, int>> heap_;
  std::vector<char> target_;
};

// Summary: clips, frames, edges by kind, transitions per clip, SCC size and covered tags, threshold.
nlohmann::json graph_report(const MotionGraph& g);
// Clip-level Graphviz DOT: one node per clip, one edge per connected clip pair labelled and weighted
// by the number of transitions (natural continuations drawn dashed).
std::string graph_dot(const MotionGraph& g);

}  // namespace eng::anim
