// Clip splines (C1 rotation/position interpolation, angular velocities), clip loading and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "anim/anim_test_util.h"
#include "engine/anim/clip.h"

using namespace eng::anim;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

Quaterniond euler(double rx, double ry, double rz) {
  return Quaterniond(Eigen::AngleAxisd(rz, Vector3d::UnitZ()) * Eigen::AngleAxisd(ry, Vector3d::UnitY()) *
                     Eigen::AngleAxisd(rx, Vector3d::UnitX()));
}

// A synthetic 3-bone clip with non-uniform key times and large rotations.
Clip synthetic(bool loop) {
  Clip c;
  c.name = "syn";
  c.loop = loop;
  c.key_times = {0.0, 0.13, 0.41, 0.52, 0.9};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1.2, 1.2);
  for (size_t k = 0; k < c.key_times.size(); ++k) {
    Pose p;
    p.root_position = Vector3d(U(rng), U(rng), 1.0 + 0.1 * U(rng));
    for (int b = 0; b < 3; ++b) p.rotation.push_back(euler(U(rng), U(rng), U(rng)));
    c.keys.push_back(p);
  }
  if (loop) c.keys.back() = c.keys.front();
  return c;
}

double qdist(const Quaterniond& a, const Quaterniond& b) { return quat_log(a.conjugate() * b).norm(); }

}  // namespace

TEST(ClipSpline, PassesThroughKeys) {
  for (bool loop : {false, true}) {
    const Clip c = synthetic(loop);
    for (size_t k = 0; k < c.keys.size(); ++k) {
      const Pose p = sample_clip_pose(c, c.key_times[k]);
      EXPECT_LT((p.root_position - c.keys[k].root_position).norm(), 1e-9);
      for (int b = 0; b < 3; ++b) EXPECT_LT(qdist(p.rotation[b], c.keys[k].rotation[b]), 1e-9) << k << " " << b;
    }
  }
}

TEST(ClipSpline, ABakedClipSamplesTheSamePosesBitForBitAndTheRootAloneMatches) {
  // bake_spline stores the per-segment controls a sample would compute: the same numbers, so the same poses exactly;
  // sample_clip_root gives the whole sample's root position and no bones.
  for (bool loop : {false, true}) {
    const Clip plain = synthetic(loop);
    Clip baked = plain;
    bake_spline(baked);
    ASSERT_EQ(baked.spline.size(), 3 * (baked.keys.size() - 1) * 3);
    Pose root;
    for (double t = -0.3; t < 1.3; t += 0.0137) {
      const Pose a = sample_clip_pose(plain, t), b = sample_clip_pose(baked, t);
      EXPECT_EQ(a.root_position, b.root_position) << t;
      for (int k = 0; k < 3; ++k) EXPECT_EQ(a.rotation[k].coeffs(), b.rotation[k].coeffs()) << t << " bone " << k;
      sample_clip_root(baked, t, &root);
      EXPECT_EQ(root.root_position, a.root_position) << t;
      EXPECT_TRUE(root.rotation.empty());
    }
  }
}

TEST(ClipSpline, AngularVelocityContinuousAcrossKeys) {
  for (bool loop : {false, true}) {
    const Clip c = synthetic(loop);
    const double eps = 1.2e-4;  // > the 1e-4 differentiation step, so each side sees one segment only
    for (size_t k = 1; k + 1 < c.keys.size(); ++k) {
      const PoseSample a = sample_clip(c, c.key_times[k] - eps), b = sample_clip(c, c.key_times[k] + eps);
      for (int i = 0; i < 3; ++i) {
        // C1: the jump across the key is only what the acceleration over 2*eps explains (a C0
        // slerp chain would jump by O(|w|)): bound 2% of |w| + 0.02 rad/s
        EXPECT_LT((a.angular_velocity[i] - b.angular_velocity[i]).norm(), 0.02 * (1.0 + a.angular_velocity[i].norm()))
            << "key " << k << " bone " << i << " |w|=" << a.angular_velocity[i].norm();
      }
      EXPECT_LT((a.root_velocity - b.root_velocity).norm(), 0.02 * (1.0 + a.root_velocity.norm()));
    }
    if (loop) {  // the seam of a looping clip is C1 too
      const PoseSample a = sample_clip(c, c.duration() - 1.2e-4), b = sample_clip(c, 1.2e-4);
      for (int i = 0; i < 3; ++i)
        EXPECT_LT((a.angular_velocity[i] - b.angular_velocity[i]).norm(), 0.02 * (1.0 + a.angular_velocity[i].norm()));
    }
  }
}

TEST(ClipSpline, AngularVelocityMatchesOrientationDifference) {
  const Clip c = synthetic(false);
  for (double t = 0.01; t < c.duration() - 0.01; t += 0.037) {
    const PoseSample s = sample_clip(c, t);
    const double d = 1e-3;
    const Pose a = sample_clip_pose(c, t - d), b = sample_clip_pose(c, t + d);
    for (int i = 0; i < 3; ++i) {
      const Vector3d fd = quat_log(b.rotation[i] * a.rotation[i].conjugate()) / (2 * d);
      EXPECT_LT((fd - s.angular_velocity[i]).norm(), 1e-2 * (1.0 + fd.norm())) << t;
    }
    EXPECT_LT(((b.root_position - a.root_position) / (2 * d) - s.root_velocity).norm(), 1e-2);
  }
}

TEST(ClipSpline, ParentFrameConvention) {
  // A bone spinning about the parent's Z at 2 rad/s: omega must be (0,0,2) whatever the key orientation.
  Clip c;
  c.loop = false;
  c.key_times = {0.0, 0.5, 1.0, 1.5};
  const Quaterniond base = euler(0.0, 0.7, 0.0);
  for (double t : c.key_times) {
    Pose p;
    p.rotation.push_back(Quaterniond(Eigen::AngleAxisd(2.0 * t, Vector3d::UnitZ())) * base);
    c.keys.push_back(p);
  }
  const PoseSample s = sample_clip(c, 0.75);
  EXPECT_LT((s.angular_velocity[0] - Vector3d(0, 0, 2.0)).norm(), 1e-3);
}

TEST(ClipSpline, QuaternionHemisphere) {
  // Negating keys (q and -q are the same rotation) must not change the curve.
  const Clip c = synthetic(false);
  Clip f = c;
  for (size_t k = 0; k < f.keys.size(); k += 2)
    for (auto& q : f.keys[k].rotation) q.coeffs() = -q.coeffs();
  for (double t = 0; t <= c.duration(); t += 0.01) {
    const PoseSample a = sample_clip(c, t), b = sample_clip(f, t);
    for (int i = 0; i < 3; ++i) {
      EXPECT_LT(qdist(a.pose.rotation[i], b.pose.rotation[i]), 1e-9);
      EXPECT_LT((a.angular_velocity[i] - b.angular_velocity[i]).norm(), 1e-6);
    }
  }
  // and quat_log takes the short way round
  const Quaterniond q = euler(0, 0, 0.3);
  Quaterniond mq = q;
  mq.coeffs() = -mq.coeffs();
  EXPECT_LT((quat_log(mq) - Vector3d(0, 0, 0.3)).norm(), 1e-12);
}

TEST(ClipSpline, NoOvershootBeyondReason) {
  // Between two keys 90 deg apart with zero end velocities the rotation stays on the great arc.
  Clip c;
  c.key_times = {0.0, 1.0};
  Pose a, b;
  a.rotation = {Quaterniond::Identity()};
  b.rotation = {Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()))};
  c.keys = {a, b};
  for (double t = 0; t <= 1.0; t += 0.05) {
    const Vector3d v = quat_log(sample_clip_pose(c, t).rotation[0]);
    EXPECT_NEAR(v.y(), 0, 1e-9);
    EXPECT_NEAR(v.z(), 0, 1e-9);
    EXPECT_GE(v.x(), -1e-9);
    EXPECT_LE(v.x(), M_PI / 2 + 1e-9);
  }
}

// The per-tick forms (into a kept PoseSample / Pose) give the same numbers, bit for bit, as the value forms, and a
// second call into the same storage (the no-allocation path) as well.
TEST(ClipSample, IntoStorageEqualsByValueBitForBit) {
  const auto& clips = anim_test::content_clips();
  PoseSample into;
  Pose pose_into;
  for (const Clip& c : clips)
    for (double t : {0.0, 0.013, c.duration() * 0.5, c.duration(), c.duration() + 0.2}) {
      const PoseSample v = sample_clip(c, t);
      sample_clip(c, t, &into);
      ASSERT_EQ(v.pose.rotation.size(), into.pose.rotation.size());
      EXPECT_EQ(v.pose.root_position, into.pose.root_position) << c.name << " t " << t;
      EXPECT_EQ(v.root_velocity, into.root_velocity);
      for (size_t i = 0; i < v.pose.rotation.size(); ++i) {
        EXPECT_EQ(v.pose.rotation[i].coeffs(), into.pose.rotation[i].coeffs());
        EXPECT_EQ(v.angular_velocity[i], into.angular_velocity[i]);
      }
      sample_clip_pose(c, t, &pose_into);
      EXPECT_EQ(pose_into.root_position, v.pose.root_position);
    }
}
