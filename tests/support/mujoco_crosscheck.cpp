#include "tests/support/mujoco_crosscheck.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/physics/data.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/model.h"
#include "tests/support/humanoid_from_mujoco.h"

namespace bench {

using namespace eng::physics;

CrossCheck crosscheck_mujoco(const mjModel* m, int states, unsigned seed) {
  CrossCheck r;
  Model model;
  const std::vector<MappedBody> map = convert_mujoco_model(m, model, 1).front();
  Data od = make_data(model);
  r.nq = model.nq, r.nv = model.nv, r.mj_nq = m->nq, r.mj_nv = m->nv;
  if (!r.same_layout()) return r;
  mjData* d = mj_makeData(m);
  const int nv = m->nv;
  std::vector<mjtNum> Mmj(size_t(nv) * nv);
  VecX c(nv);
  MatX M(nv, nv);
  auto rnd = [&]() {  // uniform [-1, 1), fixed LCG for reproducibility
    seed = seed * 1664525u + 1013904223u;
    return double(seed >> 8) / double(1u << 23) - 1.0;
  };
  for (int trial = 0; trial < states; ++trial) {
    mj_resetData(m, d);
    for (int i = 0; i < 3; ++i) d->qpos[i] += 0.5 * rnd();
    Quat qr(1.0 + rnd(), rnd(), rnd(), rnd());
    qr.normalize();
    d->qpos[3] = qr.w(), d->qpos[4] = qr.x(), d->qpos[5] = qr.y(), d->qpos[6] = qr.z();
    for (int i = 7; i < m->nq; ++i) d->qpos[i] = 0.8 * rnd();
    for (int i = 0; i < nv; ++i) d->qvel[i] = 2.0 * rnd();
    mj_forward(m, d);
    mj_fullM(m, Mmj.data(), d->qM);
    od = make_data(model);
    for (int i = 0; i < m->nq; ++i) od.q[i] = d->qpos[i];
    for (int i = 0; i < nv; ++i) od.v[i] = d->qvel[i];
    forward_kinematics(model, od);
    crba(model, od, M);
    bias_forces(model, od, c);
    for (int b = 1; b < m->nbody; ++b) {
      const MappedBody& mb = map[b];
      const Vec3 p = od.x[mb.body].apply(mb.offset);
      r.body_pos = std::max(r.body_pos, (p - Vec3(d->xpos[3 * b], d->xpos[3 * b + 1], d->xpos[3 * b + 2])).norm());
      Mat3 Rm;
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) Rm(i, k) = d->xmat[9 * b + 3 * i + k];
      r.body_rot = std::max(r.body_rot, (od.x[mb.body].R - Rm).cwiseAbs().maxCoeff());
    }
    // geoms: ours are the world planes first, then the humanoid's geoms in MuJoCo order
    int og = 0;
    while (og < int(model.geoms.size()) && model.geoms[og].body == 0) ++og;
    for (int g = 0; g < m->ngeom; ++g) {
      if (m->geom_bodyid[g] == 0) continue;
      const Geom& geom = model.geoms[og++];
      const Pose X = od.x[geom.body] * geom.local;
      const Vec3 pm(d->geom_xpos[3 * g], d->geom_xpos[3 * g + 1], d->geom_xpos[3 * g + 2]);
      r.geom_pose = std::max(r.geom_pose, (X.p - pm).norm());
      // capsule / sphere / box axes: compare the local Z axis (the capsule axis)
      const Vec3 zm(d->geom_xmat[9 * g + 2], d->geom_xmat[9 * g + 5], d->geom_xmat[9 * g + 8]);
      r.geom_pose = std::max(r.geom_pose, (X.R.col(2) - zm).norm());
    }
    for (int i = 0; i < nv; ++i) {
      const int bi = model.dof_body[i];
      for (int j = 0; j < nv; ++j) {
        const double ours = M(i, j) + (i == j ? model.bodies[bi].armature : 0.0);
        r.M = std::max(r.M, std::abs(ours - Mmj[size_t(i) * nv + j]));
        r.M_max = std::max(r.M_max, std::abs(Mmj[size_t(i) * nv + j]));
      }
      r.bias = std::max(r.bias, std::abs(c[i] - d->qfrc_bias[i]));
      r.bias_max = std::max(r.bias_max, std::abs(d->qfrc_bias[i]));
    }
    ++r.states;
  }
  mj_deleteData(d);
  return r;
}

}  // namespace bench
