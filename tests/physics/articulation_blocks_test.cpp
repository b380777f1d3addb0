// Independent articulations in one Model: block structure of the step (M block diagonal, constraint
// rows restricted to their articulations' DoFs) and exact independence of far-apart articulations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {

// Appends a copy of the 36-DoF humanoid tree (capsule limbs, limits, damping) with its root moved by
// `offset`; returns the index of its root body.
int add_fighter(Model& m, const Vec3& offset) {
  const Model src = humanoid_tree();
  const int base = static_cast<int>(m.bodies.size()) - 1;  // src body i -> base + i
  for (size_t i = 1; i < src.bodies.size(); ++i) {
    Body b = src.bodies[i];
    if (b.parent == 0) {
      b.X_tree.p += offset;
    } else {
      b.parent += base;
    }
    b.damping = 0.5;
    b.armature = 0.01;
    if (b.joint == JointType::Hinge) {
      b.limited = true;
      b.lower = -1.0;
      b.upper = 1.0;
    }
    if (b.joint == JointType::Ball) b.swing_limit = 0.8, b.twist_limit = 0.5;
    const int id = m.add_body(b);
    Geom g;
    g.body = id;
    g.shape.type = ShapeType::Capsule;
    g.shape.radius = 0.05;
    g.shape.half_length = 0.1;
    g.local = at({0, 0, -0.15});
    m.add_geom(g);
  }
  return base + 1;
}

void add_floor(Model& m) {
  Geom floor;
  floor.body = 0;
  floor.shape.type = ShapeType::Plane;
  m.add_geom(floor);
}

Model fighters(const std::vector<Vec3>& offsets) {
  Model m;
  for (const Vec3& o : offsets) add_fighter(m, o);
  add_floor(m);
  m.finalize();
  return m;
}

// Drives fighter f (DoFs [v0, v0 + nvf), root body `root`) with the same inputs whatever model it is in.
void drive(const Model& m, Data& d, int step_i, int root, int v0, int nvf) {
  apply_force_at_point(m, d, root + 1, Vec3(std::sin(0.01 * step_i) * 30, 10, 0), d.com_world[root + 1]);
  for (int k = 6; k < nvf; ++k) d.tau[v0 + k] = 5 * std::sin(0.02 * step_i + k);
}

}  // namespace

TEST(ArticulationBlocks, FarApartArticulationsEvolveExactlyAsAlone) {
  const Vec3 oa(0, 0, 0), ob(0, 30, 0.3);
  const Model ma = fighters({oa}), mb = fighters({ob}), mab = fighters({oa, ob});
  const int nvf = ma.nv, nqf = ma.nq, nbf = static_cast<int>(ma.bodies.size()) - 1;
  ASSERT_EQ(mab.nv, 2 * nvf);
  ASSERT_EQ(mab.block_begin.size(), 3u);  // two independent DoF blocks
  Data da = make_data(ma), db = make_data(mb), dab = make_data(mab);
  size_t max_contacts = 0;
  for (int i = 0; i < 600; ++i) {
    clear_applied(da);
    clear_applied(db);
    clear_applied(dab);
    drive(ma, da, i, 1, 0, nvf);
    drive(mb, db, i, 1, 0, nvf);
    drive(mab, dab, i, 1, 0, nvf);
    drive(mab, dab, i, 1 + nbf, nvf, nvf);
    step(ma, da);
    step(mb, db);
    step(mab, dab);
    max_contacts = std::max(max_contacts, dab.contacts.size());
  }
  EXPECT_GT(max_contacts, 4u);  // they did land and touch the floor
  EXPECT_EQ(dab.contacts.size(), da.contacts.size() + db.contacts.size());
  EXPECT_EQ(0, std::memcmp(dab.q.data(), da.q.data(), sizeof(double) * nqf));
  EXPECT_EQ(0, std::memcmp(dab.q.data() + nqf, db.q.data(), sizeof(double) * nqf));
  EXPECT_EQ(0, std::memcmp(dab.v.data(), da.v.data(), sizeof(double) * nvf));
  EXPECT_EQ(0, std::memcmp(dab.v.data() + nvf, db.v.data(), sizeof(double) * nvf));
  for (int k = 0; k < nqf; ++k) {
    ASSERT_NEAR(dab.q[k], da.q[k], 1e-12) << k;
    ASSERT_NEAR(dab.q[nqf + k], db.q[k], 1e-12) << k;
  }
  EXPECT_TRUE(dab.q.allFinite());
}

TEST(ArticulationBlocks, RowsStayInsideTheirArticulationsAndWIsExact) {
  // fighters 0 and 1 overlap at the arms (inter-articulation contacts), fighter 2 is far away
  const Model m = fighters({Vec3(0, 0, 0), Vec3(0, 0.35, 0), Vec3(0, 10, 0)});
  const int nvf = m.nv / 3;
  ASSERT_EQ(m.block_begin.size(), 4u);
  for (int b = 0; b < 3; ++b) EXPECT_EQ(m.block_begin[b], b * nvf);
  EXPECT_EQ(m.block_begin[3], m.nv);
  for (int k = 0; k < m.nv; ++k) EXPECT_EQ(m.dof_block[k], k / nvf);
  Data d = make_data(m);
  bool saw_cross = false, saw_limit = false;
  for (int s = 0; s < 120; ++s) {
    step(m, d);
    // M is block diagonal: nothing outside the articulation blocks
    for (int i = 0; i < m.nv; ++i) {
      for (int j = 0; j < m.nv; ++j) {
        if (i / nvf != j / nvf) {
          ASSERT_EQ(d.M(i, j), 0.0) << i << "," << j;
        }
      }
    }
    if (s % 20 != 0) continue;
    // each row's range = the DoF blocks of its bodies; J inside it; W = M^-1 J^T exactly (zero outside)
    const Eigen::LDLT<MatX> ldlt(d.M);
    for (const ConstraintRow& r : d.rows) {
      int lo = m.nv, hi = 0;
      for (int k = 0; k < r.nz_count; ++k) {
        lo = std::min(lo, d.J_idx[r.nz_begin + k]);
        hi = std::max(hi, d.J_idx[r.nz_begin + k] + 1);
      }
      ASSERT_LE(r.j_begin, lo);
      ASSERT_GE(r.j_end, hi);
      const int bb = r.j_begin / nvf, be = (r.j_end + nvf - 1) / nvf;
      EXPECT_EQ(r.j_begin, bb * nvf);
      EXPECT_EQ(r.j_end, be * nvf);
      EXPECT_EQ(lo / nvf, bb);
      EXPECT_EQ((hi - 1) / nvf, be - 1);
      if (r.kind == ConstraintRow::Limit) {
        EXPECT_EQ(be - bb, 1);
        saw_limit = true;
      } else {
        const Contact& c = d.contacts[r.contact];
        const bool cross = m.bodies[c.body_a].root != m.bodies[c.body_b].root && c.body_a != 0 && c.body_b != 0;
        EXPECT_EQ(be - bb, cross ? 2 : 1);
        saw_cross = saw_cross || cross;
      }
      VecX j = VecX::Zero(m.nv);
      for (int k = 0; k < r.nz_count; ++k) j[d.J_idx[r.nz_begin + k]] += d.J_val[r.nz_begin + k];
      const VecX w = ldlt.solve(j);
      const double scale = w.cwiseAbs().maxCoeff() + 1e-300;
      for (int i = 0; i < m.nv; ++i) {
        const double wi = (i >= r.j_begin && i < r.j_end) ? d.MinvJT[r.w_off + (i - r.j_begin)] : 0.0;
        ASSERT_NEAR(wi, w[i], 1e-9 * scale) << "dof " << i;
      }
    }
  }
  EXPECT_TRUE(saw_cross);
  EXPECT_TRUE(saw_limit);
  EXPECT_TRUE(d.q.allFinite());
}
