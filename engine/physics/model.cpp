#include "engine/physics/model.h"

#include <algorithm>
#include <cassert>
#include <stdexcept>

#include "engine/physics/data.h"
#include "engine/physics/spatial.h"

namespace eng::physics {

Model::Model() {
  Body world;
  world.name = "world";
  world.parent = -1;
  world.joint = JointType::Fixed;
  bodies.push_back(world);
}

int Model::add_body(const Body& b) {
  if (b.parent < 0 || b.parent >= static_cast<int>(bodies.size()))
    throw std::invalid_argument("add_body: parent must be an existing body (topological order)");
  if (b.joint == JointType::Free && b.parent != 0)
    throw std::invalid_argument("add_body: a Free joint must attach to the world (body 0)");
  bodies.push_back(b);
  finalized = false;
  return static_cast<int>(bodies.size()) - 1;
}

int Model::add_geom(const Geom& g) {
  geoms.push_back(g);
  return static_cast<int>(geoms.size()) - 1;
}

void Model::finalize() {
  nq = 0;
  nv = 0;
  dof_body.clear();
  dof_parent.clear();
  body_last_dof.assign(bodies.size(), -1);
  bodies[0].q_index = bodies[0].v_index = bodies[0].nq = bodies[0].nv = 0;
  bodies[0].root = 0;
  for (size_t i = 1; i < bodies.size(); ++i) {
    Body& b = bodies[i];
    switch (b.joint) {
      case JointType::Free: b.nq = 7; b.nv = 6; break;
      case JointType::Ball: b.nq = 4; b.nv = 3; break;
      case JointType::Hinge: b.nq = 1; b.nv = 1; b.axis.normalize(); break;
      case JointType::Fixed: b.nq = 0; b.nv = 0; break;
    }
    b.q_index = nq;
    b.v_index = nv;
    b.root = b.parent == 0 ? static_cast<int>(i) : bodies[b.parent].root;
    int prev = body_last_dof[b.parent];  // lambda(i) expanded to DoFs (RBDA eq. 6.21)
    for (int k = 0; k < b.nv; ++k) {
      dof_body.push_back(static_cast<int>(i));
      dof_parent.push_back(prev);
      prev = nv + k;
    }
    body_last_dof[i] = prev;
    nq += b.nq;
    nv += b.nv;
  }
  dof_anc_begin.assign(1, 0);
  dof_anc.clear();
  for (int i = 0; i < nv; ++i) {
    for (int j = dof_parent[i]; j >= 0; j = dof_parent[j]) dof_anc.push_back(j);
    dof_anc_begin.push_back(static_cast<int>(dof_anc.size()));
  }
  // DoF blocks: per articulation root the interval [min DoF, max DoF]; overlapping intervals merged
  // (with bodies added articulation by articulation each block is exactly one articulation).
  {
    std::vector<int> lo(bodies.size(), nv), hi(bodies.size(), -1);
    for (int i = 0; i < nv; ++i) {
      const int r = bodies[dof_body[i]].root;
      lo[r] = std::min(lo[r], i);
      hi[r] = std::max(hi[r], i);
    }
    std::vector<std::pair<int, int>> iv;
    for (size_t r = 1; r < bodies.size(); ++r)
      if (hi[r] >= 0) iv.emplace_back(lo[r], hi[r] + 1);
    std::sort(iv.begin(), iv.end());
    block_begin.clear();
    dof_block.assign(nv, 0);
    int cur_end = 0;
    for (const auto& [b, e] : iv) {
      if (block_begin.empty() || b >= cur_end) block_begin.push_back(b);
      cur_end = std::max(cur_end, e);
    }
    block_begin.push_back(nv);
    for (size_t k = 0; k + 1 < block_begin.size(); ++k)
      for (int i = block_begin[k]; i < block_begin[k + 1]; ++i) dof_block[i] = static_cast<int>(k);
  }
  finalized = true;
}

Data make_data(const Model& m) {
  if (!m.finalized) throw std::logic_error("make_data: call Model::finalize() first");
  const int nb = static_cast<int>(m.bodies.size());
  Data d;
  d.q = VecX::Zero(m.nq);
  d.v = VecX::Zero(m.nv);
  d.qacc = VecX::Zero(m.nv);
  d.tau = VecX::Zero(m.nv);
  d.spring_ref = VecX::Zero(m.nv);
  for (int i = 1; i < nb; ++i) {
    const Body& b = m.bodies[i];
    if (b.joint == JointType::Free) {  // rest pose of a free body = X_tree (in the world)
      d.q.segment<3>(b.q_index) = b.X_tree.p;
      quat_store(Quat(b.X_tree.R), d.q.data() + b.q_index + 3);
    } else if (b.joint == JointType::Ball) {
      d.q[b.q_index] = 1.0;
    }
  }
  d.x.assign(nb, Pose{});
  d.com_world.assign(nb, Vec3::Zero());
  d.v_body.assign(nb, Vec6::Zero());
  d.cdof.assign(m.nv, Vec6::Zero());
  d.cdof_dot.assign(m.nv, Vec6::Zero());
  d.cinert.assign(nb, Mat6::Zero());
  d.applied_force.assign(nb, Vec3::Zero());
  d.applied_torque.assign(nb, Vec3::Zero());
  const int maxc = m.solver.max_contacts;
  d.contacts.reserve(maxc);
  d.prev_contacts.reserve(maxc);
  d.contact_begin.reserve(maxc);
  d.contact_end.reserve(maxc);
  d.hit_events.reserve(maxc);
  d.touching.reserve(maxc);
  d.prev_touching.reserve(maxc);
  d.ws_a.assign(nb, Vec6::Zero());
  d.ws_f.assign(nb, Vec6::Zero());
  d.ws_Ic.assign(nb, Mat6::Zero());
  d.ws_p.assign(nb, Vec6::Zero());
  d.ws_U.assign(nb, Mat6::Zero());
  d.ws_Dinv.assign(nb, Mat6::Zero());
  d.ws_u.assign(nb, Vec6::Zero());
  d.ws_c.assign(nb, Vec6::Zero());
  d.M_crba = MatX::Zero(m.nv, m.nv);
  d.qfrc_bias = VecX::Zero(m.nv);
  d.M = MatX::Zero(m.nv, m.nv);
  d.LD = MatX::Zero(m.nv, m.nv);
  d.bias = VecX::Zero(m.nv);
  d.vtmp = VecX::Zero(m.nv);
  d.vtmp2 = VecX::Zero(m.nv);
  d.v_free = VecX::Zero(m.nv);
  d.passive = VecX::Zero(m.nv);
  d.speed_damping = VecX::Zero(m.nv);
  int limit_rows = 0;
  for (int i = 1; i < nb; ++i) {
    const Body& b = m.bodies[i];
    if (b.joint == JointType::Hinge && b.limited) limit_rows += 1;
    if (b.joint == JointType::Ball) limit_rows += 2;
  }
  d.max_rows = 3 * maxc + limit_rows + 3 * kMaxPointSprings;
  d.rows.reserve(d.max_rows);
  d.row_order.assign(d.max_rows, 0);
  d.J_idx.assign(static_cast<size_t>(d.max_rows) * 2 * std::max(m.nv, 1), 0);
  d.J_val.assign(static_cast<size_t>(d.max_rows) * 2 * std::max(m.nv, 1), 0.0);
  d.MinvJT_T.assign(static_cast<size_t>(d.max_rows) * std::max(m.nv, 1), 0.0);
  d.MinvJT.assign(static_cast<size_t>(d.max_rows) * std::max(m.nv, 1), 0.0);
  const size_t ng = m.geoms.size();
  d.aabbs.assign(ng, Aabb{});
  d.geom_fixed.assign(ng, 0);
  for (size_t g = 0; g < ng; ++g) d.geom_fixed[g] = m.body_last_dof[m.geoms[g].body] < 0;
  d.geom_x.assign(ng, Pose{});
  d.pairs.reserve(std::min<size_t>(std::max<size_t>(64, ng * (ng - 1) / 2), size_t{1} << 16));
  d.cp_tmp.assign(8, ContactPoint{});
  return d;
}

}  // namespace eng::physics
