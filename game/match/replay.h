#pragma once
// The instant replay: the last seconds of every body's joint coordinates, kept at the display rate in a ring
// allocated once, played back after a knockdown in slow motion from another camera (game/app.cpp). Determinism makes
// it cheap: coordinates are all a frame needs (forward kinematics rebuilds every body's pose from them).
#include <Eigen/Core>
#include <vector>

namespace boxing {

class ReplayBuffer {
 public:
  // Keeps the newest `frames` frames of `nq` coordinates each.
  void init(int frames, int nq);
  void record(const Eigen::VectorXd& q, double time);
  int count() const { return count_; }
  // Frame i in time order: 0 the oldest kept, count() - 1 the newest.
  const double* q(int i) const { return q_.data() + static_cast<size_t>(slot(i)) * nq_; }
  double time(int i) const { return t_[slot(i)]; }
  // The newest frame at or before `time` (0 when none is that old).
  int at_or_before(double time) const;
  int nq() const { return nq_; }

 private:
  int slot(int i) const { return (next_ - count_ + i + 2 * frames_) % frames_; }
  int frames_ = 0, nq_ = 0, next_ = 0, count_ = 0;
  std::vector<double> q_, t_;
};

}  // namespace boxing
