#include "terrain/TileBuilder.hpp"

#include <algorithm>
#include <utility>

namespace og::terrain {

TileBuilder::TileBuilder(std::shared_ptr<const Heightfield> heights, int workers)
    : TileBuilder([h = std::move(heights)](const TileKey& key) { return buildTile(*h, key); },
                  workers) {}

TileBuilder::TileBuilder(BuildFn build, int workers) : build_(std::move(build)) {
  const int n = workers > 0 ? workers : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  workers_.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    workers_.emplace_back([this](const std::stop_token& stop) { work(stop); });
}

TileBuilder::~TileBuilder() {
  // Stop them all before joining any (jthread's destructor joins): each finishes its tile.
  for (auto& w : workers_) w.request_stop();
}

void TileBuilder::build(std::span<const TileKey> keys) {
  std::unique_lock lock(mutex_);
  for (const TileKey& key : keys) {
    auto [it, fresh] = state_.try_emplace(key.packed());
    Entry& e = it->second;
    if (fresh || e.state == State::Queued) {
      if (!fresh) --queuedCount_;  // its queued_ entry is now skipped
      e.state = State::Urgent;
      urgent_.push_back(key);
    } else if (e.state == State::Done || e.blocking) {
      continue;  // finished, or already counted (a key twice in `keys`)
    }
    e.blocking = true;
    ++blockingLeft_;
  }
  lock.unlock();
  workCv_.notify_all();
  lock.lock();
  doneCv_.wait(lock, [this] { return blockingLeft_ == 0; });
}

void TileBuilder::request(std::span<const TileKey> keys) {
  {
    std::lock_guard lock(mutex_);
    for (const TileKey& key : queued_)  // drop what the latest frame no longer asks for
      if (auto it = state_.find(key.packed()); it != state_.end() && it->second.state == State::Queued)
        state_.erase(it);
    queued_.clear();
    queuedCount_ = 0;
    for (const TileKey& key : keys) {
      if (queuedCount_ == kMaxQueued) break;
      if (!state_.try_emplace(key.packed(), Entry{State::Queued, false}).second) continue;
      queued_.push_back(key);
      ++queuedCount_;
    }
  }
  workCv_.notify_all();
}

TileBuilder::Finished TileBuilder::takeFinished() {
  std::lock_guard lock(mutex_);
  Finished f;
  f.tiles = std::exchange(done_, {});
  f.error = std::exchange(error_, nullptr);
  for (const Tile& t : f.tiles) state_.erase(t.key.packed());
  return f;
}

std::size_t TileBuilder::pending() const {
  std::lock_guard lock(mutex_);
  return state_.size();
}

void TileBuilder::waitIdle() {
  std::unique_lock lock(mutex_);
  doneCv_.wait(lock, [this] { return urgent_.empty() && queuedCount_ == 0 && inFlight_ == 0; });
}

void TileBuilder::work(const std::stop_token& stop) {
  std::unique_lock lock(mutex_);
  for (;;) {
    workCv_.wait(lock, stop, [this] { return !urgent_.empty() || queuedCount_ != 0; });
    if (stop.stop_requested()) return;
    TileKey key;
    if (!urgent_.empty()) {
      key = urgent_.front();
      urgent_.pop_front();
    } else {
      // queuedCount_ != 0: a live entry remains; skip those dropped or taken over by build().
      for (;;) {
        key = queued_.front();
        queued_.pop_front();
        const auto it = state_.find(key.packed());
        if (it != state_.end() && it->second.state == State::Queued) break;
      }
      --queuedCount_;
    }
    const std::uint64_t id = key.packed();
    state_[id].state = State::InFlight;
    ++inFlight_;
    lock.unlock();

    Tile tile;
    std::exception_ptr error;
    try {
      tile = build_(key);
    } catch (...) {
      error = std::current_exception();  // handed to the render thread by takeFinished()
    }

    lock.lock();
    --inFlight_;
    const auto it = state_.find(id);
    if (it->second.blocking) --blockingLeft_;
    if (error) {
      state_.erase(it);  // not built: may be asked for again
      if (!error_) error_ = error;
    } else {
      it->second.state = State::Done;
      done_.push_back(std::move(tile));
    }
    doneCv_.notify_all();
  }
}

}  // namespace og::terrain
