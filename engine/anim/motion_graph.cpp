#include "engine/anim/motion_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <sstream>

namespace eng::anim {

using Eigen::Quaterniond;
using Eigen::Vector3d;

// ------------------------------------------------------------------------------------------ Align2D
Vector3d Align2D::apply(const Vector3d& p) const {
  const double c = std::cos(theta), s = std::sin(theta);
  return Vector3d(c * p.x() - s * p.y() + tx, s * p.x() + c * p.y() + ty, p.z());
}

Quaterniond Align2D::rotation() const { return Quaterniond(Eigen::AngleAxisd(theta, Vector3d::UnitZ())); }

Align2D Align2D::then(const Align2D& in) const {
  Align2D r;
  r.theta = theta + in.theta;
  const Vector3d t = apply(Vector3d(in.tx, in.ty, 0.0));
  r.tx = t.x();
  r.ty = t.y();
  return r;
}

// Closed form (Kovar et al. 2002, appendix; 2D Procrustes): with weighted centroids a_c, b_c of the
// floor coordinates and centred coordinates a', b':
//   theta = atan2(sum w (b'x a'y - b'y a'x), sum w (b'x a'x + b'y a'y)),  t = a_c - R(theta) b_c.
// Heights are untouched by the alignment and simply add to the residual.
Align2D align_2d(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b, const std::vector<double>& w) {
  const size_t n = std::min(a.size(), b.size());
  double W = 0, ax = 0, ay = 0, bx = 0, by = 0;
  for (size_t i = 0; i < n; ++i) {
    const double wi = w.empty() ? 1.0 : w[i];
    W += wi;
    ax += wi * a[i].x();
    ay += wi * a[i].y();
    bx += wi * b[i].x();
    by += wi * b[i].y();
  }
  Align2D r;
  if (W <= 0) return r;
  ax /= W;
  ay /= W;
  bx /= W;
  by /= W;
  double num = 0, den = 0;
  for (size_t i = 0; i < n; ++i) {
    const double wi = w.empty() ? 1.0 : w[i];
    const double pax = a[i].x() - ax, pay = a[i].y() - ay, pbx = b[i].x() - bx, pby = b[i].y() - by;
    num += wi * (pbx * pay - pby * pax);
    den += wi * (pbx * pax + pby * pay);
  }
  r.theta = std::atan2(num, den);
  const double c = std::cos(r.theta), s = std::sin(r.theta);
  r.tx = ax - (c * bx - s * by);
  r.ty = ay - (s * bx + c * by);
  return r;
}

// ------------------------------------------------------------------------------------------ graph
namespace {

// Clips entered only through force_clip (hits, knockdowns) or a natural continuation, never by a
// random transition (a boxer must not flinch or fall without being hit), and clips never left by one.
bool has_any_tag(const Clip& c, const std::vector<std::string>& tags) {
  for (const auto& t : tags)
    if (c.has_tag(t)) return true;
  return false;
}

// out = a blended toward b by w (out may be b, not a).
void blend_pose_into(const Pose& a, const Pose& b, double w, Pose& out) {
  out.root_position = (1.0 - w) * a.root_position + w * b.root_position;
  out.rotation.resize(a.rotation.size());
  for (size_t i = 0; i < a.rotation.size(); ++i) out.rotation[i] = a.rotation[i].slerp(w, b.rotation[i]).normalized();
}

// p (clip frame) placed by the walk's 2D alignment T, in place.
void to_world_in_place(Pose& p, const Align2D& T) {
  p.root_position = T.apply(p.root_position);
  if (!p.rotation.empty()) p.rotation[0] = (T.rotation() * p.rotation[0]).normalized();
}

double ease(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}

}  // namespace

std::vector<Vector3d> MotionGraph::point_cloud(const Pose& p) const {
  std::vector<Vector3d> wp;
  std::vector<Quaterniond> wr;
  forward_kinematics(skeleton, p, &wp, &wr);
  std::vector<Vector3d> pts = wp;
  for (const FeaturePoint& fp : content.feature_points) {
    const int b = skeleton.find(fp.bone);
    if (b >= 0) pts.push_back(wp[b] + wr[b] * fp.offset);
  }
  return pts;
}

namespace {

// Per clip, per frame: the frame's point cloud (clip space).
using FrameClouds = std::vector<std::vector<std::vector<Vector3d>>>;

// One node per frame (the clip sampled at options.fps), its point cloud, and the Next edges along each clip.
FrameClouds add_frames(MotionGraph& g) {
  const int C = static_cast<int>(g.clips.size());
  FrameClouds cloud(C);
  for (int c = 0; c < C; ++c) {
    const int n = static_cast<int>(std::floor(g.clips[c].duration() * g.options.fps + 1e-9)) + 1;
    g.first_node.push_back(static_cast<int>(g.nodes.size()));
    g.frame_count.push_back(n);
    for (int f = 0; f < n; ++f) {
      g.nodes.push_back({c, f});
      cloud[c].push_back(g.point_cloud(sample_clip_pose(g.clips[c], f / g.options.fps)));
    }
  }
  g.edges.assign(g.nodes.size(), {});
  for (int c = 0; c < C; ++c)
    for (int f = 0; f + 1 < g.frame_count[c]; ++f) {
      GraphEdge e;
      e.to = g.node(c, f + 1);
      e.kind = EdgeKind::Next;
      g.edges[g.node(c, f)].push_back(e);
    }
  return cloud;
}

// The window distances from clip a's windows (rows, na) to clip b's (columns, nb): D the squared distance after the
// 2D alignment AL of b's window onto a's (Kovar et al. 2002), each pair's per-point RMS added to sum_rms.
void window_distances(const MotionGraph& g, const FrameClouds& cloud, int a, int b, int k, int P, int na, int nb,
                      std::vector<double>& D, std::vector<Align2D>& AL, double& sum_rms) {
  std::vector<Vector3d> wa, wb;
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) {
      wa.clear();
      wb.clear();
      for (int q = 0; q < k; ++q) {
        wa.insert(wa.end(), cloud[a][i + q].begin(), cloud[a][i + q].end());
        wb.insert(wb.end(), cloud[b][j + q].begin(), cloud[b][j + q].end());
      }
      const Align2D T = align_2d(wa, wb);
      double d = 0;
      for (size_t m = 0; m < wa.size(); ++m) d += (wa[m] - T.apply(wb[m])).squaredNorm();
      D[i * nb + j] = d;
      AL[i * nb + j] = T;
      sum_rms += std::sqrt(d / (k * P));
    }
}

// A Transition edge from a's window i to b's window j for every pair under threshold_rms that is a local minimum of
// the distance among its 8 neighbours (not within min_self_gap_windows of itself in the same clip).
void add_local_minima(MotionGraph& g, int a, int b, int k, int P, int na, int nb, const std::vector<double>& D,
                      const std::vector<Align2D>& AL) {
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) {
      if (a == b && std::abs(i - j) < g.options.min_self_gap_windows * k) continue;
      const double d = D[i * nb + j];
      const double rms = std::sqrt(d / (k * P));
      if (rms >= g.options.threshold_rms) continue;
      bool local_min = true;
      for (int di = -1; di <= 1 && local_min; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          const int ii = i + di, jj = j + dj;
          if ((di || dj) && ii >= 0 && jj >= 0 && ii < na && jj < nb && D[ii * nb + jj] < d) {
            local_min = false;
            break;
          }
        }
      if (!local_min) continue;
      GraphEdge e;
      e.to = g.node(b, j + k - 1);
      e.kind = EdgeKind::Transition;
      e.blend = (k - 1) / g.options.fps;
      e.dst_start_frame = j;
      e.align = AL[i * nb + j];
      e.rms = rms;
      g.edges[g.node(a, i)].push_back(e);
      ++g.transitions_before_prune;
    }
}

// Window distances and candidate transitions between every pair of clips a random transition may leave and enter.
void add_transitions(MotionGraph& g, const FrameClouds& cloud, int k) {
  const int C = static_cast<int>(g.clips.size());
  const int P = cloud.empty() || cloud[0].empty() ? 1 : static_cast<int>(cloud[0][0].size());
  double sum_rms = 0.0;
  g.candidate_pairs = 0;
  g.transitions_before_prune = 0;
  for (int a = 0; a < C; ++a) {
    if (has_any_tag(g.clips[a], g.content.no_source_tags)) continue;
    for (int b = 0; b < C; ++b) {
      if (has_any_tag(g.clips[b], g.content.entry_only_tags)) continue;
      const int na = g.frame_count[a] - k + 1, nb = g.frame_count[b] - k + 1;
      if (na <= 0 || nb <= 0) continue;
      std::vector<double> D(static_cast<size_t>(na) * nb);
      std::vector<Align2D> AL(D.size());
      window_distances(g, cloud, a, b, k, P, na, nb, D, AL, sum_rms);
      g.candidate_pairs += na * nb;
      add_local_minima(g, a, b, k, P, na, nb, D, AL);
    }
  }
  g.mean_rms = g.candidate_pairs ? sum_rms / g.candidate_pairs : 0.0;
}

// Natural continuations (a clip's last frame to the first of its next clips, or itself / the home clip) and the
// knockdown edges (the home clip's first frame to each forced-entry clip's).
void add_continuations(MotionGraph& g, const FrameClouds& cloud) {
  const int C = static_cast<int>(g.clips.size());
  const int home = g.clip_index(g.content.home_clip);
  for (int a = 0; a < C; ++a) {
    std::vector<std::string> next = g.clips[a].next;
    if (next.empty()) next.push_back(g.clips[a].loop || home < 0 ? g.clips[a].name : g.content.home_clip);
    const int last = g.frame_count[a] - 1;
    const Pose pa = sample_clip_pose(g.clips[a], g.clips[a].duration());
    for (const auto& nn : next) {
      const int b = g.clip_index(nn);
      if (b < 0) continue;
      GraphEdge e;
      e.to = g.node(b, 0);
      e.kind = EdgeKind::Continuation;
      e.align = align_2d(g.point_cloud(pa), cloud[b][0]);
      g.edges[g.node(a, last)].push_back(e);
    }
    if (has_any_tag(g.clips[a], g.content.forced_entry_tags) && home >= 0) {
      GraphEdge e;
      e.to = g.node(a, 0);
      e.kind = EdgeKind::Knockdown;
      e.align = align_2d(cloud[home][0], cloud[a][0]);
      g.edges[g.node(home, 0)].push_back(e);
    }
  }
}

// The strongly connected components of the edges (iterative Tarjan): comp[v] per node; returns their count.
int strongly_connected_components(const std::vector<std::vector<GraphEdge>>& edges, std::vector<int>& comp) {
  const int N = static_cast<int>(edges.size());
  std::vector<int> index(N, -1), low(N, 0), stack;
  comp.assign(N, -1);
  std::vector<char> on_stack(N, 0);
  std::vector<std::pair<int, size_t>> call;
  int counter = 0, ncomp = 0;
  for (int s = 0; s < N; ++s) {
    if (index[s] >= 0) continue;
    call.push_back({s, 0});
    index[s] = low[s] = counter++;
    stack.push_back(s);
    on_stack[s] = 1;
    while (!call.empty()) {
      auto& [v, ei] = call.back();
      if (ei < edges[v].size()) {
        const int w = edges[v][ei++].to;
        if (index[w] < 0) {
          index[w] = low[w] = counter++;
          stack.push_back(w);
          on_stack[w] = 1;
          call.push_back({w, 0});
        } else if (on_stack[w]) {
          low[v] = std::min(low[v], index[w]);
        }
      } else {
        const int vv = v;
        if (low[vv] == index[vv]) {
          while (true) {
            const int w = stack.back();
            stack.pop_back();
            on_stack[w] = 0;
            comp[w] = ncomp;
            if (w == vv) break;
          }
          ++ncomp;
        }
        call.pop_back();
        if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[vv]);
      }
    }
  }
  return ncomp;
}

// Only the largest strongly connected component stays alive (a walk can neither dead-end nor get stuck in a corner):
// the other nodes lose their edges, and the edges into them go.
void keep_largest_component(MotionGraph& g) {
  std::vector<int> comp;
  const int ncomp = strongly_connected_components(g.edges, comp);
  const int N = static_cast<int>(g.nodes.size());
  std::vector<int> size(ncomp, 0);
  for (int v = 0; v < N; ++v) ++size[comp[v]];
  const int best = ncomp ? static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin()) : -1;
  g.alive.assign(N, 0);
  for (int v = 0; v < N; ++v) g.alive[v] = comp[v] == best;
  g.scc_size = best >= 0 ? size[best] : 0;
  g.transitions = 0;
  for (int v = 0; v < N; ++v) {
    auto& es = g.edges[v];
    if (!g.alive[v]) {
      es.clear();
      continue;
    }
    es.erase(std::remove_if(es.begin(), es.end(), [&](const GraphEdge& e) { return !g.alive[e.to]; }), es.end());
    for (const auto& e : es) g.transitions += e.kind == EdgeKind::Transition;
  }
}

}  // namespace

// Kovar et al. 2002: a node per frame, transitions where windows of k frames match (local minima of the aligned
// point-cloud distance under the threshold), the clips' own continuations, then the largest strongly connected
// component.
void MotionGraph::build(const std::vector<Clip>& cl, const GraphOptions& opt, const MotionGraphOptions& co,
                        const Skeleton& sk) {
  clips = cl;
  for (Clip& c : clips) bake_spline(c);
  options = opt;
  content = co;
  skeleton = sk;
  nodes.clear();
  edges.clear();
  first_node.clear();
  frame_count.clear();
  const int k = std::max(1, options.window);
  const FrameClouds cloud = add_frames(*this);
  add_transitions(*this, cloud, k);
  add_continuations(*this, cloud);
  keep_largest_component(*this);
}

// ------------------------------------------------------------------------------------------ walker
GraphWalker::GraphWalker(const MotionGraph& g, uint64_t seed, const std::string& start_clip)
    : g_(&g), rng_(seed), home_(g.clip_index(g.content.home_clip)) {
  clip_ = std::max(0, g.clip_index(start_clip.empty() ? g.content.home_clip : start_clip));
  // The plans' scratch at its full size now: the first request_clip can come in a graph walk's measured stretch, where
  // its arrays' first growth would be the step's only allocation. The
  // heap holds at most one entry per edge relaxed, plus the source.
  const size_t N = g.nodes.size();
  size_t E = 1;
  for (const auto& es : g.edges) E += es.size();
  target_.reserve(N);
  plan_target_.reserve(N);
  dist_.reserve(N);
  prev_.reserve(N);
  heap_.reserve(E);
  plan_.reserve(N);
}

double GraphWalker::uniform() { return static_cast<double>(rng_() >> 11) * (1.0 / 9007199254740992.0); }

const std::string& GraphWalker::current_clip() const { return g_->clips[clip_].name; }

void GraphWalker::take_edge(int from_node, const GraphEdge& e) {
  const GraphNode& to = g_->nodes[e.to];
  if (e.kind == EdgeKind::Transition) {
    const double over = time_ - g_->frame_time(g_->nodes[from_node].frame);
    blend_.active = true;
    blend_.clip = clip_;
    blend_.time = time_;
    blend_.T = T_;
    blend_.elapsed = over;
    blend_.duration = e.blend;
    T_ = T_.then(e.align);
    prev_clip_ = -1;
    clip_ = to.clip;
    frame_ = e.dst_start_frame;
    time_ = g_->frame_time(e.dst_start_frame) + over;
    // the frames inside the blend are walked normally (frame_ advances with time_)
  } else if (e.kind == EdgeKind::Continuation || e.kind == EdgeKind::Knockdown) {
    const double over = std::max(0.0, time_ - g_->clips[clip_].duration());
    prev_clip_ = clip_;
    prev_T_ = T_;
    T_ = T_.then(e.align);
    clip_ = to.clip;
    frame_ = 0;
    time_ = over;
  }
}

void GraphWalker::decide() {
  // Called whenever frame_ changes (and at clip ends). Takes at most one non-Next edge.
  const int v = current_node();
  const bool at_end = frame_ == g_->frame_count[clip_] - 1 && time_ >= g_->clips[clip_].duration();
  // A request is done once the walk is in its target: the walk goes on at random from there (kept, the target would
  // draw the walk back into the requested clip at every continuation: a requested punch thrown again and again).
  if (!repeat_ && !plan_target_.empty() && plan_target_[v]) {
    plan_target_.clear();
    plan_.clear();
  }
  if (follow_plan(v, at_end)) return;
  if (at_end) {
    take_continuation(v);
    return;
  }
  take_random_transition(v);
}

bool GraphWalker::follow_plan(int v, bool at_end) {
  const auto& es = g_->edges[v];
  if (!plan_.empty()) {
    const GraphNode& pf = g_->nodes[plan_.front().from_node];
    if (pf.clip == clip_ && pf.frame < frame_) {  // went past it (should not happen): replan
      plan_.clear();
      if (!plan_target_.empty()) plan_to(plan_target_);
    }
  }
  if (plan_.empty()) return false;
  const Step s = plan_.front();
  const GraphEdge* held = nullptr;  // the plan's next edge, when the hold keeps the walk from taking it
  if (s.from_node == v && hold_transitions) {
    const GraphEdge& e = es[s.edge];
    if (e.kind != EdgeKind::Continuation || g_->nodes[e.to].clip != home_) held = &e;
  }
  if (held && !at_end) return true;  // the plan waits (made again once the walk is past it)
  if (s.from_node == v && !held) {
    const GraphEdge& e = es[s.edge];
    if (e.kind == EdgeKind::Continuation ? at_end : !blend_.active) {
      plan_.erase(plan_.begin());
      take_edge(v, e);
      return true;
    }
    if (e.kind != EdgeKind::Continuation) {  // missed (blending): replan from the next frame
      plan_.clear();
      if (!plan_target_.empty()) plan_to(plan_target_);
      return true;
    }
  }
  return false;
}

void GraphWalker::take_continuation(int v) {
  const auto& es = g_->edges[v];
  // The continuations, split into those looping back to this clip and the others; one drawn (no lists built: the k-th
  // edge of a kind is found by counting, the same draw as indexing a list of them).
  int n_cont = 0, n_self = 0;
  for (const GraphEdge& e : es)
    if (e.kind == EdgeKind::Continuation) {
      ++n_cont;
      if (g_->nodes[e.to].clip == clip_) ++n_self;
    }
  if (n_cont == 0) return;  // cannot happen in a pruned graph
  if (hold_transitions) {  // held: into the home clip when a continuation goes there
    for (const GraphEdge& e : es)
      if (e.kind == EdgeKind::Continuation && g_->nodes[e.to].clip == home_) {
        plan_.clear();
        take_edge(v, e);
        if (!plan_target_.empty()) plan_to(plan_target_);
        return;
      }
  }
  const int n_other = n_cont - n_self;
  int pool = 0;  // 0: every continuation, 1: self, 2: other
  if (n_self > 0 && n_other > 0) pool = uniform() < loop_probability ? 1 : 2;
  const int size = pool == 0 ? n_cont : pool == 1 ? n_self : n_other;
  const int k = static_cast<int>(std::min(static_cast<size_t>(size) - 1, static_cast<size_t>(uniform() * size)));
  int pick = -1;
  for (int i = 0, seen = 0; i < static_cast<int>(es.size()) && pick < 0; ++i) {
    if (es[i].kind != EdgeKind::Continuation) continue;
    const bool self = g_->nodes[es[i].to].clip == clip_;
    if (pool == 1 && !self) continue;
    if (pool == 2 && self) continue;
    if (seen++ == k) pick = i;
  }
  plan_.clear();
  take_edge(v, es[pick]);
  if (!plan_target_.empty()) plan_to(plan_target_);
}

void GraphWalker::take_random_transition(int v) {
  const auto& es = g_->edges[v];
  if (!plan_.empty() || blend_.active || hold_transitions) return;
  int n_tr = 0;
  for (const GraphEdge& e : es) n_tr += e.kind == EdgeKind::Transition;
  if (n_tr == 0) return;
  if (uniform() >= transition_probability) return;
  const int k = static_cast<int>(std::min(static_cast<size_t>(n_tr) - 1, static_cast<size_t>(uniform() * n_tr)));
  for (int i = 0, seen = 0; i < static_cast<int>(es.size()); ++i)
    if (es[i].kind == EdgeKind::Transition && seen++ == k) {
      take_edge(v, es[i]);
      return;
    }
}

void GraphWalker::tick(double dt, PoseSample* out) {
  time_ += dt;
  if (blend_.active) {
    blend_.time += dt;
    blend_.elapsed += dt;
    if (blend_.elapsed >= blend_.duration) blend_.active = false;
  }
  for (int iter = 0; iter < 1000; ++iter) {  // bounded: a zero-length clip cannot spin forever
    const int n = g_->frame_count[clip_];
    const Clip& c = g_->clips[clip_];
    if (frame_ + 1 < n && time_ >= g_->frame_time(frame_ + 1)) {
      ++frame_;
      decide();
      continue;
    }
    if (frame_ == n - 1 && time_ >= c.duration()) {
      const int before = current_node();
      decide();
      if (current_node() == before) break;  // no continuation (not expected)
      // landed on frame 0 of the next clip: give it a decision too
      decide();
      continue;
    }
    break;
  }
  constexpr double h = 1e-4;
  PoseSample& s = *out;
  if (heading_hold > 0.0) hold_heading(dt);
  world_pose_at(0.0, s.pose);
  world_pose_at(-h, fd_a_);
  world_pose_at(h, fd_b_);
  s.root_velocity = (fd_b_.root_position - fd_a_.root_position) / (2 * h);
  s.angular_velocity.resize(s.pose.rotation.size());
  for (size_t i = 0; i < s.pose.rotation.size(); ++i)
    s.angular_velocity[i] = angular_velocity_between(fd_a_.rotation[i], fd_b_.rotation[i], 2 * h);
}

void GraphWalker::hold_heading(double dt) {
  const double turn_by = -(1.0 - std::exp(-dt * heading_hold)) * std::remainder(T_.theta, 2.0 * M_PI);
  world_pose_at(0.0, fd_a_, true);  // the root's floor position is all it needs
  // A rotation by turn_by about the root's floor position c: x -> R x + (c - R c), composed before every frame the
  // walk samples through (the clip's, the one it blends from, the one it left).
  Align2D turn;
  turn.theta = turn_by;
  const Vector3d c(fd_a_.root_position.x(), fd_a_.root_position.y(), 0.0);
  const Vector3d Rc = turn.apply(c);
  turn.tx = c.x() - Rc.x();
  turn.ty = c.y() - Rc.y();
  T_ = turn.then(T_);
  prev_T_ = turn.then(prev_T_);
  blend_.T = turn.then(blend_.T);
}

PoseSample GraphWalker::tick(double dt) {
  PoseSample s;
  tick(dt, &s);
  return s;
}

const Pose& GraphWalker::preview(double ahead) const {
  world_pose_at(ahead, preview_);
  return preview_;
}

void GraphWalker::world_pose_at(double off, Pose& out, bool root_only) const {
  const auto sample = root_only ? sample_clip_root : static_cast<void (*)(const Clip&, double, Pose*)>(sample_clip_pose);
  const Clip& c = g_->clips[clip_];
  // within the current clip, time is clamped to the clip (the walk continues in the next clip);
  // just after a continuation, negative offsets look back into the clip that was left
  if (time_ + off < 0.0 && prev_clip_ >= 0) {
    const Clip& pc = g_->clips[prev_clip_];
    sample(pc, std::max(0.0, pc.duration() + time_ + off), &out);
    to_world_in_place(out, prev_T_);
  } else {
    sample(c, c.loop ? time_ + off : std::clamp(time_ + off, 0.0, c.duration()), &out);
    to_world_in_place(out, T_);
  }
  if (!blend_.active) return;
  const Clip& ca = g_->clips[blend_.clip];
  sample(ca, ca.loop ? blend_.time + off : std::clamp(blend_.time + off, 0.0, ca.duration()), &blend_from_);
  to_world_in_place(blend_from_, blend_.T);
  const double w = ease((blend_.elapsed + off) / blend_.duration);
  blend_pose_into(blend_from_, out, w, out);
}

bool GraphWalker::plan_to(const std::vector<char>& target) {
  plan_.clear();
  const int N = static_cast<int>(g_->nodes.size());
  const int src = current_node();
  if (target[src]) return true;
  // Dijkstra over the nodes; its arrays and heap are the walker's, kept between plans (no allocation once warm).
  dist_.assign(N, std::numeric_limits<double>::infinity());
  prev_.assign(N, {-1, -1});
  using QE = std::pair<double, int>;
  const std::greater<QE> later;
  heap_.clear();
  dist_[src] = 0;
  heap_.push_back({0.0, src});
  int found = -1;
  const int k1 = std::max(1, g_->options.window - 1);
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const auto [d, v] = heap_.back();
    heap_.pop_back();
    if (d > dist_[v]) continue;
    if (target[v]) {
      found = v;
      break;
    }
    const auto& es = g_->edges[v];
    for (size_t i = 0; i < es.size(); ++i) {
      const GraphEdge& e = es[i];
      if (e.kind == EdgeKind::Knockdown || !g_->alive[e.to]) continue;
      if (v == src && e.kind == EdgeKind::Transition) continue;  // src's decision is already made
      const double w = e.kind == EdgeKind::Transition ? k1 : 1.0;
      if (d + w < dist_[e.to]) {
        dist_[e.to] = d + w;
        prev_[e.to] = {v, static_cast<int>(i)};
        heap_.push_back({d + w, e.to});
        std::push_heap(heap_.begin(), heap_.end(), later);
      }
    }
  }
  if (found < 0) return false;
  for (int v = found; v != src;) {  // walked back from the target, then reversed
    const auto [p, ei] = prev_[v];
    if (g_->edges[p][ei].kind != EdgeKind::Next) plan_.push_back({p, ei});
    v = p;
  }
  std::reverse(plan_.begin(), plan_.end());
  return true;
}

bool GraphWalker::request_tag(const std::string& tag, bool repeat) {
  std::vector<char>& target = target_;
  target.assign(g_->nodes.size(), 0);
  bool any = false;
  for (size_t c = 0; c < g_->clips.size(); ++c) {
    if (!g_->clips[c].has_tag(tag)) continue;
    const int n = g_->frame_count[c];
    for (int f = 0; f <= std::max(0, (n - 1) / 4); ++f)
      if (g_->alive[g_->node(static_cast<int>(c), f)]) target[g_->node(static_cast<int>(c), f)] = any = true;
  }
  if (!any) return false;
  repeat_ = repeat;
  plan_target_ = target;
  const bool ok = plan_to(target);
  if (ok && plan_.empty()) plan_target_.clear();  // already there
  return ok;
}

bool GraphWalker::request_clip(const std::string& name, bool repeat) {
  const int c = g_->clip_index(name);
  if (c < 0) return false;
  std::vector<char>& target = target_;
  target.assign(g_->nodes.size(), 0);
  bool any = false;
  const int n = g_->frame_count[c];
  for (int f = 0; f <= std::max(0, (n - 1) / 4); ++f)
    if (g_->alive[g_->node(c, f)]) target[g_->node(c, f)] = any = true;
  if (!any) return false;
  repeat_ = repeat;
  plan_target_ = target;
  const bool ok = plan_to(target);
  if (ok && plan_.empty()) plan_target_.clear();
  return ok;
}

bool GraphWalker::restart(const std::string& name) {
  const int c = g_->clip_index(name.empty() ? g_->content.home_clip : name);
  if (c < 0) return false;
  clip_ = c;
  frame_ = 0;
  time_ = 0.0;
  T_ = Align2D{};
  prev_clip_ = -1;
  prev_T_ = Align2D{};
  blend_ = Blend{};
  plan_.clear();
  plan_target_.clear();
  repeat_ = false;
  return true;
}

bool GraphWalker::force_clip(const std::string& name) {
  const int b = g_->clip_index(name);
  if (b < 0) return false;
  // align the target's first frame to the current (displayed) pose, in the current clip's space
  const Clip& c = g_->clips[clip_];
  const Pose cur = sample_clip_pose(c, c.loop ? time_ : std::clamp(time_, 0.0, c.duration()));
  const Align2D rel = align_2d(g_->point_cloud(cur), g_->point_cloud(sample_clip_pose(g_->clips[b], 0.0)));
  blend_.active = true;
  blend_.clip = clip_;
  blend_.time = time_;
  blend_.T = T_;
  blend_.elapsed = 0.0;
  // Blend length: the graph's (k-1)/fps, longer when the poses are far apart so that the blend
  // itself turns no joint faster than ~8 rad/s (smoothstep peaks at 1.5x the mean rate), <= 0.4 s.
  const Pose target = sample_clip_pose(g_->clips[b], 0.0);
  double far = 0.0;
  for (size_t i = 1; i < cur.rotation.size(); ++i)
    far = std::max(far, quat_log(cur.rotation[i].conjugate() * target.rotation[i]).norm());
  blend_.duration = std::clamp(1.5 * far / 8.0, std::max(1, g_->options.window - 1) / g_->options.fps, 0.4);
  T_ = T_.then(rel);
  clip_ = b;
  frame_ = 0;
  time_ = 0.0;
  prev_clip_ = -1;
  plan_.clear();
  plan_target_.clear();
  return true;
}

// ------------------------------------------------------------------------------------------ reports
nlohmann::json graph_report(const MotionGraph& g) {
  nlohmann::json r;
  const int C = static_cast<int>(g.clips.size());
  std::vector<int> tr_out(C, 0), tr_in(C, 0), alive_frames(C, 0);
  int n_next = 0, n_cont = 0, n_knock = 0, n_alive = 0;
  for (size_t v = 0; v < g.nodes.size(); ++v) {
    if (g.alive[v]) {
      ++n_alive;
      ++alive_frames[g.nodes[v].clip];
    }
    for (const auto& e : g.edges[v]) {
      switch (e.kind) {
        case EdgeKind::Next: ++n_next; break;
        case EdgeKind::Continuation: ++n_cont; break;
        case EdgeKind::Knockdown: ++n_knock; break;
        case EdgeKind::Transition:
          ++tr_out[g.nodes[v].clip];
          ++tr_in[g.nodes[e.to].clip];
          break;
      }
    }
  }
  std::set<std::string> tags_in, tags_all;
  nlohmann::json clips = nlohmann::json::array();
  for (int c = 0; c < C; ++c) {
    for (const auto& t : g.clips[c].tags) {
      tags_all.insert(t);
      if (alive_frames[c] > 0) tags_in.insert(t);
    }
    clips.push_back({{"name", g.clips[c].name},
                     {"tags", g.clips[c].tags},
                     {"frames", g.frame_count[c]},
                     {"frames_in_scc", alive_frames[c]},
                     {"transitions_out", tr_out[c]},
                     {"transitions_in", tr_in[c]},
                     {"next", g.clips[c].next}});
  }
  std::vector<std::string> missing;
  for (const auto& t : tags_all)
    if (!tags_in.count(t)) missing.push_back(t);
  r["clips"] = clips;
  r["frames"] = static_cast<int>(g.nodes.size());
  r["fps"] = g.options.fps;
  r["window_frames"] = g.options.window;
  r["edges"] = {{"next", n_next}, {"transitions", g.transitions}, {"continuations", n_cont}, {"knockdown", n_knock}};
  r["transitions_before_prune"] = g.transitions_before_prune;
  r["window_pairs_compared"] = g.candidate_pairs;
  r["mean_window_rms_m"] = g.mean_rms;
  r["scc"] = {{"frames", g.scc_size}, {"frames_removed", static_cast<int>(g.nodes.size()) - n_alive},
              {"tags", std::vector<std::string>(tags_in.begin(), tags_in.end())},
              {"tags_missing", missing}};
  r["threshold"] = {{"rms_m", g.options.threshold_rms},
                    {"why", "per-point RMS of the aligned 5-frame point-cloud windows; below ~4 cm a "
                            "0.13 s slerp blend with the root aligned is not visible and stays within what "
                            "the servos track, while distinct boxing poses differ by 10-30 cm"},
                    {"fraction_of_mean", g.mean_rms > 0 ? g.options.threshold_rms / g.mean_rms : 0.0}};
  return r;
}

std::string graph_dot(const MotionGraph& g) {
  std::map<std::pair<int, int>, int> tr, cont;
  for (size_t v = 0; v < g.nodes.size(); ++v)
    for (const auto& e : g.edges[v]) {
      const auto key = std::make_pair(g.nodes[v].clip, g.nodes[e.to].clip);
      if (e.kind == EdgeKind::Transition) ++tr[key];
      if (e.kind == EdgeKind::Continuation) ++cont[key];
    }
  std::ostringstream os;
  os << "digraph motion_graph {\n  rankdir=LR;\n  node [shape=box, style=rounded];\n";
  for (size_t c = 0; c < g.clips.size(); ++c) {
    std::string tags;
    for (const auto& t : g.clips[c].tags) tags += (tags.empty() ? "" : ",") + t;
    os << "  \"" << g.clips[c].name << "\" [label=\"" << g.clips[c].name << "\\n" << tags << " ("
       << g.frame_count[c] << " f)\"];\n";
  }
  for (const auto& [key, n] : tr)
    os << "  \"" << g.clips[key.first].name << "\" -> \"" << g.clips[key.second].name << "\" [label=\"" << n
       << "\", weight=" << n << ", penwidth=" << (1.0 + std::log2(1.0 + n)) << "];\n";
  for (const auto& [key, n] : cont)
    os << "  \"" << g.clips[key.first].name << "\" -> \"" << g.clips[key.second].name
       << "\" [style=dashed, label=\"next\"];\n";
  os << "}\n";
  return os.str();
}

}  // namespace eng::anim
