#include "engine/anim/clip.h"

#include <algorithm>
#include <cmath>

#include "engine/assets/gltf.h"

namespace eng::anim {

namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

// Segment index i with key_times[i] <= t <= key_times[i+1].
int find_segment(const std::vector<double>& kt, double t) {
  auto it = std::upper_bound(kt.begin(), kt.end(), t);
  int i = static_cast<int>(it - kt.begin()) - 1;
  return std::clamp(i, 0, static_cast<int>(kt.size()) - 2);
}

double wrap_time(const Clip& c, double t) {
  const double d = c.duration();
  if (d <= 0.0) return 0.0;
  if (c.loop) {
    double r = std::fmod(t, d);
    if (r < 0) r += d;
    return r;
  }
  return std::clamp(t, 0.0, d);
}

// Neighbour key indices and spacings of key k: (prev, h_prev, next, h_next); -1 when none.
struct Nb {
  int prev, next;
  double hp, hn;
};
Nb neighbours(const Clip& c, int k) {
  const int n = static_cast<int>(c.keys.size());
  const auto& t = c.key_times;
  Nb r{-1, -1, 0.0, 0.0};
  if (c.loop) {  // keys[n-1] == keys[0]
    const int kk = (k == n - 1) ? 0 : k;
    r.prev = kk == 0 ? n - 2 : kk - 1;
    r.hp = kk == 0 ? t[n - 1] - t[n - 2] : t[kk] - t[kk - 1];
    r.next = kk + 1;
    r.hn = t[kk + 1] - t[kk];
    if (r.prev < 0) r.prev = -1;
    return r;
  }
  if (k == 0 || k == n - 1) return r;  // zero velocity at the ends
  r.prev = k - 1;
  r.hp = t[k] - t[k - 1];
  r.next = k + 1;
  r.hn = t[k + 1] - t[k];
  return r;
}

// Body-frame angular velocity tangent of bone b at key k.
Vector3d rot_tangent(const Clip& c, int b, int k) {
  const Nb nb = neighbours(c, k);
  if (nb.prev < 0 || nb.next < 0 || nb.hp <= 0 || nb.hn <= 0) return Vector3d::Zero();
  const Quaterniond& q = c.keys[k].rotation[b];
  const Vector3d sp = quat_log(c.keys[nb.prev].rotation[b].conjugate() * q) / nb.hp;
  const Vector3d sn = quat_log(q.conjugate() * c.keys[nb.next].rotation[b]) / nb.hn;
  return (nb.hn * sp + nb.hp * sn) / (nb.hp + nb.hn);
}

Vector3d pos_tangent(const Clip& c, int k) {
  const Nb nb = neighbours(c, k);
  if (nb.prev < 0 || nb.next < 0 || nb.hp <= 0 || nb.hn <= 0) return Vector3d::Zero();
  const Vector3d& p = c.keys[k].root_position;
  const Vector3d sp = (p - c.keys[nb.prev].root_position) / nb.hp;
  const Vector3d sn = (c.keys[nb.next].root_position - p) / nb.hn;
  return (nb.hn * sp + nb.hp * sn) / (nb.hp + nb.hn);
}

// The rotation spline of bone b over segment i (Kim, Kim & Shin 1995's cumulative cubic form): q(u) = q0 exp(r1 b1(u))
// exp(r2 b2(u)) exp(r3 b3(u)), with r1, r3 the keys' tangents over a third of the segment and r2 the rotation between
// the two inner control points.
void spline_controls(const Clip& c, int i, int b, Vector3d r[3]) {
  const double h = c.key_times[i + 1] - c.key_times[i];
  const Quaterniond& q0 = c.keys[i].rotation[b];
  Quaterniond q3 = c.keys[i + 1].rotation[b];
  if (q0.dot(q3) < 0) q3.coeffs() = -q3.coeffs();
  r[0] = rot_tangent(c, b, i) * (h / 3.0);
  r[2] = rot_tangent(c, b, i + 1) * (h / 3.0);
  const Quaterniond q1 = q0 * quat_exp(r[0]);
  const Quaterniond q2 = q3 * quat_exp(-r[2]);
  r[1] = quat_log(q1.conjugate() * q2);
}

void pose_into(const Clip& c, double t, Pose& out, bool root_only = false) {
  const int nb = c.keys.empty() || root_only ? 0 : static_cast<int>(c.keys[0].rotation.size());
  out.root_position.setZero();
  out.rotation.assign(nb, Quaterniond::Identity());  // reuses the capacity: no allocation once warm
  if (c.keys.empty()) return;
  if (c.keys.size() == 1) {
    if (!root_only) out.rotation = c.keys[0].rotation;
    out.root_position = c.keys[0].root_position;
    return;
  }
  t = wrap_time(c, t);
  const int i = find_segment(c.key_times, t);
  const double h = c.key_times[i + 1] - c.key_times[i];
  const double u = h > 0 ? std::clamp((t - c.key_times[i]) / h, 0.0, 1.0) : 0.0;
  const double u2 = u * u, u3 = u2 * u;
  // root position: cubic Hermite
  {
    const Vector3d& p0 = c.keys[i].root_position;
    const Vector3d& p1 = c.keys[i + 1].root_position;
    const Vector3d m0 = pos_tangent(c, i) * h, m1 = pos_tangent(c, i + 1) * h;
    out.root_position = (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 +
                        (u3 - u2) * m1;
  }
  const double b1 = 1.0 - (1.0 - u) * (1.0 - u) * (1.0 - u), b2 = 3 * u2 - 2 * u3, b3 = u3;
  const bool baked = c.spline.size() == static_cast<size_t>(3 * (c.keys.size() - 1) * nb);
  for (int b = 0; b < nb; ++b) {
    Vector3d r[3];
    if (baked)
      for (int k = 0; k < 3; ++k) r[k] = c.spline[3 * (static_cast<size_t>(i) * nb + b) + k];
    else
      spline_controls(c, i, b, r);
    out.rotation[b] = (c.keys[i].rotation[b] * quat_exp(r[0] * b1) * quat_exp(r[1] * b2) * quat_exp(r[2] * b3)).normalized();
  }
}

}  // namespace

bool Clip::has_tag(const std::string& tag) const {
  return std::find(tags.begin(), tags.end(), tag) != tags.end();
}

Pose sample_clip_pose(const Clip& c, double t) {
  Pose out;
  pose_into(c, t, out);
  return out;
}

void sample_clip_pose(const Clip& c, double t, Pose* out) { pose_into(c, t, *out); }

void sample_clip_root(const Clip& c, double t, Pose* out) { pose_into(c, t, *out, true); }

Eigen::Vector3d angular_velocity_between(const Eigen::Quaterniond& qa, const Eigen::Quaterniond& qb,
                                         double dt) {
  return quat_log(qb * qa.conjugate()) / dt;
}

void bake_spline(Clip& c) {
  c.spline.clear();
  if (c.keys.size() < 2) return;
  const int nb = static_cast<int>(c.keys[0].rotation.size());
  c.spline.resize(3 * (c.keys.size() - 1) * nb);
  for (int i = 0; i + 1 < static_cast<int>(c.keys.size()); ++i)
    for (int b = 0; b < nb; ++b) spline_controls(c, i, b, &c.spline[3 * (static_cast<size_t>(i) * nb + b)]);
}

PoseSample sample_clip(const Clip& c, double t) {
  PoseSample s;
  sample_clip(c, t, &s);
  return s;
}

void sample_clip(const Clip& c, double t, PoseSample* out) {
  constexpr double kH = 1e-4;
  PoseSample& s = *out;
  pose_into(c, t, s.pose);
  s.root_velocity.setZero();
  double ta = t - kH, tb = t + kH;
  if (!c.loop) {
    const double tc = std::clamp(t, 0.0, c.duration());
    ta = std::max(0.0, tc - kH);
    tb = std::min(c.duration(), tc + kH);
  }
  const int nb = static_cast<int>(s.pose.rotation.size());
  s.angular_velocity.assign(nb, Vector3d::Zero());
  if (tb - ta <= 0.0) return;
  // The two poses of the central difference, kept per thread between calls (no allocation once warm).
  thread_local Pose a, b;
  pose_into(c, ta, a);
  pose_into(c, tb, b);
  const double dt = tb - ta;
  s.root_velocity = (b.root_position - a.root_position) / dt;
  for (int i = 0; i < nb; ++i) s.angular_velocity[i] = angular_velocity_between(a.rotation[i], b.rotation[i], dt);
}

int find_clip(const std::vector<Clip>& clips, const std::string& name) {
  for (size_t i = 0; i < clips.size(); ++i)
    if (clips[i].name == name) return static_cast<int>(i);
  return -1;
}

eng::Result<std::vector<Clip>> load_clips(const std::string& path, const Skeleton& sk) {
  auto scene = eng::assets::load_gltf(path);
  if (!scene) return eng::make_error("load_clips: " + scene.error());
  return load_clips(*scene, sk);
}

namespace {

// A clip's metadata from its animation's extras (tags, loop, glove, impact, next): an error message, or empty.
std::string read_clip_metadata(const eng::assets::GltfAnimation& a, const Skeleton& sk, Clip& c) {
  c.name = a.name;
  const auto& ex = a.extras;
  if (!ex.is_object() || !ex.contains("tags") || !ex["tags"].is_array() || !ex.contains("loop") ||
      !ex["loop"].is_boolean())
    return "missing metadata: extras.tags (array) and extras.loop (bool) are required";
  for (const auto& t : ex["tags"]) {
    if (!t.is_string()) return "extras.tags must hold strings";
    c.tags.push_back(t.get<std::string>());
  }
  c.loop = ex["loop"].get<bool>();
  if (ex.contains("glove") && ex["glove"].is_string()) {
    c.glove = sk.find(ex["glove"].get<std::string>());
    if (c.glove < 0) return "extras.glove '" + ex["glove"].get<std::string>() + "' is not a bone";
  }
  if (ex.contains("impact") && ex["impact"].is_number()) c.impact_time = ex["impact"].get<double>();
  if (ex.contains("next") && ex["next"].is_array())
    for (const auto& t : ex["next"])
      if (t.is_string()) c.next.push_back(t.get<std::string>());
  if ((c.glove >= 0) != (c.impact_time >= 0)) return "missing metadata: a strike needs both extras.glove and extras.impact";
  return {};
}

// The key times: those of the root translation channel (every channel must share them): an error message, or empty.
std::string read_key_times(const eng::assets::GltfScene& sc, const eng::assets::GltfAnimation& a, const Skeleton& sk,
                           Clip& c, const eng::assets::GltfChannel*& root_ch) {
  root_ch = nullptr;
  for (const auto& ch : a.channels) {
    if (ch.node < 0 || ch.node >= static_cast<int>(sc.nodes.size())) return "channel targets a missing node";
    const std::string& nn = sc.nodes[ch.node].name;
    const int bone = sk.find(nn);
    if (bone < 0) return "channel on node '" + nn + "', which is not a skeleton bone";
    if (bone == 0 && ch.path == "translation") root_ch = &ch;
  }
  if (!root_ch) return "no translation channel on the root bone '" + sk.name[0] + "'";
  for (double t : root_ch->times) c.key_times.push_back(t);
  const size_t nk = c.key_times.size();
  if (nk < 2) return "needs at least two keys";
  for (size_t k = 1; k < nk; ++k)
    if (!(c.key_times[k] > c.key_times[k - 1])) return "key times must increase";
  if (std::abs(c.key_times[0]) > 1e-6) return "first key must be at time 0";
  c.key_times[0] = 0.0;
  return {};
}

// The keys' poses from the rotation channels and the root's translation, each rotation in the previous key's
// hemisphere: an error message, or empty.
std::string read_keys(const eng::assets::GltfScene& sc, const eng::assets::GltfAnimation& a, const Skeleton& sk,
                      const eng::assets::GltfChannel& root_ch, Clip& c) {
  const size_t nk = c.key_times.size();
  Pose rest;
  rest.rotation.assign(sk.size(), Eigen::Quaterniond::Identity());
  c.keys.assign(nk, rest);
  for (const auto& ch : a.channels) {
    const int bone = sk.find(sc.nodes[ch.node].name);
    if (ch.times.size() != nk) return "channel key times differ from the root's";
    for (size_t k = 0; k < nk; ++k)
      if (std::abs(ch.times[k] - root_ch.times[k]) > 1e-6) return "channel key times differ from the root's";
    if (ch.interpolation == "CUBICSPLINE") return "CUBICSPLINE channels are not supported";
    if (ch.path == "rotation") {
      if (ch.values.size() != 4 * nk) return "rotation channel has the wrong value count";
      for (size_t k = 0; k < nk; ++k) {
        Eigen::Quaterniond q(ch.values[4 * k + 3], ch.values[4 * k], ch.values[4 * k + 1], ch.values[4 * k + 2]);
        if (q.norm() < 1e-6) return "zero quaternion";
        c.keys[k].rotation[bone] = q.normalized();
      }
    } else if (ch.path == "translation") {
      if (bone != 0) continue;  // bone offsets are fixed; only the root translates
      if (ch.values.size() != 3 * nk) return "translation channel has the wrong value count";
      for (size_t k = 0; k < nk; ++k)
        c.keys[k].root_position = Eigen::Vector3d(ch.values[3 * k], ch.values[3 * k + 1], ch.values[3 * k + 2]);
    }
  }
  // hemisphere continuity
  for (int b = 0; b < sk.size(); ++b)
    for (size_t k = 1; k < nk; ++k)
      if (c.keys[k].rotation[b].dot(c.keys[k - 1].rotation[b]) < 0)
        c.keys[k].rotation[b].coeffs() = -c.keys[k].rotation[b].coeffs();
  return {};
}

}  // namespace

eng::Result<std::vector<Clip>> load_clips(const eng::assets::GltfScene& sc, const Skeleton& sk) {
  const std::string& path = sc.path;
  auto fail = [&](const std::string& anim, const std::string& msg) {
    return eng::make_error("load_clips: " + path + ": animation '" + anim + "': " + msg);
  };
  if (sc.animations.empty()) return eng::make_error("load_clips: " + path + ": no animations");
  std::vector<Clip> out;
  for (const auto& a : sc.animations) {
    Clip c;
    std::string error = read_clip_metadata(a, sk, c);
    const eng::assets::GltfChannel* root_ch = nullptr;
    if (error.empty()) error = read_key_times(sc, a, sk, c, root_ch);
    if (error.empty()) error = read_keys(sc, a, sk, *root_ch, c);
    if (!error.empty()) return fail(a.name, error);
    if (c.impact_time >= 0 && !(c.impact_time > 0 && c.impact_time < c.duration()))
      return fail(a.name, "impact time outside the clip");
    out.push_back(std::move(c));
  }
  for (const auto& c : out)
    for (const auto& n : c.next)
      if (find_clip(out, n) < 0) return fail(c.name, "extras.next names unknown clip '" + n + "'");
  return out;
}

}  // namespace eng::anim
