#include "game/match/replay.h"

#include <algorithm>

namespace boxing {

void ReplayBuffer::init(int frames, int nq) {
  frames_ = std::max(1, frames);
  nq_ = nq;
  q_.assign(static_cast<size_t>(frames_) * nq_, 0.0);
  t_.assign(frames_, 0.0);
  next_ = count_ = 0;
}

void ReplayBuffer::record(const Eigen::VectorXd& q, double time) {
  if (frames_ == 0 || q.size() != nq_) return;
  std::copy(q.data(), q.data() + nq_, q_.data() + static_cast<size_t>(next_) * nq_);
  t_[next_] = time;
  next_ = (next_ + 1) % frames_;
  count_ = std::min(count_ + 1, frames_);
}

int ReplayBuffer::at_or_before(double time) const {
  int best = 0;
  for (int i = 0; i < count_; ++i)
    if (this->time(i) <= time) best = i;
  return best;
}

}  // namespace boxing
